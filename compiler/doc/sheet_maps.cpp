// Bit maps: every assembly and every DeviceNet data set as runs of bits, each
// named by the parameter (or whatever the member names), padding explicit.
#include <algorithm>
#include <charconv>

#include <fmt/format.h>

#include "doc/sheet_parts.hpp"
#include "facts/header_parts.hpp"

namespace edsc::doc::detail {

namespace {

using model::value;

class map_builder {
 public:
  explicit map_builder(bit_map& m) : m_(m) {}

  void add(std::string label, std::string detail, std::uint32_t bits, bool padding, std::uint32_t line) {
    if (bits == 0) return;
    bit_block b{std::move(label), std::move(detail), pos_, bits, padding, padding ? 0 : next_color_++, line};
    pos_ += bits;
    m_.blocks.push_back(std::move(b));
  }
  // Bits up to the end of the data that no member describes.
  void finish() {
    if (pos_ < m_.bytes * 8) add("unused", "no member describes these bits", m_.bytes * 8 - pos_, true, 0);
  }
  [[nodiscard]] std::uint32_t position() const { return pos_; }

 private:
  bit_map& m_;
  std::uint32_t pos_ = 0;
  std::uint32_t next_color_ = 0;
};

bool is_param_kind(schema::ref_kind k) {
  using schema::ref_kind;
  return k == ref_kind::param || k == ref_kind::proxy_param || k == ref_kind::proxied_param ||
         k == ref_kind::constructed_param;
}

// What one assembly member is called on the map, and its tooltip detail.
std::pair<std::string, std::string> member_label(const reader& r, const model::assembly_member& m) {
  if (const auto* ref = m.ref.as_ref()) {
    auto id = r.ref_text(*ref, false);
    if (is_param_kind(ref->kind) && ref->resolved()) {
      const auto& p = r.dev.params[ref->target];
      auto name = param_name(r.dev, ref->target);
      auto detail = p.type != nullptr ? fmt::format("{}, {}", id, p.type->name) : id;
      if (ref->has_bit()) name += fmt::format(" (bit {})", ref->bit);
      return {name.empty() ? id : name, detail};
    }
    auto named = r.ref_text(*ref);
    return {named, id};
  }
  if (m.ref.ok() && m.ref.kind == model::value_kind::epath) return {r.path_text(m.ref), "EPATH " + r.text(m.ref)};
  return {"= " + r.text(m.ref), "constant"};
}

std::uint32_t instance_of(const model::device& dev, const value& path) {
  const auto* p = dev.path_of(path);
  if (p == nullptr) return 0;
  bool assembly_class = false;
  for (const auto& s : p->segments) {
    if (s.kind == model::segment_kind::class_id) assembly_class = !s.has_param && s.value == 4;
    if (assembly_class && !s.has_param &&
        (s.kind == model::segment_kind::instance || s.kind == model::segment_kind::connection_point))
      return s.value;
  }
  return 0;
}

void fill_from_members(const reader& r, const model::assembly& a, map_builder& b) {
  for (const auto& m : a.members) {
    const auto bits = emit::number_or_param_default(r.dev, m.size).value_or(0);
    if (!m.ref.present()) {
      b.add("padding", "reserved bits", static_cast<std::uint32_t>(bits), true, r.line(m.size.from));
      continue;
    }
    auto [label, detail] = member_label(r, m);
    b.add(std::move(label), std::move(detail), static_cast<std::uint32_t>(bits), false, r.line(m.ref.from));
  }
}

std::uint64_t member_bits(const reader& r, const model::assembly& a) {
  std::uint64_t bits = 0;
  for (const auto& m : a.members) bits += emit::number_or_param_default(r.dev, m.size).value_or(0);
  return bits;
}

// Maps are drawn, so their size is bounded: beyond this the table says it.
constexpr std::uint64_t max_map_bytes = 1u << 16;

void assembly_map(const reader& r, const model::assembly& a, sheet& s) {
  static constexpr const char* stems[] = {"Assem",        "AssemExa",      "ProxyAssem",
                                          "ProxiedAssem", "ProxyAssemExa", "ProxiedAssemExa"};
  const auto keyword = fmt::format("{}{}", stems[static_cast<int>(a.kind)], a.number);
  bit_map m;
  m.id = fmt::format("{}{}", stems[static_cast<int>(a.kind)], a.number);
  for (auto& c : m.id) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto name = r.text(a.name);
  m.title = name.empty() ? keyword : fmt::format("{}: {}", keyword, name);
  m.line = r.line(a.from);
  const auto size = emit::number_or_param_default(r.dev, a.size);
  const auto bits = member_bits(r, a);
  const std::uint64_t bytes = std::max<std::uint64_t>(size.value_or(0), (bits + 7) / 8);
  if (bytes == 0 || bytes > max_map_bytes) return;
  m.bytes = static_cast<std::uint32_t>(bytes);
  m.caption = fmt::format("{} byte{}", m.bytes, m.bytes == 1 ? "" : "s");
  if (a.path.present()) m.caption += ", path: " + r.path_text(a.path);
  if (size && bits > *size * 8)
    m.note = fmt::format("the members take {} bits, more than the {} bytes the size field gives", bits, *size);
  map_builder b(m);
  if (a.members.empty()) b.add(name.empty() ? keyword : name, "members not described", m.bytes * 8, false, m.line);
  fill_from_members(r, a, b);
  b.finish();
  s.maps.push_back(std::move(m));
}

// "Bit 0: sensor output", "Bits 2-3: margin", "Byte 1: presence": the layout
// some DeviceNet files write into a data set's help. Used only when every
// such line fits the data and none overlaps another.
struct help_field {
  std::uint32_t first = 0, bits = 0;
  std::string label;
};

std::optional<help_field> help_line(std::string_view line) {
  while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
  std::uint32_t unit = 0;
  for (auto [word, u] : {std::pair{"Bits ", 1u}, {"Bit ", 1u}, {"Bytes ", 8u}, {"Byte ", 8u}}) {
    const std::string_view w(word);
    if (line.size() > w.size() && line.substr(0, w.size()) == w) {
      unit = u;
      line.remove_prefix(w.size());
      break;
    }
  }
  if (unit == 0) return std::nullopt;
  std::uint32_t lo = 0, hi = 0;
  auto [p, ec] = std::from_chars(line.data(), line.data() + line.size(), lo);
  if (ec != std::errc{}) return std::nullopt;
  hi = lo;
  if (p < line.data() + line.size() && *p == '-') {
    auto [q, ec2] = std::from_chars(p + 1, line.data() + line.size(), hi);
    if (ec2 != std::errc{} || hi < lo) return std::nullopt;
    p = q;
  }
  if (p == line.data() + line.size() || *p != ':' || hi > 4096) return std::nullopt;
  std::string_view label(p + 1, static_cast<std::size_t>(line.data() + line.size() - p - 1));
  while (!label.empty() && label.front() == ' ') label.remove_prefix(1);
  return help_field{lo * unit, (hi - lo + 1) * unit, std::string(label)};
}

std::vector<help_field> help_layout(std::string_view help, std::uint32_t total_bits) {
  std::vector<help_field> out;
  std::size_t start = 0;
  while (start <= help.size()) {
    const auto end = std::min(help.find('\n', start), help.size());
    if (auto f = help_line(help.substr(start, end - start))) out.push_back(std::move(*f));
    start = end + 1;
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::uint32_t pos = 0;
  for (const auto& f : out) {
    if (f.first < pos || f.first + f.bits > total_bits) return {};
    pos = f.first + f.bits;
  }
  return out;
}

const model::assembly* assembly_at(const model::device& dev, std::uint32_t instance) {
  if (instance == 0) return nullptr;
  for (const auto& a : dev.assemblies)
    if (!a.members.empty() && instance_of(dev, a.path) == instance) return &a;
  return nullptr;
}

void io_map(const reader& r, const model::io_data& d, const char* prefix, sheet& s) {
  if (!d.size.is_integer() || d.size.as_uint() == 0 || d.size.as_uint() > max_map_bytes) return;
  bit_map m;
  const auto keyword = fmt::format("{}{}", d.output ? "Output" : "Input", d.number);
  m.id = fmt::format("{}{}", *prefix != 0 ? "variant-" : "", keyword);
  for (auto& c : m.id) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto name = r.text(d.name);
  m.title = fmt::format("{}{}{}", prefix, keyword, name.empty() ? "" : ": " + name);
  m.line = r.line(d.from);
  m.bytes = static_cast<std::uint32_t>(d.size.as_uint());
  m.caption = fmt::format("{} byte{}", m.bytes, m.bytes == 1 ? "" : "s");
  if (d.path.present()) m.caption += ", path: " + r.path_text(d.path);
  map_builder b(m);
  const auto label = name.empty() ? keyword : name;
  if (const auto* a = assembly_at(r.dev, instance_of(r.dev, d.path));
      a != nullptr && member_bits(r, *a) <= m.bytes * 8u) {
    m.caption += fmt::format(", members from Assem{}", a->number);
    fill_from_members(r, *a, b);
  } else if (auto fields = help_layout(d.help.ok() ? r.text(d.help) : std::string{}, m.bytes * 8); !fields.empty()) {
    m.caption += ", fields as the help text describes them";
    for (const auto& f : fields) {
      if (f.first > b.position()) b.add("unused", "", f.first - b.position(), true, 0);
      const bool unused = f.label.rfind("unused", 0) == 0 || f.label.rfind("reserved", 0) == 0;
      b.add(f.label, fmt::format("{} (from the help text)", label), f.bits, unused, r.line(d.help.from));
    }
  } else {
    const auto sig = d.significant_bits.is_integer() ? d.significant_bits.as_uint() : 0;
    const auto used = sig == 0 || sig > m.bytes * 8u ? m.bytes * 8u : static_cast<std::uint32_t>(sig);
    b.add(label, keyword, used, false, m.line);
  }
  b.finish();
  s.maps.push_back(std::move(m));
}

}  // namespace

void build_maps(const reader& r, sheet& s) {
  for (const auto* io : {&r.dev.io, &r.dev.variant_io}) {
    const char* prefix = io == &r.dev.io ? "" : "Variant ";
    for (const auto& d : io->inputs) io_map(r, d, prefix, s);
    for (const auto& d : io->outputs) io_map(r, d, prefix, s);
  }
  for (const auto& a : r.dev.assemblies) assembly_map(r, a, s);
  // A keyword written twice must not give two elements one anchor.
  std::vector<std::string> seen;
  for (auto& m : s.maps) {
    const auto base = m.id;
    for (int n = 2; std::find(seen.begin(), seen.end(), m.id) != seen.end(); ++n) m.id = fmt::format("{}-{}", base, n);
    seen.push_back(m.id);
  }
}

}  // namespace edsc::doc::detail
