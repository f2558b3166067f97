#pragma once
// `edsc header --stack opener`: what OpENer's application API must be told to
// serve an EDS (docs/header.md, "OpENer"), derived from the same facts as
// `edsc header` (collect_facts), plus what OpENer cannot serve as diagnostics.
#include <cstdint>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "emit/header_view.hpp"

namespace edsc::emit {

// OpENer's Ethernet buffer (PC_OPENER_ETHERNET_BUFFER_SIZE, its CMake default)
// less the I/O frame's overhead: item count 2, sequenced address item 12,
// data item header 4, sequence count 2, run/idle header 4.
inline constexpr std::uint32_t opener_max_assembly_bytes = 512 - 24;

struct opener_assembly {
  std::uint32_t instance = 0, size = 0;
  const char* role = "";  // "input", "output", "configuration", for the comment
};

struct opener_point {
  model::app_type kind = model::app_type::exclusive_owner;
  unsigned index = 0;  // OpENer's connection_number: counted per kind from 0
  std::uint32_t connection = 0;  // the ConnectionN it serves
  std::string name;
  std::uint32_t output_instance = 0, input_instance = 0, config_instance = 0;
};

struct opener_plan {
  identity_facts identity;
  std::string source_name, source_sha256;
  std::vector<opener_assembly> assemblies;  // by instance, each once
  std::vector<opener_point> points;
  unsigned exclusive_owner = 0, input_only = 0, listen_only = 0;
  bool consumed_run_idle = true, produced_run_idle = false;  // OpENer's defaults
};

// The plan and, in `diags`, what OpENer cannot serve (errors: no files then)
// and the identity problems `edsc header` reports (as `issues`).
[[nodiscard]] opener_plan plan_opener(const model::device& dev, const source_file& src, diagnostics& diags,
                                      std::vector<header_issue>& issues);

struct opener_file {
  std::string name, text;
};

// The files of the ready OpENer project, in the order they are written.
[[nodiscard]] std::vector<opener_file> render_opener(const opener_plan& plan);

}  // namespace edsc::emit
