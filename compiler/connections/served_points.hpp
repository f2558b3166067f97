#pragma once
// The class 1 ConnectionN entries a device built from an EDS accepts a
// Forward_Open for, with everything a Forward_Open is held against: the
// application path as segments, the sizes and formats of the plan, the RPI
// limits and the configuration's member parameters. The simulator serves
// them; the capture judge holds a captured Forward_Open against them.
#include <cstdint>
#include <string>
#include <vector>

#include "cip/request.hpp"
#include "connections/fields.hpp"
#include "connections/plan.hpp"
#include "model/device.hpp"

namespace edsc::connections {

// Any RPI from 0.1 ms to 10 s: what a field that sets no limit (empty, or a
// fixed number, which is the default a tool proposes) leaves a scanner.
inline constexpr std::uint32_t default_rpi_min_us = 100, default_rpi_max_us = 10'000'000;

// The RPIs one direction of a ConnectionN accepts.
struct rpi_limits {
  std::uint32_t min_us = default_rpi_min_us, max_us = default_rpi_max_us;
  std::uint32_t param = 0;  // N of the ParamN the RPI field names (its limits, as the Parameter object reports them)
  bool unset = false;       // the field is empty: the EDS sets no limit
};

// The RPIs one RPI field lets a scanner ask. A fixed number widens the
// default limits to include it; a ParamN of an unsigned type of at most 32
// bits gives its limits, the default one where the EDS leaves a limit out
// (what the Parameter object reports for it), its type's where the EDS's
// does not fit the type.
[[nodiscard]] rpi_limits rpi_limits_of(const model::device& dev, const model::value& field);

struct connection_point {
  std::uint32_t number = 0;  // N of ConnectionN
  connection_plan plan;
  cip::bytes app_path;                                      // owns what `segments` views
  std::vector<cip::path_segment> segments;                  // the application path, widths forgotten
  model::app_type kind = model::app_type::exclusive_owner;  // as the plan classifies it
  rpi_limits ot_rpi, to_rpi;
  // The configuration assembly's member parameters: configuration data a
  // Forward_Open carries is held to their type, limits and EnumN.
  std::vector<data_field> config_fields;
};

// A ConnectionN not served, and why.
struct unserved {
  std::uint32_t number = 0;
  std::string why;
};

struct served_points {
  // In ConnectionN order. Each point's segments view its own app_path: a
  // move keeps them valid, a copy of a point does not.
  std::vector<connection_point> points;
  std::vector<unserved> skipped;
};

[[nodiscard]] served_points serve_points(const model::device& dev);

}  // namespace edsc::connections
