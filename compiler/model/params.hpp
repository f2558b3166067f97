#pragma once
#include <cstdint>
#include <vector>

#include "model/value.hpp"
#include "schema/cip_types.hpp"
#include "schema/schema.hpp"

namespace edsc::model {

// Parameter descriptor bits (EDS_FORMAT.md §3.7.2).
enum param_descriptor_bit : std::uint16_t {
  pd_settable_path = 0x0001,
  pd_enumerated = 0x0002,
  pd_scaling = 0x0004,
  pd_scaling_links = 0x0008,
  pd_read_only = 0x0010,
  pd_monitor = 0x0020,
  pd_extended_precision = 0x0040,
};

enum class param_kind : std::uint8_t { param, proxy_param, proxied_param, constructed_param };

// The reference kind naming a parameter of that kind (`ProxiedParam3`).
[[nodiscard]] constexpr schema::ref_kind param_ref_kind(param_kind k) {
  return static_cast<schema::ref_kind>(static_cast<int>(schema::ref_kind::param) + static_cast<int>(k));
}
// The reference kind naming the enumeration of a parameter of that kind.
[[nodiscard]] constexpr schema::ref_kind enum_ref_kind(param_kind k) {
  switch (k) {
    case param_kind::proxy_param: return schema::ref_kind::proxy_enum;
    case param_kind::proxied_param: return schema::ref_kind::proxied_enum;
    default: return schema::ref_kind::enum_;
  }
}

// ParamN and its proxy variants. min/max/default are typed by the
// parameter's own data type: `type` is that type (nullptr when field 5 is
// missing or unknown, in which case the three are invalid/unknown_type).
// A proxy parameter without a data type (§3.18) keeps them as untyped
// numbers: the proxied module owns the type.
struct param {
  param_kind kind = param_kind::param;
  std::uint32_t number = 0;
  origin from;
  value reserved, link_path_size, link_path, descriptor, data_type, data_size, name, units, help, min, max,
      default_value, scaling_multiplier, scaling_divisor, scaling_base, scaling_offset, multiplier_link, divisor_link,
      base_link, offset_link, decimal_precision, international_name, international_units, international_help;
  const schema::cip_type_info* type = nullptr;
  bool legacy_type = false;             // field 5 used a legacy DeviceNet code (§4.2)
  std::uint32_t enum_index = none;      // device::enums entry describing it
  std::uint32_t enum_par_index = none;  // device::enum_pars entry describing it
  std::vector<value> extra;             // fields beyond 24 (ConstructedParamN: all fields)
};

struct enum_pair {
  value val;  // typed by the parameter's data type
  value text;
};

// EnumN in [Params]; `param` is the index of ParamN with the same N.
// ProxyEnumN / ProxiedEnumN describe ProxyParamN / ProxiedParamN (`kind`
// names the parameter kind they belong to).
struct param_enum {
  param_kind kind = param_kind::param;
  std::uint32_t number = 0;
  origin from;
  std::vector<enum_pair> pairs;
  value dangling;  // the last field when the count is odd
  std::uint32_t param = none;
};

// [EnumPar] ParamN: strings only (DeviceNet legacy, §3.8).
struct enum_par {
  std::uint32_t number = 0;
  origin from;
  std::vector<value> strings;
  std::uint32_t param = none;
};

// GroupN: members are number references to parameters.
struct group {
  std::uint32_t number = 0;
  origin from;
  value name, count;
  std::vector<value> members;
};

// [ParamClass] (§3.6).
struct param_class {
  std::uint32_t section = none;
  value max_inst, descriptor, cfg_assembly, safety_cfg_assembly;
};

}  // namespace edsc::model
