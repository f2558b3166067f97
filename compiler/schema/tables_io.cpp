// Schema rows for [Assembly], [Connection Manager], [Port], [Capacity],
// [Modular] and the object-class sections (EDS_FORMAT.md §3.10-3.15).
#include <array>
#include <iterator>

#include "schema/tables.hpp"

namespace edsc::schema::tables {

using vt = value_type;
using rk = ref_kind;
namespace c = code;

namespace {
constexpr std::string_view yes_no[] = {"Yes", "No"};
constexpr std::string_view tspec_words[] = {"Tx", "Rx", "TxRx"};
constexpr std::string_view port_words[] = {"TCP", "DeviceNet", "ControlNet", "CompoNet", "EtherNetIP"};

constexpr ref_mask any_param =
    bit(rk::param) | bit(rk::proxy_param) | bit(rk::proxied_param) | bit(rk::constructed_param);
constexpr ref_mask any_assem = bit(rk::assem) | bit(rk::assem_exa) | bit(rk::proxy_assem) | bit(rk::proxied_assem) |
                               bit(rk::proxy_assem_exa) | bit(rk::proxied_assem_exa);
constexpr ref_mask any_layout =
    any_param | any_assem | bit(rk::variant) | bit(rk::variant_exa) | bit(rk::bitstring_variant) | bit(rk::array);

constexpr field_desc f_assem[] = {
    {"name", vt::string, 0, false},
    {"path", vt::epath, 0, false},
    {"size", vt::int_or_ref, c::UINT, false, any_param},
    {"descriptor", vt::integer, c::WORD, false},
    {"reserved1", vt::any, 0, false},
    {"reserved2", vt::any, 0, false},
};
constexpr field_desc f_assem_tail[] = {
    {"member_size", vt::int_or_ref, c::UINT, false, any_param},
    {"member", vt::member, c::UDINT, false, any_layout},
};
constexpr field_desc f_variant[] = {
    {"name", vt::string, 0, false},   {"help", vt::string, 0, false},
    {"reserved1", vt::any, 0, false}, {"reserved2", vt::any, 0, false},
    {"reserved3", vt::any, 0, false}, {"selector", vt::reference, 0, true, any_param | any_assem},
};
constexpr field_desc f_variant_tail[] = {
    {"selection", vt::integer, c::UDINT, true},
    {"target", vt::reference, 0, false, any_layout},
};
constexpr field_desc f_bitstring_tail[] = {
    {"bit", vt::integer, c::UINT, true},
    {"when_set", vt::reference, 0, false, any_layout},
    {"when_clear", vt::reference, 0, false, any_layout},
};
constexpr field_desc f_array[] = {
    {"name", vt::string, 0, false},
    {"path", vt::epath, 0, false},
    {"descriptor", vt::integer, c::WORD, false},
    {"help", vt::string, 0, false},
    {"reserved1", vt::any, 0, false},
    {"reserved2", vt::any, 0, false},
    {"reserved3", vt::any, 0, false},
    {"element_size", vt::int_or_ref, c::UINT, false, any_param},
    {"element_type", vt::reference, 0, false, any_layout},
    {"dimensions", vt::integer, c::USINT, false},
};
constexpr field_desc f_array_tail[] = {{"extent", vt::int_or_ref, c::UDINT, false, any_param}};

constexpr field_desc f_connection[] = {
    {"trigger_transport", vt::integer, c::DWORD, true},
    {"parameters", vt::integer, c::DWORD, true},
    {"ot_rpi", vt::int_or_ref, c::UDINT, false, any_param},
    {"ot_size", vt::int_or_ref, c::UINT, false, any_param},
    {"ot_format", vt::reference, 0, false, any_layout},
    {"to_rpi", vt::int_or_ref, c::UDINT, false, any_param},
    {"to_size", vt::int_or_ref, c::UINT, false, any_param},
    {"to_format", vt::reference, 0, false, any_layout},
    {"proxy_config_size", vt::int_or_ref, c::UINT, false, any_param},
    {"proxy_config_format", vt::reference, 0, false, any_layout},
    {"target_config_size", vt::int_or_ref, c::UINT, false, any_param},
    {"target_config_format", vt::reference, 0, false, any_layout},
    {"name", vt::string, 0, true},
    {"help", vt::string, 0, false},
    {"path", vt::epath, 0, true},
    {"safety_async", vt::integer, c::UDINT, false},
    {"safety_max_consumers", vt::integer, c::UDINT, false},
};
// ProxyConnectN / ProxiedConnectN (§3.18): the ConnectionN layout with
// every field zero or empty; nothing is required.
constexpr auto proxy_connection_fields() {
  std::array<field_desc, std::size(f_connection)> a{};
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i] = f_connection[i];
    a[i].required = false;
  }
  return a;
}
constexpr auto f_proxy_connection = proxy_connection_fields();
constexpr field_desc f_yes_no[] = {{"value", vt::keyword, 0, true, 0, yes_no}};
constexpr field_desc f_uint[] = {{"value", vt::integer, c::UINT, true}};
constexpr field_desc f_udint[] = {{"value", vt::integer, c::UDINT, true}};
constexpr field_desc f_usint[] = {{"value", vt::integer, c::USINT, true}};
constexpr field_desc f_bool[] = {{"value", vt::integer, c::BOOL, true}};
constexpr field_desc f_real[] = {{"value", vt::real, 0, true}};
constexpr field_desc f_string[] = {{"value", vt::string, 0, true}};
constexpr field_desc f_any[] = {{"value", vt::any, 0, false}};
constexpr field_desc f_conn_list[] = {{"connection", vt::number_ref, c::UINT, true, bit(rk::connection)}};
constexpr field_desc f_rack[] = {
    {"vendor", vt::integer, c::UINT, false},
    {"product_type", vt::integer, c::UINT, false},
    {"product_code", vt::integer, c::UINT, false},
    {"major_revision", vt::integer, c::USINT, false},
    {"minor_revision", vt::integer, c::USINT, false},
    {"reserved1", vt::any, 0, false},
    {"reserved2", vt::any, 0, false},
    {"reserved3", vt::any, 0, false},
};
constexpr field_desc f_rack_slot[] = {{"slot", vt::integer, c::UINT, false}};
constexpr field_desc f_param_ref[] = {{"param", vt::reference, 0, true, any_param}};

constexpr field_desc f_port[] = {
    {"type", vt::keyword, 0, true, 0, port_words},
    {"name", vt::string, 0, true},
    {"path", vt::epath, 0, true},
    {"port_number", vt::integer, c::UINT, true},
};
constexpr field_desc f_tspec[] = {
    {"direction", vt::keyword, 0, true, 0, tspec_words},
    {"size", vt::integer, c::UINT, true},
    {"rate", vt::integer, c::UDINT, true},
};
// Lists are mostly plain numbers, but datasets such as `{0x0E,*}` occur.
constexpr field_desc f_attr_tail[] = {{"attribute", vt::any, 0, true}};
constexpr field_desc f_service_tail[] = {{"service", vt::any, 0, true}};
constexpr field_desc f_qct[] = {{"ready_time", vt::integer, c::UINT, true},
                                {"accumulated_time", vt::integer, c::UINT, true}};
constexpr field_desc f_service_description[] = {
    {"service", vt::integer, c::USINT, true}, {"name", vt::string, 0, false},  {"path", vt::epath, 0, false},
    {"request", vt::any, 0, false},           {"response", vt::any, 0, false},
};
}  // namespace

const keyword_desc assembly_keywords[10] = {
    {"Assem", true, entry_id::assem_n, f_assem, f_assem_tail},
    {"AssemExa", true, entry_id::assem_exa_n, f_assem, f_assem_tail},
    {"ProxyAssem", true, entry_id::proxy_assem_n, f_assem, f_assem_tail},
    {"ProxiedAssem", true, entry_id::proxied_assem_n, f_assem, f_assem_tail},
    {"ProxyAssemExa", true, entry_id::proxy_assem_exa_n, f_assem, f_assem_tail},
    {"ProxiedAssemExa", true, entry_id::proxied_assem_exa_n, f_assem, f_assem_tail},
    {"Variant", true, entry_id::variant_n, f_variant, f_variant_tail},
    {"VariantExa", true, entry_id::variant_exa_n, f_variant, f_variant_tail},
    {"BitStringVariant", true, entry_id::bitstring_variant_n, f_variant, f_bitstring_tail},
    {"Array", true, entry_id::array_n, f_array, f_array_tail},
};

const keyword_desc connection_manager_keywords[11] = {
    {"Connection", true, entry_id::connection_n, f_connection},
    {"ProxyConnect", true, entry_id::proxy_connection_n, f_proxy_connection},
    {"ProxiedConnect", true, entry_id::proxied_connection_n, f_proxy_connection},
    {"PITNS", false, entry_id::pitns, f_yes_no},
    {"PITNS_usec", false, entry_id::pitns_usec, f_yes_no},
    {"MaxSafetyConnections", false, entry_id::safety_setting, f_uint},
    {"MaxSafetyInputCnxns", false, entry_id::safety_setting, f_uint},
    {"MaxSafetyOutputCnxns", false, entry_id::safety_setting, f_uint},
    {"SafetyFormat", false, entry_id::safety_setting, f_uint},
    {"DefaultSafetyConnections", false, entry_id::default_safety_connections, {}, f_conn_list},
    {"ConnectionTimeoutMultiplier", false, entry_id::safety_setting, f_any},
};

const keyword_desc port_keywords[1] = {
    {"Port", true, entry_id::port_n, f_port, f_any},
};

const keyword_desc capacity_keywords[12] = {
    {"TSpec", true, entry_id::tspec_n, f_tspec},
    {"ConnOverhead", false, entry_id::capacity_setting, f_real},
    {"MaxCIPConnections", false, entry_id::capacity_setting, f_uint},
    {"MaxIOConnections", false, entry_id::capacity_setting, f_uint},
    {"MaxMsgConnections", false, entry_id::capacity_setting, f_uint},
    {"MaxIOProducers", false, entry_id::capacity_setting, f_uint},
    {"MaxIOConsumers", false, entry_id::capacity_setting, f_uint},
    {"MaxIOProduceConsume", false, entry_id::capacity_setting, f_uint},
    {"MaxIOMcastProducers", false, entry_id::capacity_setting, f_uint},
    {"MaxIOMcastConsumers", false, entry_id::capacity_setting, f_uint},
    {"MaxConsumersPerMcast", false, entry_id::capacity_setting, f_uint},
    {"MaxSafetyConnections", false, entry_id::capacity_setting, f_uint},
};

const keyword_desc modular_keywords[5] = {
    {"DefineSlotsInRack", false, entry_id::define_slots_in_rack, f_uint},
    {"SlotDisplayRule", false, entry_id::slot_display_rule, f_param_ref},
    {"Width", false, entry_id::width, f_uint},
    // A chassis the module fits, and the slots it may occupy (§3.18).
    {"Rack", true, entry_id::rack_n, f_rack, f_rack_slot},
    // A hex byte string identifying the module to the adapter (§3.18).
    {"ExternalID", false, entry_id::external_id, f_string},
};

const keyword_desc common_keywords[10] = {
    {"Revision", false, entry_id::object_setting, f_uint},
    {"Object_Name", false, entry_id::object_setting, f_string},
    {"Object_Class_Code", false, entry_id::object_setting, f_udint},
    {"MaxInst", false, entry_id::object_setting, f_uint},
    {"Number_Of_Static_Instances", false, entry_id::object_setting, f_uint},
    {"Max_Number_Of_Dynamic_Instances", false, entry_id::object_setting, f_uint},
    {"Class_Attributes", false, entry_id::attribute_list, {}, f_attr_tail},
    {"Instance_Attributes", false, entry_id::attribute_list, {}, f_attr_tail},
    {"Class_Services", false, entry_id::service_list, {}, f_service_tail},
    {"Instance_Services", false, entry_id::service_list, {}, f_service_tail},
};
// Service_DescriptionN is numbered, so it lives beside the class-specific rows.
const keyword_desc tcpip_keywords[2] = {
    // ENetQCTN = ready-for-connection time, accumulated CIP connection time (ms).
    {"ENetQCT", true, entry_id::object_setting, f_qct},
    {"ENetQCON", false, entry_id::object_setting, f_uint},
};
const keyword_desc ethernet_link_keywords[3] = {
    {"InterfaceSpeed", true, entry_id::object_setting, f_udint},
    {"InterfaceLabel", true, entry_id::object_setting, f_string},
    {"InterfaceType", true, entry_id::object_setting, f_usint},
};
const keyword_desc dlr_keywords[2] = {
    {"Ring_Supervisor_Capable", false, entry_id::object_setting, f_yes_no},
    {"Redunant_Gateway_Capable", false, entry_id::object_setting, f_yes_no},
};
const keyword_desc ingress_egress_keywords[1] = {
    {"Maintain_Existing_Connection", false, entry_id::object_setting, f_bool},
};
const keyword_desc service_description_keyword[1] = {
    {"Service_Description", true, entry_id::service_description_n, f_service_description},
};

}  // namespace edsc::schema::tables
