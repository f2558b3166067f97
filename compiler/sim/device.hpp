#pragma once
// What the simulated device holds, read once from the typed model: its
// identity from [Device], its assembly instances, and one connection point
// per ConnectionN it can serve (paths, sizes and formats from the same
// collector `edsc header` and `verify --live` use). No second model of the
// EDS: every number here comes from model::device through live::plan_connections.
#include <cstdint>
#include <string>
#include <vector>

#include "cip/encap.hpp"
#include "cip/request.hpp"
#include "live/plan.hpp"
#include "model/device.hpp"

namespace edsc::sim {

enum class assembly_role : std::uint8_t { input, output, config, other };

struct assembly_instance {
  std::uint32_t instance = 0;
  assembly_role role = assembly_role::other;
  cip::bytes data;  // its size is the EDS's
  bool fixed = false;  // input data given by --inputs: the counter pattern leaves it alone
};

enum class point_kind : std::uint8_t { exclusive_owner, input_only, listen_only };

// One ConnectionN the simulator accepts Forward_Open for.
struct connection_point {
  std::uint32_t number = 0;  // N of ConnectionN
  live::connection_plan plan;
  cip::bytes app_path;                      // owns what `segments` views
  std::vector<cip::path_segment> segments;  // the application path, widths forgotten
  point_kind kind = point_kind::exclusive_owner;
  std::uint32_t rpi_min_us = 0, rpi_max_us = 0;
};

// A ConnectionN the simulator does not serve, and why.
struct unserved {
  std::uint32_t number = 0;
  std::string why;
};

struct device {
  cip::identity id;  // attributes 1-7; serial from the command line
  std::vector<assembly_instance> assemblies;
  std::vector<connection_point> points;
  std::vector<unserved> skipped;

  [[nodiscard]] assembly_instance* assembly(std::uint32_t instance);
  [[nodiscard]] const assembly_instance* assembly(std::uint32_t instance) const;
};

[[nodiscard]] device build_device(const model::device& dev, std::uint32_t serial);

}  // namespace edsc::sim
