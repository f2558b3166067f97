#pragma once
// `--set NAME=VALUE`: a parameter's value chosen by the user instead of its
// default. The device is copied with each chosen value as the parameter's
// default, so everything a connection reads from a ParamN follows it: the
// configuration data, an RPI, a [ParamN] in the path, a member size.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"
#include "connections/fields.hpp"
#include "model/device.hpp"

namespace edsc::connections {

struct param_set {
  std::string name, value;
};
// "NAME=VALUE" split at its first '='; the reason when it is not that shape.
[[nodiscard]] result<param_set, std::string> parse_set(std::string_view arg);

enum class set_fault : std::uint8_t { unknown_param, value };
struct set_refusal {
  set_fault fault = set_fault::unknown_param;
  value_fault value = value_fault::type;  // fault value: which rule the value breaks
  std::string message;
  span at;  // the EDS field the value breaks; empty when the name is unknown
};

struct set_value {
  std::uint32_t param_index = 0;  // into device::params
  number v;
  std::string enum_text;  // the EnumN text the user named the value by, or the one it has
};

struct applied_sets {
  model::device dev;
  std::vector<set_value> sets;
  std::vector<set_refusal> warnings;  // values applied that are none of their EnumN's
};
// The device with every set applied, or every refusal (not only the first).
[[nodiscard]] result<applied_sets, std::vector<set_refusal>> apply_sets(const model::device& dev,
                                                                        const std::vector<param_set>& sets);

// Whether the ConnectionN reads the parameter: an RPI or size field, a
// [ParamN] of its path, a member or member size of its assemblies.
[[nodiscard]] bool uses_param(const model::device& dev, const model::connection& c, std::uint32_t param_index);

}  // namespace edsc::connections
