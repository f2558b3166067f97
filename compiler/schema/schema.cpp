#include "schema/schema.hpp"

#include <array>

#include "schema/tables.hpp"
#include "schema/text.hpp"

namespace edsc::schema {

namespace {

using sf = section_family;
namespace t = tables;

constexpr std::span<const keyword_desc> none{};

// EDS_FORMAT.md §3 and §3.15 (section name -> class code).
const section_desc sections[] = {
    {"File", sf::file, 0, t::file_keywords, false},
    {"Device", sf::device, 0, t::device_keywords, false},
    {"Device Classification", sf::classification, 0, t::classification_keywords, false},
    {"IO_Info", sf::io_info, 0, t::io_info_keywords, false},
    {"Variant_IO_Info", sf::variant_io_info, 0, t::io_info_keywords, false},
    {"ParamClass", sf::param_class, 0x0F, t::param_class_keywords, false},
    {"Params", sf::params, 0, t::params_keywords, false},
    {"EnumPar", sf::enum_par, 0, t::enum_par_keywords, false},
    {"Groups", sf::groups, 0x10, t::groups_keywords, false},
    {"Assembly", sf::assembly, 0x04, t::assembly_keywords, true},
    {"Connection Manager", sf::connection_manager, 0x06, t::connection_manager_keywords, true},
    {"Port", sf::port, 0xF4, t::port_keywords, true},
    {"Capacity", sf::capacity, 0, t::capacity_keywords, false},
    {"Modular", sf::modular, 0, t::modular_keywords, false},
    {"Identity Class", sf::object_class, 0x01, none, true},
    {"Message Router Class", sf::object_class, 0x02, none, true},
    {"DeviceNet Class", sf::object_class, 0x03, none, true},
    {"Connection Class", sf::object_class, 0x05, none, true},
    {"Register Class", sf::object_class, 0x07, none, true},
    {"Discrete Input Class", sf::object_class, 0x08, none, true},
    {"Discrete Output Class", sf::object_class, 0x09, none, true},
    {"Analog Input Class", sf::object_class, 0x0A, none, true},
    {"Analog Output Class", sf::object_class, 0x0B, none, true},
    {"Presence Sensing Class", sf::object_class, 0x0E, none, true},
    {"File Class", sf::object_class, 0x37, none, true},
    {"Safety Supervisor Class", sf::object_class, 0x39, none, true},
    {"Safety Validator Class", sf::object_class, 0x3A, none, true},
    {"Safety Discrete Output Point Class", sf::object_class, 0x3B, none, true},
    {"Safety Discrete Input Point Class", sf::object_class, 0x3D, none, true},
    {"DLR Class", sf::object_class, 0x47, t::dlr_keywords, true},
    {"QoS Class", sf::object_class, 0x48, none, true},
    {"CIP Security Class", sf::object_class, 0x5D, none, true},
    {"EtherNet/IP Security Class", sf::object_class, 0x5E, none, true},
    {"Certificate Management Class", sf::object_class, 0x5F, none, true},
    {"Authority Class", sf::object_class, 0x60, none, true},
    {"Password Authenticator Class", sf::object_class, 0x61, none, true},
    {"Certificate Authenticator Class", sf::object_class, 0x62, none, true},
    {"Ingress Egress Class", sf::object_class, 0x63, t::ingress_egress_keywords, true},
    {"Connection Configuration", sf::object_class, 0xF3, none, true},
    {"TCP/IP Interface Class", sf::object_class, 0xF5, t::tcpip_keywords, true},
    {"Ethernet Link Class", sf::object_class, 0xF6, t::ethernet_link_keywords, true},
    {"LLDP Management Class", sf::object_class, 0x109, none, true},
    {"LLDP Data Table Class", sf::object_class, 0x10A, none, true},
    {"Time Sync Class", sf::object_class, 0x43, none, true},
    {"Originator Connection List Class", sf::object_class, 0x45, none, true},
};

const section_desc vendor_object_class{"ClassN_VendorM", sf::object_class, 0, none, true};

constexpr std::array<std::string_view, static_cast<std::size_t>(ref_kind::count_)> stems{
    "Param",           "ProxyParam",   "ProxiedParam",  "ConstructedParam", "Enum",
    "Assem",           "AssemExa",     "ProxyAssem",    "ProxiedAssem",     "ProxyAssemExa",
    "ProxiedAssemExa", "Variant",      "VariantExa",    "BitStringVariant", "Array",
    "Connection",      "Group",        "Input",         "Output",           "ProxyEnum",
    "ProxiedEnum",     "ProxyConnect", "ProxiedConnect"};

const keyword_desc* match_in(std::span<const keyword_desc> list, std::string_view kw, split_keyword parts) {
  for (const auto& k : list) {
    if (k.numbered) {
      if (!parts.digits.empty() && iequals(k.stem, parts.stem)) return &k;
    } else if (iequals(k.stem, kw)) {
      return &k;
    }
  }
  return nullptr;
}

}  // namespace

std::string_view stem_of(ref_kind k) { return stems[static_cast<std::size_t>(k)]; }

bool parse_reference(std::string_view text, ref_mask allowed, ref_kind& kind, std::uint32_t& number) {
  const auto parts = split_number(text);
  if (parts.digits.empty() || !parse_u32(parts.digits, number)) return false;
  for (std::size_t i = 0; i < stems.size(); ++i) {
    if ((allowed & (ref_mask{1} << i)) != 0 && iequals(stems[i], parts.stem)) {
      kind = static_cast<ref_kind>(i);
      return true;
    }
  }
  return false;
}

const section_desc* find_section(std::string_view name) {
  for (const auto& s : sections)
    if (iequals(s.name, name)) return &s;
  // `[Connection ManagerN]`: per-port connection lists (§3.11.4).
  const auto parts = split_number(name);
  if (!parts.digits.empty() && iequals(parts.stem, "Connection Manager")) return &sections[10];
  // `[Class940_Vendor1]`: a vendor's own object class, written by Rockwell tools.
  if (name.size() > 5 && iequals(name.substr(0, 5), "Class")) {
    const auto us = name.find('_');
    if (us != std::string_view::npos && us > 5 && iequals(name.substr(us + 1, 6), "Vendor")) {
      std::uint32_t n = 0;
      if (parse_u32(name.substr(5, us - 5), n) && parse_u32(name.substr(us + 7), n)) return &vendor_object_class;
    }
  }
  return nullptr;
}

keyword_match find_keyword(const section_desc& s, std::string_view keyword) {
  const auto parts = split_number(keyword);
  const keyword_desc* k = match_in(s.keywords, keyword, parts);
  if (!k && s.common_keywords) {
    k = match_in(t::common_keywords, keyword, parts);
    if (!k) k = match_in(t::service_description_keyword, keyword, parts);
  }
  keyword_match m;
  m.desc = k;
  if (k && k->numbered && !parse_u32(parts.digits, m.number)) m.desc = nullptr;
  return m;
}

const field_desc* field_at(const keyword_desc& k, std::uint32_t index) {
  if (index < k.fields.size()) return &k.fields[index];
  if (k.tail.empty()) return nullptr;
  return &k.tail[(index - k.fields.size()) % k.tail.size()];
}

std::span<const section_desc> all_sections() { return sections; }
std::span<const keyword_desc> common_object_keywords() { return t::common_keywords; }

}  // namespace edsc::schema
