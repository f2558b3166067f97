#pragma once
// `edsc header --stack opener`: what OpENer's application API must be told to
// serve an EDS (docs/header.md, "OpENer"), derived from the same facts as
// `edsc header` (collect_facts), plus what OpENer cannot serve as diagnostics.
#include <cstdint>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "facts/header_view.hpp"

namespace edsc::emit {

// OpENer sizes its message buffers by one build option,
// OPENER_ETHERNET_BUFFER_SIZE (512 bytes unless set). Around an assembly's
// data a buffer holds at most 64 bytes more: an I/O frame's 24 (item count,
// sequenced address item, data item header, sequence count, run/idle header)
// or an explicit message's (encapsulation 24, CPF 16, request path or reply
// header 10). The generated project raises the option when its largest
// assembly needs it; the 16-bit encapsulation length bounds it.
// A configuration assembly's data travels in the Forward_Open itself, with
// more around it: encapsulation and CPF 40, the request's service and path
// 6, the large form's fields 40, the key 10, three 16-bit connection points
// 12, the data segment's header and pad 3 (111; EIPScanner's request with
// 408 bytes of data is 514), and 15 more when a scanner routes it through
// Unconnected Send. OpENer drops a message over its buffer without a reply.
inline constexpr std::uint32_t opener_default_buffer_bytes = 512;
inline constexpr std::uint32_t opener_buffer_headroom = 64;
inline constexpr std::uint32_t opener_forward_open_headroom = 128;
inline constexpr std::uint32_t opener_max_assembly_bytes = 65535 - opener_buffer_headroom;

struct opener_assembly {
  std::uint32_t instance = 0, size = 0;
  const char* role = "";  // "input", "output", "configuration", for the comment
};

struct opener_point {
  model::app_type kind = model::app_type::exclusive_owner;
  unsigned index = 0;            // OpENer's connection_number: counted per kind from 0
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
  bool consumed_run_idle = true, produced_run_idle = false;           // OpENer's defaults
  std::uint32_t ethernet_buffer_bytes = opener_default_buffer_bytes;  // OPENER_ETHERNET_BUFFER_SIZE
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
