// Schema rows for [File], [Device], [Device Classification], [IO_Info],
// [ParamClass], [Params], [EnumPar] and [Groups] (EDS_FORMAT.md §3.1-3.9).
#include <array>
#include <iterator>

#include "schema/tables.hpp"

namespace edsc::schema::tables {

using vt = value_type;
using rk = ref_kind;
namespace c = code;

namespace {
constexpr std::string_view exclude_words[] = {"NONE", "WRITE", "READ_WRITE"};
constexpr std::string_view network_words[] = {
    "CompoNet",  "ControlNet", "DeviceNet", "EtherNetIP", "EtherNetIP_In_Cabinet", "EtherNetIP_UDP_Only", "ModbusSL",
    "ModbusTCP", "Safety",     "HART",      "IOLink"};

constexpr field_desc f_desc_text[] = {{"text", vt::string, 0, true}};
constexpr field_desc f_date[] = {{"date", vt::date, 0, true}};
constexpr field_desc f_time[] = {{"time", vt::time, 0, true}};
constexpr field_desc f_revision[] = {{"revision", vt::revision, 0, true}};
constexpr field_desc f_string[] = {{"text", vt::string, 0, true}};
constexpr field_desc f_exclude[] = {{"mode", vt::keyword, 0, true, 0, exclude_words}};
constexpr field_desc f_crc[] = {{"crc", vt::integer, c::UDINT, true}};
constexpr field_desc f_uint[] = {{"value", vt::integer, c::UINT, true}};
constexpr field_desc f_usint[] = {{"value", vt::integer, c::USINT, true}};
constexpr field_desc f_word[] = {{"value", vt::integer, c::WORD, true}};
constexpr field_desc f_class[] = {{"network", vt::keyword, 0, true, 0, network_words}};
constexpr field_desc f_cfg_assembly[] = {
    {"instance", vt::number_ref, c::UINT, true, bit(rk::assem) | bit(rk::assem_exa)}};

constexpr field_desc f_io_info[] = {
    {"mask", vt::integer, c::WORD, true},
    {"default_input", vt::number_ref, c::UINT, true, bit(rk::input)},
    {"default_output", vt::number_ref, c::UINT, true, bit(rk::output)},
};
constexpr field_desc f_io_data[] = {
    {"size", vt::integer, c::UINT, true},
    {"significant_bits", vt::integer, c::UINT, true},
    {"mask", vt::integer, c::WORD, true},
    {"name", vt::string, 0, true},
    {"path_size", vt::integer, c::USINT, false},
    {"path", vt::epath, 0, false},
    {"help", vt::string, 0, false},
};

constexpr ref_mask param_like = bit(rk::param) | bit(rk::proxy_param) | bit(rk::proxied_param);
constexpr field_desc f_param[] = {
    {"reserved", vt::integer, c::USINT, true},
    {"link_path_size", vt::integer, c::USINT, false},
    {"link_path", vt::epath, 0, false},
    {"descriptor", vt::integer, c::WORD, true},
    {"data_type", vt::integer, c::USINT, true},
    {"data_size", vt::integer, c::USINT, false},
    {"name", vt::string, 0, true},
    {"units", vt::string, 0, false},
    {"help", vt::string, 0, false},
    {"min", vt::typed, 0, false},
    {"max", vt::typed, 0, false},
    {"default", vt::typed, 0, false},
    {"scaling_multiplier", vt::integer, c::UINT, false},
    {"scaling_divisor", vt::integer, c::UINT, false},
    {"scaling_base", vt::integer, c::UINT, false},
    {"scaling_offset", vt::integer, c::DINT, false},
    {"multiplier_link", vt::number_ref, c::UINT, false, param_like},
    {"divisor_link", vt::number_ref, c::UINT, false, param_like},
    {"base_link", vt::number_ref, c::UINT, false, param_like},
    {"offset_link", vt::number_ref, c::UINT, false, param_like},
    {"decimal_precision", vt::integer, c::USINT, false},
    {"international_name", vt::stringi, 0, false},
    {"international_units", vt::stringi, 0, false},
    {"international_help", vt::stringi, 0, false},
};
// ProxyParamN / ProxiedParamN (§3.18): the ParamN layout, but the proxied
// module owns the type, so reserved, descriptor and data type may be empty.
constexpr auto proxy_param_fields() {
  std::array<field_desc, std::size(f_param)> a{};
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = f_param[i];
  a[0].required = a[3].required = a[4].required = false;
  return a;
}
constexpr auto f_proxy_param = proxy_param_fields();
// InputExaN / OutputExaN (§3.18): the InputN layout; the size may be empty and
// the path names the (variable) assembly that carries the data.
constexpr ref_mask exa_targets = bit(rk::assem) | bit(rk::assem_exa);
constexpr field_desc f_io_exa[] = {
    {"size", vt::integer, c::UINT, false},
    {"significant_bits", vt::integer, c::UINT, false},
    {"mask", vt::integer, c::WORD, true},
    {"name", vt::string, 0, true},
    {"path_size", vt::integer, c::USINT, false},
    {"path", vt::member, 0, false, exa_targets},
    {"help", vt::string, 0, false},
};
constexpr field_desc f_any_tail[] = {{"field", vt::any, 0, false}};
constexpr field_desc f_enum_tail[] = {{"value", vt::typed, 0, true}, {"text", vt::string, 0, true}};
constexpr field_desc f_enum_par_tail[] = {{"text", vt::string, 0, true}};
constexpr field_desc f_group[] = {{"name", vt::string, 0, true}, {"count", vt::integer, c::UINT, true}};
constexpr field_desc f_group_tail[] = {{"member", vt::number_ref, c::UINT, true, param_like}};
}  // namespace

const keyword_desc file_keywords[9] = {
    {"DescText", false, entry_id::desc_text, f_desc_text}, {"CreateDate", false, entry_id::create_date, f_date},
    {"CreateTime", false, entry_id::create_time, f_time},  {"ModDate", false, entry_id::mod_date, f_date},
    {"ModTime", false, entry_id::mod_time, f_time},        {"Revision", false, entry_id::file_revision, f_revision},
    {"HomeURL", false, entry_id::home_url, f_string},      {"Exclude", false, entry_id::exclude, f_exclude},
    {"EDSFileCRC", false, entry_id::eds_file_crc, f_crc},
};

const keyword_desc device_keywords[12] = {
    {"VendCode", false, entry_id::vend_code, f_uint},
    {"VendName", false, entry_id::vend_name, f_string},
    {"ProdType", false, entry_id::prod_type, f_uint},
    {"ProdTypeStr", false, entry_id::prod_type_str, f_string},
    {"ProdCode", false, entry_id::prod_code, f_uint},
    {"MajRev", false, entry_id::maj_rev, f_usint},
    {"MinRev", false, entry_id::min_rev, f_usint},
    {"ProdName", false, entry_id::prod_name, f_string},
    {"Catalog", false, entry_id::catalog, f_string},
    {"Icon", false, entry_id::icon, f_string},
    {"IconContents", false, entry_id::icon_contents, f_string},
    {"ApplicationProfilesAssembly", false, entry_id::application_profiles_assembly, f_uint},
};

const keyword_desc classification_keywords[1] = {
    {"Class", true, entry_id::class_n, f_class, f_class},
};

const keyword_desc io_info_keywords[9] = {
    {"Default", false, entry_id::io_default, f_word},        {"PollInfo", false, entry_id::poll_info, f_io_info},
    {"StrobeInfo", false, entry_id::strobe_info, f_io_info}, {"COSInfo", false, entry_id::cos_info, f_io_info},
    {"CyclicInfo", false, entry_id::cyclic_info, f_io_info}, {"Input", true, entry_id::input_n, f_io_data},
    {"Output", true, entry_id::output_n, f_io_data},         {"InputExa", true, entry_id::input_exa_n, f_io_exa},
    {"OutputExa", true, entry_id::output_exa_n, f_io_exa},
};

const keyword_desc param_class_keywords[4] = {
    {"MaxInst", false, entry_id::pc_max_inst, f_uint},
    {"Descriptor", false, entry_id::pc_descriptor, f_word},
    {"CfgAssembly", false, entry_id::pc_cfg_assembly, f_cfg_assembly},
    {"SafetyCfgAssembly", false, entry_id::pc_safety_cfg_assembly, f_cfg_assembly},
};

const keyword_desc params_keywords[7] = {
    {"Param", true, entry_id::param_n, f_param},
    {"ProxyParam", true, entry_id::proxy_param_n, f_proxy_param},
    {"ProxiedParam", true, entry_id::proxied_param_n, f_proxy_param},
    {"ConstructedParam", true, entry_id::constructed_param_n, {}, f_any_tail},
    {"Enum", true, entry_id::enum_n, {}, f_enum_tail},
    {"ProxyEnum", true, entry_id::proxy_enum_n, {}, f_enum_tail},
    {"ProxiedEnum", true, entry_id::proxied_enum_n, {}, f_enum_tail},
};

const keyword_desc enum_par_keywords[1] = {
    {"Param", true, entry_id::enum_par_n, {}, f_enum_par_tail},
};

const keyword_desc groups_keywords[1] = {
    {"Group", true, entry_id::group_n, f_group, f_group_tail},
};

}  // namespace edsc::schema::tables
