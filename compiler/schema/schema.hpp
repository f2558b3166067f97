#pragma once
#include <cstdint>
#include <span>
#include <string_view>

namespace edsc::schema {

// What lowering does with a section's entries.
enum class section_family : std::uint8_t {
  file,
  device,
  classification,
  io_info,
  variant_io_info,
  param_class,
  params,
  enum_par,
  groups,
  assembly,
  connection_manager,
  port,
  capacity,
  modular,
  object_class,
  unknown,
};

// The EDS pseudo-type of one field (EDS_FORMAT.md §3 column "Type").
enum class value_type : std::uint8_t {
  integer,     // CIP integer named by field_desc::cip (range checked)
  real,        // REAL written as a decimal (`.004`)
  string,      // quoted, escapes decoded
  date,        // mm-dd-yyyy
  time,        // hh:mm:ss
  revision,    // major.minor, two integers
  epath,       // quoted hex bytes, may hold [ParamN]
  keyword,     // one word of field_desc::words, or vendor-specific
  reference,   // ParamN, AssemN... of field_desc::refs
  int_or_ref,  // an integer or a reference (RPI, sizes)
  number_ref,  // an integer naming the N of a target of field_desc::refs (0 = none)
  member,      // assembly member: reference, EPATH or integer
  typed,       // typed by the owning ParamN's data type (min/max/default/enum values)
  stringi,     // `{ ... }` dataset
  any,         // layout unknown: kept as written, typed by its syntax only
};

// Kinds of entries a reference can name; the bit index of a ref_mask.
enum class ref_kind : std::uint8_t {
  param,
  proxy_param,
  proxied_param,
  constructed_param,
  enum_,
  assem,
  assem_exa,
  proxy_assem,
  proxied_assem,
  proxy_assem_exa,
  proxied_assem_exa,
  variant,
  variant_exa,
  bitstring_variant,
  array,
  connection,
  group,
  input,
  output,
  // Proxy descriptions (EDS_FORMAT.md §3.18): after the original kinds so
  // their bit positions stay put.
  proxy_enum,
  proxied_enum,
  proxy_connection,
  proxied_connection,
  count_,
};
using ref_mask = std::uint32_t;
[[nodiscard]] constexpr ref_mask bit(ref_kind k) { return ref_mask{1} << static_cast<unsigned>(k); }
// The stem a reference of that kind is written with (`Param`, `AssemExa`...).
[[nodiscard]] std::string_view stem_of(ref_kind k);
// `AssemExa12` -> assem_exa / 12 when that kind is in `allowed`.
[[nodiscard]] bool parse_reference(std::string_view text, ref_mask allowed, ref_kind& kind, std::uint32_t& number);

struct field_desc {
  std::string_view name;
  value_type type = value_type::any;
  std::uint8_t cip = 0;  // CIP type code for integers (and the integer part of int_or_ref)
  bool required = false;
  ref_mask refs = 0;
  std::span<const std::string_view> words{};  // keyword sets; vendor-specific words always fit
};

// Every known entry, so lowering can dispatch with a switch.
enum class entry_id : std::uint16_t {
  // [File] / [Device]
  desc_text,
  create_date,
  create_time,
  mod_date,
  mod_time,
  file_revision,
  home_url,
  exclude,
  eds_file_crc,
  vend_code,
  vend_name,
  prod_type,
  prod_type_str,
  prod_code,
  maj_rev,
  min_rev,
  prod_name,
  catalog,
  icon,
  icon_contents,
  application_profiles_assembly,
  class_n,
  // [IO_Info]
  io_default,
  poll_info,
  strobe_info,
  cos_info,
  cyclic_info,
  input_n,
  output_n,
  // [ParamClass] [Params] [EnumPar] [Groups]
  pc_max_inst,
  pc_descriptor,
  pc_cfg_assembly,
  pc_safety_cfg_assembly,
  param_n,
  proxy_param_n,
  proxied_param_n,
  constructed_param_n,
  enum_n,
  proxy_enum_n,
  proxied_enum_n,
  enum_par_n,
  group_n,
  // [IO_Info] extended entries (DeviceNet POINT I/O, §3.18)
  input_exa_n,
  output_exa_n,
  // [Assembly]
  assem_n,
  assem_exa_n,
  proxy_assem_n,
  proxied_assem_n,
  proxy_assem_exa_n,
  proxied_assem_exa_n,
  variant_n,
  variant_exa_n,
  bitstring_variant_n,
  array_n,
  // [Connection Manager]
  connection_n,
  proxy_connection_n,
  proxied_connection_n,
  pitns,
  pitns_usec,
  safety_setting,
  default_safety_connections,
  // [Port] [Capacity] [Modular]
  port_n,
  tspec_n,
  capacity_setting,
  define_slots_in_rack,
  slot_display_rule,
  width,
  rack_n,
  external_id,
  // common object-class keywords and class-specific settings
  object_setting,
  attribute_list,
  service_list,
  service_description_n,
};

struct keyword_desc {
  std::string_view stem;  // canonical spelling
  bool numbered;          // `StemN`: the keyword carries a decimal instance number
  entry_id id;
  std::span<const field_desc> fields;  // fixed fields, numbered from 1
  std::span<const field_desc> tail{};  // repeating group after the fixed fields
};

struct section_desc {
  std::string_view name;  // canonical spelling
  section_family family;
  std::uint32_t class_code;  // CIP object class, 0 when none
  std::span<const keyword_desc> keywords;
  bool common_keywords;  // also accepts the object-class keywords of §3.15
};

// The section with that name (case-insensitive), or nullptr. Numbered
// variants such as `[Connection Manager2]` map to their base section.
[[nodiscard]] const section_desc* find_section(std::string_view name);

struct keyword_match {
  const keyword_desc* desc = nullptr;
  std::uint32_t number = 0;  // N of a numbered keyword
};
// Looks a keyword up in a section (stem compared whole and case-insensitive).
[[nodiscard]] keyword_match find_keyword(const section_desc& s, std::string_view keyword);

// The descriptor of field `index` (0-based) of an entry, following the
// repeating tail; nullptr beyond the schema.
[[nodiscard]] const field_desc* field_at(const keyword_desc& k, std::uint32_t index);

[[nodiscard]] std::span<const section_desc> all_sections();
[[nodiscard]] std::span<const keyword_desc> common_object_keywords();

}  // namespace edsc::schema
