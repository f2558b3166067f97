// The datasheet of one file: identity, [File], groups, ports, capacity and
// edsc's own findings; parameters, connections and bit maps have their files.
#include <filesystem>

#include <fmt/format.h>

#include "doc/sheet_parts.hpp"
#include "emit/json_values.hpp"
#include "facts/sha256.hpp"

namespace edsc::doc {

namespace detail {

std::string utf8(std::string_view s) { return emit::detail::to_utf8(s); }

std::string trimmed(std::string_view t) {
  // Vendors pad names with blanks; a reader never needs them.
  while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
  while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
  return utf8(t);
}

std::string param_name(const model::device& dev, std::uint32_t target) {
  if (target >= dev.params.size()) return {};
  const auto& p = dev.params[target];
  return p.name.ok() ? trimmed(p.name.text) : std::string{};
}

std::uint32_t reader::section_line(std::uint32_t section) const {
  if (section == model::none || dev.tree == nullptr || section >= dev.tree->sections.size()) return 0;
  return line(dev.tree->sections[section].header.begin);
}

std::string reader::text(const model::value& v) const {
  if (!v.present()) return {};
  if (v.ok() && v.kind == model::value_kind::string) return trimmed(v.text);
  if (v.ok() && v.kind == model::value_kind::real) return fmt::format("{}", v.real);
  return utf8(src.text(v.from.where));
}

std::string reader::ref_text(const model::reference& r, bool with_name) const {
  auto out = fmt::format("{}{}", schema::stem_of(r.kind), r.number);
  if (r.has_bit()) out += fmt::format(":{}", r.bit);
  if (!with_name || !r.resolved()) return out;
  std::string name;
  using schema::ref_kind;
  switch (r.kind) {
    case ref_kind::param:
    case ref_kind::proxy_param:
    case ref_kind::proxied_param:
    case ref_kind::constructed_param: name = param_name(dev, r.target); break;
    case ref_kind::assem:
    case ref_kind::assem_exa:
    case ref_kind::proxy_assem:
    case ref_kind::proxied_assem:
    case ref_kind::proxy_assem_exa:
    case ref_kind::proxied_assem_exa:
      if (r.target < dev.assemblies.size() && dev.assemblies[r.target].name.ok())
        name = trimmed(dev.assemblies[r.target].name.text);
      break;
    default: break;
  }
  return name.empty() ? out : fmt::format("{} ({})", name, out);
}

namespace {

std::string segment_text(const reader& r, const model::epath_segment& s) {
  const auto number = s.has_param              ? r.ref_text(s.param)
                      : !s.placeholder.empty() ? utf8(s.placeholder)
                                               : fmt::format("{}", s.value);
  switch (s.kind) {
    case model::segment_kind::port: return fmt::format("port {}, link {}", number, s.link_address);
    case model::segment_kind::class_id:
      return s.value == 4 && !s.has_param ? "Assembly class" : fmt::format("class 0x{:02X}", s.value);
    case model::segment_kind::instance: return fmt::format("instance {}", number);
    case model::segment_kind::member: return fmt::format("member {}", number);
    case model::segment_kind::connection_point: return fmt::format("connection point {}", number);
    case model::segment_kind::attribute: return fmt::format("attribute {}", number);
    case model::segment_kind::symbol: return fmt::format("symbol \"{}\"", utf8(s.symbol));
    case model::segment_kind::param: return r.ref_text(s.param);
    case model::segment_kind::placeholder:
      return fmt::format("{} (filled in by the configuration tool)", utf8(s.placeholder));
    case model::segment_kind::unknown: return "undecoded bytes";
  }
  return {};
}

}  // namespace

std::string reader::path_text(const model::value& v) const {
  const auto* p = dev.path_of(v);
  if (p == nullptr) return text(v);
  if (p->symbolic) return "a tag name the configuration tool asks for";
  std::string out;
  for (const auto& s : p->segments) join(out, ", ", segment_text(*this, s));
  if (!p->complete) out += " (incomplete)";
  return out;
}

}  // namespace detail

namespace {

using detail::reader;
using detail::utf8;
using model::value;

std::string networks_text(std::uint8_t nets) {
  static constexpr std::pair<std::uint8_t, const char*> names[] = {{model::net_devicenet, "DeviceNet"},
                                                                   {model::net_ethernetip, "EtherNet/IP"},
                                                                   {model::net_controlnet, "ControlNet"},
                                                                   {model::net_componet, "CompoNet"},
                                                                   {model::net_modbus, "Modbus"}};
  std::string out;
  for (const auto& [bit, name] : names)
    if ((nets & bit) != 0) join(out, ", ", std::string(name));
  return out;
}

// "Rockwell Automation (1)": the name the file gives and the number that counts.
std::string named_number(const reader& r, const value& name, const value& number) {
  const auto n = number.is_integer() ? std::to_string(number.as_int()) : r.text(number);
  const auto t = r.text(name);
  if (t.empty()) return n;
  return n.empty() ? t : fmt::format("{} ({})", t, n);
}

void build_summary(const reader& r, const analysis& a, summary& s) {
  const auto& id = r.dev.identity;
  s.file = std::filesystem::path(a.source->path()).filename().string();
  s.vendor = r.text(id.vend_name);
  s.product = r.text(id.prod_name);
  s.type = r.text(id.prod_type_str);
  s.catalog = r.text(id.catalog);
  s.networks = networks_text(r.dev.classes.networks);
  s.identified = id.vend_code.is_integer() && id.prod_type.is_integer() && id.prod_code.is_integer() &&
                 id.maj_rev.is_integer() && id.min_rev.is_integer();
  auto num = [](const value& v) { return v.is_integer() ? static_cast<std::uint32_t>(v.as_uint()) : 0u; };
  s.vendor_id = num(id.vend_code);
  s.type_id = num(id.prod_type);
  s.product_code = num(id.prod_code);
  s.major = num(id.maj_rev);
  s.minor = num(id.min_rev);
  s.revision = id.maj_rev.is_integer() || id.min_rev.is_integer()
                   ? fmt::format("{}.{}", r.text(id.maj_rev), r.text(id.min_rev))
                   : std::string{};
  s.sha256 = emit::sha256_hex(a.text());
  for (const auto& d : a.diags) {
    s.errors += d.level == severity::error ? 1 : 0;
    s.warnings += d.level == severity::warning ? 1 : 0;
    s.notes += d.level == severity::note ? 1 : 0;
  }
}

void build_identity(const reader& r, sheet& s) {
  const auto& id = r.dev.identity;
  auto& t = s.identity;
  t.head = {"Field", "Value"};
  auto row = [&](const char* label, cell c) {
    if (!c.text.empty()) t.rows.push_back({{label}, std::move(c)});
  };
  row("Vendor", {named_number(r, id.vend_name, id.vend_code), r.line(id.vend_code.from)});
  row("Product type", {named_number(r, id.prod_type_str, id.prod_type), r.line(id.prod_type.from)});
  if (id.prod_code.is_integer())
    row("Product code", {fmt::format("{} (0x{:04X})", id.prod_code.as_uint(), id.prod_code.as_uint() & 0xFFFF),
                         r.line(id.prod_code.from)});
  else
    row("Product code", r.at(id.prod_code));
  row("Revision", {s.sum.revision, r.line(id.maj_rev.from)});
  row("Product name", r.at(id.prod_name));
  row("Catalog", r.at(id.catalog));
  // The same words as the library index's tooltip for such a file.
  auto nets = s.sum.networks.empty() ? std::string("none named, neither in [Device Classification] nor by its sections")
                                     : s.sum.networks;
  if (!r.dev.classes.from_classification && !s.sum.networks.empty()) nets += " (from the sections present)";
  if (r.dev.classes.safety) nets += ", CIP Safety";
  row("Networks", {nets, r.section_line(r.dev.classes.section)});
  row("Icon", r.at(id.icon));
  if (!id.icon_data.empty())
    row("Icon data", {fmt::format("{} bytes (IconContents)", id.icon_data.size()), r.line(id.icon_contents.from)});
  const auto expected = conventional_name(s.sum);
  std::string file = s.sum.file;
  if (!expected.empty()) {
    std::string stem = s.sum.file.substr(0, 16);
    for (auto& c : stem) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const bool follows = s.sum.file.size() == 20 && stem == expected.substr(0, 16);
    file += follows ? "\nfollows the VVVVTTTTPPPPMM00.eds convention" : "\nthe convention names it " + expected;
  }
  row("File", {file, 0});

  const auto& f = r.dev.file;
  auto& fi = s.file_info;
  fi.head = {"Field", "Value"};
  auto frow = [&](const char* label, const value& v) {
    if (v.present()) fi.rows.push_back({{label}, r.at(v)});
  };
  frow("Description", f.desc_text);
  frow("Created", f.create_date);
  frow("Modified", f.mod_date);
  frow("File revision", f.revision);
  frow("Home URL", f.home_url);
}

void build_groups(const reader& r, sheet& s) {
  s.groups.head = {"Group", "Name", "Parameters"};
  for (const auto& g : r.dev.groups) {
    std::string members;
    for (const auto& m : g.members) {
      const auto* ref = m.as_ref();
      join(members, "\n", (ref != nullptr ? r.ref_text(*ref) : r.text(m)));
    }
    s.groups.rows.push_back(
        {{fmt::format("Group{}", g.number), r.line(g.from), cell_style::code}, r.at(g.name), {members}});
  }
}

void build_ports(const reader& r, sheet& s) {
  s.ports.head = {"Port", "Type", "Name", "Path", "Port number"};
  for (const auto& p : r.dev.ports) {
    s.ports.rows.push_back({{fmt::format("Port{}", p.number), r.line(p.from), cell_style::code},
                            r.at(p.type),
                            r.at(p.name),
                            {r.path_text(p.path), r.line(p.path.from)},
                            r.at(p.port_number, cell_style::number)});
  }
}

void build_capacity(const reader& r, sheet& s) {
  s.capacity.head = {"Entry", "Value"};
  for (const auto& st : r.dev.cap.settings) {
    std::string v;
    for (const auto& f : st.fields) join(v, ", ", r.text(f));
    s.capacity.rows.push_back({{utf8(st.keyword), r.line(st.from), cell_style::code}, {v, 0, cell_style::number}});
  }
  for (const auto& t : r.dev.cap.tspecs) {
    const auto dir = r.text(t.direction);
    s.capacity.rows.push_back(
        {{fmt::format("TSpec{}", t.number), r.line(t.from), cell_style::code},
         {fmt::format("{}: {} bytes at up to {} packets/s", dir.empty() ? "?" : dir, r.text(t.size), r.text(t.rate))}});
  }
}

void build_findings(const reader& r, const analysis& a, sheet& s) {
  for (const auto& d : a.diags) {
    finding f;
    f.level = d.level;
    f.id = std::string(rule_of(d.id).name);
    f.message = utf8(d.message);
    if (!(d.where.empty() && d.where.begin == 0)) {
      const auto pos = r.src.position(d.where.begin);
      f.line = pos.line;
      f.column = pos.column;
    }
    for (const auto& n : d.notes) f.notes.emplace_back(r.line(n.where.begin), utf8(n.message));
    s.findings.push_back(std::move(f));
  }
}

}  // namespace

std::string conventional_name(const summary& s) {
  if (!s.identified) return {};
  return fmt::format("{:04X}{:04X}{:04X}{:02X}00.eds", s.vendor_id & 0xFFFF, s.type_id & 0xFFFF,
                     s.product_code & 0xFFFF, s.major & 0xFF);
}

sheet build_sheet(const analysis& a) {
  const reader r{a.dev, *a.source};
  sheet s;
  build_summary(r, a, s.sum);
  s.title = !s.sum.product.empty() ? s.sum.product : s.sum.file;
  s.subtitle = s.sum.vendor;
  if (!s.sum.type.empty()) join(s.subtitle, " · ", s.sum.type);
  build_identity(r, s);
  detail::build_connections(r, s);
  detail::build_maps(r, s);
  detail::build_params(r, s);
  build_groups(r, s);
  build_ports(r, s);
  build_capacity(r, s);
  build_findings(r, a, s);
  return s;
}

}  // namespace edsc::doc
