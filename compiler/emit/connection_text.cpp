// The text of `edsc connection`: one block per ConnectionN, each line a
// setting a scanner asks for, with the EDS field it comes from.
#include <fmt/format.h>

#include "emit/connection_render.hpp"

namespace edsc::emit {

namespace {

using namespace connections;

std::string joined(const std::vector<std::string>& words, std::string_view sep = ", ") {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : std::string(sep)) + w;
  return out;
}

template <class T, class F>
std::string words_of(const std::vector<T>& xs, F&& word) {
  std::vector<std::string> w;
  for (const auto& x : xs) w.emplace_back(word(x));
  return w.empty() ? "none" : joined(w);
}

// Long byte strings wrap at 16 bytes, aligned under the first.
std::string wrapped_hex(const cip::bytes& b, std::size_t indent) {
  std::string out;
  for (std::size_t i = 0; i < b.size(); i += 16) {
    if (i > 0) out += "\n" + std::string(indent, ' ');
    out += hex_bytes(cip::bytes(b.begin() + static_cast<std::ptrdiff_t>(i),
                                b.begin() + static_cast<std::ptrdiff_t>(std::min(b.size(), i + 16))));
  }
  return out;
}

std::string size_words(const direction_setting& d) {
  if (!d.used) return "none (null connection)";
  std::string s = fmt::format("{} data", d.data_size);
  if (d.sequence) s += " + 2 sequence";
  if (d.run_idle) s += " + 4 run/idle";
  s += fmt::format(" = {} bytes, {}", d.asked.size, d.asked.variable ? "variable" : "fixed");
  if (d.fixed && d.variable) s += " (fixed or variable offered)";
  return s;
}

std::string rpi_words(const rpi_setting& r, std::string_view other) {
  const auto asked = interval_words(r.asked_us);
  switch (r.source) {
    case rpi_source::number: return fmt::format("RPI {} (the EDS gives {} µs)", asked, r.asked_us);
    case rpi_source::param: {
      std::string range = "no limits given";
      if (r.min_us && r.max_us)
        range = fmt::format("from {} to {}", interval_words(*r.min_us), interval_words(*r.max_us));
      else if (r.min_us)
        range = fmt::format("at least {}", interval_words(*r.min_us));
      else if (r.max_us)
        range = fmt::format("at most {}", interval_words(*r.max_us));
      return fmt::format("RPI {} (Param{}'s default; {})", asked, r.param, range);
    }
    case rpi_source::other: return fmt::format("RPI {} (field empty: the {} RPI)", asked, other);
    case rpi_source::not_given: return fmt::format("RPI {} (the EDS gives none: edsc's default)", asked);
  }
  return "RPI " + asked;
}

void direction_text(std::string& out, std::string_view name, std::string_view other, const direction_setting& d) {
  constexpr std::size_t indent = 16;
  out += fmt::format("  {:<13} {}\n", name, size_words(d));
  if (!d.used) return;
  const std::string pad(indent, ' ');
  out += fmt::format("{}instance {}, {}\n", pad, d.instance, format_words(d.format));
  out += fmt::format("{}{} (offered: {}), {} priority (offered: {})\n", pad, type_words(d.asked.type),
                     words_of(d.types, type_words), priority_words(d.asked.priority),
                     words_of(d.priorities, priority_words));
  out += pad + "network parameters ";
  out += d.word16 ? fmt::format("0x{:04X} (Forward_Open), ", *d.word16) : std::string("over 511 bytes: ");
  out += fmt::format("0x{:08X} (Large_Forward_Open)\n", d.word32);
  out += fmt::format("{}{}\n", pad, rpi_words(d.rpi, other));
}

void path_text(std::string& out, const connection_setting& s) {
  out += fmt::format("  {:<13} {} ({} bytes)\n", "path", wrapped_hex(s.app_path, 16), s.app_path.size());
  for (const auto& p : s.path) {
    std::string value = p.value ? fmt::format("{}", *p.value) : std::string("(the tool fills it in)");
    if (p.param != 0) value += fmt::format(" (Param{} default)", p.param);
    const auto role = role_words(p.role);
    out += fmt::format("    {:<14}{} {}{}{}\n", hex_bytes(p.bytes), segment_words(p.kind), value,
                       role.empty() ? "" : ": ", role);
  }
}

void owner_text(std::string& out, const connection_setting& s) {
  if (s.kind.type == model::app_type::exclusive_owner) return;
  std::vector<std::string> names;
  for (const auto n : s.owners) names.push_back(fmt::format("Connection{}", n));
  if (s.kind.type == model::app_type::listen_only)
    out += names.empty() ? fmt::format("  {:<13} none in this EDS produces input point {}\n", "needs", s.to.instance)
                         : fmt::format("  {:<13} one of {} open first (same input point {})\n", "needs", joined(names),
                                       s.to.instance);
  else if (!names.empty())
    out += fmt::format("  {:<13} input point {} with {}\n", "shares", s.to.instance, joined(names));
}

void key_text(std::string& out, const connection_setting& s) {
  if (!s.key) {
    out += fmt::format("  {:<13} none: [Device] lacks a number the key needs\n", "key");
    return;
  }
  const auto& k = *s.key;
  out += fmt::format("  {:<13} {}: vendor {}, device type {}, product code {}, revision {}.{}, {}\n", "key",
                     hex_bytes(s.key_bytes), k.vendor, k.device_type, k.product_code, k.major, k.minor,
                     k.compatible ? "compatible" : "exact");
}

// Each member parameter of the configuration data with the value the bytes hold.
void config_text(std::string& out, const connection_setting& s) {
  for (const auto& f : s.config_fields) {
    const auto& d = f.field;
    const auto bits = d.bits == 1 ? fmt::format("bit {}", d.bit) : fmt::format("bits {}-{}", d.bit, d.bit + d.bits - 1);
    out += fmt::format("    Param{}{} = {}{} ({}){}\n", d.param, d.name.empty() ? "" : fmt::format(" \"{}\"", d.name),
                       number_text(f.value), f.enum_text.empty() ? "" : fmt::format(" \"{}\"", f.enum_text), bits,
                       f.set ? ", set by --set" : "");
  }
}

void one_text(std::string& out, const connection_setting& s, const source_file& src) {
  const auto lc = src.position(s.at.begin);
  out += fmt::format("Connection{} \"{}\" (line {})\n", s.number, s.name, lc.line);
  std::vector<std::string> classes;
  for (const auto c : s.classes) classes.push_back(fmt::format("{}", c));
  out += fmt::format("  {:<13} {}{}{}\n", "kind", kind_words(s.kind), s.kind.configured ? ", with configuration" : "",
                     s.redundant_owner ? "; redundant owner offered" : "");
  out += fmt::format("  {:<13} class {}, {} (offered: {}); transport byte 0x{:02X}\n", "transport",
                     classes.empty() ? "none" : joined(classes), s.trigger_asked,
                     s.triggers.empty() ? "none" : joined(s.triggers), s.transport);
  owner_text(out, s);
  if (!s.cannot_express.empty()) out += fmt::format("  {:<13} no request: {}\n", "note", s.cannot_express);
  path_text(out, s);
  key_text(out, s);
  direction_text(out, "O->T", "T->O", s.ot);
  direction_text(out, "T->O", "O->T", s.to);
  if (s.config_instance != 0)
    out += fmt::format("  {:<13} instance {}, {} bytes: {}\n", "configuration", s.config_instance, s.config_data.size(),
                       s.config_data.empty() ? "none" : wrapped_hex(s.config_data, 16));
  if (s.config_instance != 0) config_text(out, s);
  if (!s.request.empty())
    out += fmt::format("  {:<13} {}, {} bytes:\n{}{}\n", "request",
                       s.large ? "Large_Forward_Open (a size over 511 bytes)" : "Forward_Open (no size over 511 bytes)",
                       s.request.size(), std::string(16, ' '), wrapped_hex(s.request, 16));
}

}  // namespace

std::string hex_bytes(const cip::bytes& b) {
  std::string out;
  for (const auto x : b) out += fmt::format("{}{:02X}", out.empty() ? "" : " ", x);
  return out;
}

std::string interval_words(std::uint32_t us) {
  if (us >= 1000 && us % 1000 == 0) return fmt::format("{} ms", us / 1000);
  if (us >= 1000 && us % 100 == 0) return fmt::format("{}.{} ms", us / 1000, (us % 1000) / 100);
  return fmt::format("{} µs", us);
}

std::string render_connections_text(const std::vector<connection_setting>& all, const source_file& src) {
  std::string out;
  for (const auto& s : all) {
    if (!out.empty()) out += "\n";
    one_text(out, s, src);
  }
  return out;
}

}  // namespace edsc::emit
