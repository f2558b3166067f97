// The words of one connection's settings, shared by `edsc connection`, the
// datasheet and the hover (summary.hpp).
#include "connections/summary.hpp"

#include <fmt/format.h>

#include "base/plural.hpp"

namespace edsc::connections {

namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

template <class T, class F>
std::string words_of(const std::vector<T>& xs, F&& word) {
  std::vector<std::string> w;
  for (const auto& x : xs) w.emplace_back(word(x));
  return w.empty() ? "none" : joined(w);
}

std::string size_words(const direction_setting& d) {
  if (!d.used) return "none (null connection)";
  std::string s = fmt::format("{} data", d.data_size);
  if (d.sequence) s += " + 2 sequence";
  if (d.run_idle) s += " + 4 run/idle";
  s += fmt::format(" = {}, {}", plural(d.asked.size, "byte"), d.asked.variable ? "variable" : "fixed");
  if (d.fixed && d.variable) s += " (fixed or variable offered)";
  return s;
}

direction_summary direction_of(const direction_setting& d, std::string_view other) {
  direction_summary out;
  out.size = size_words(d);
  if (!d.used) return out;
  out.point = fmt::format("instance {}, {}", d.instance, format_words(d.format));
  out.types = fmt::format("{} (offered: {}), {} priority (offered: {})", type_words(d.asked.type),
                          words_of(d.types, type_words), priority_words(d.asked.priority),
                          words_of(d.priorities, priority_words));
  out.rpi = rpi_words(d.rpi, other);
  return out;
}

void owners_of(const connection_setting& s, connection_summary& out) {
  if (s.kind.type == model::app_type::exclusive_owner) return;
  std::vector<std::string> names;
  for (const auto n : s.owners) names.push_back(fmt::format("Connection{}", n));
  if (s.kind.type == model::app_type::listen_only) {
    out.owner_label = "needs";
    out.owners = names.empty()
                     ? fmt::format("none in this EDS produces input point {}", s.to.instance)
                     : fmt::format("one of {} open first (same input point {})", joined(names), s.to.instance);
  } else if (!names.empty()) {
    out.owner_label = "shares";
    out.owners = fmt::format("input point {} with {}", s.to.instance, joined(names));
  }
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

std::string range_words(std::uint32_t min_us, std::uint32_t max_us) {
  const auto lo = interval_words(min_us), hi = interval_words(max_us);
  const auto unit = [](const std::string& w) { return w.substr(w.rfind(' ')); };
  if (unit(lo) == unit(hi)) return fmt::format("{}–{}", lo.substr(0, lo.rfind(' ')), hi);
  return fmt::format("{}–{}", lo, hi);
}

std::string rpi_words(const rpi_setting& r, std::string_view other) {
  const auto asked = interval_words(r.asked_us);
  switch (r.source) {
    case rpi_source::number: return fmt::format("RPI {} (the EDS gives {} µs)", asked, r.asked_us);
    case rpi_source::param: {
      if (r.min_us && r.max_us)
        return fmt::format("RPI {}, default {} (Param{})", range_words(*r.min_us, *r.max_us), asked, r.param);
      if (r.min_us)
        return fmt::format("RPI at least {}, default {} (Param{})", interval_words(*r.min_us), asked, r.param);
      if (r.max_us)
        return fmt::format("RPI at most {}, default {} (Param{})", interval_words(*r.max_us), asked, r.param);
      return fmt::format("RPI {} (Param{}'s default; no limits given)", asked, r.param);
    }
    case rpi_source::other: return fmt::format("RPI {} (field empty: the {} RPI)", asked, other);
    case rpi_source::not_given: return fmt::format("RPI {} (the EDS gives none: edsc's default)", asked);
  }
  return "RPI " + asked;
}

std::string config_field_lines(const connection_setting& s, std::size_t indent) {
  std::string out;
  for (const auto& f : s.config_fields) {
    const auto& d = f.field;
    const auto bits = d.bits == 1 ? fmt::format("bit {}", d.bit) : fmt::format("bits {}-{}", d.bit, d.bit + d.bits - 1);
    out += fmt::format("{}Param{}{} = {}{} ({}){}\n", std::string(indent, ' '), d.param,
                       d.name.empty() ? "" : fmt::format(" \"{}\"", d.name), number_text(f.value),
                       f.enum_text.empty() ? "" : fmt::format(" \"{}\"", f.enum_text), bits,
                       f.set ? ", set by --set" : "");
  }
  return out;
}

connection_summary summarize(const connection_setting& s) {
  connection_summary out;
  out.kind = fmt::format("{}{}{}", kind_words(s.kind), s.kind.configured ? ", with configuration" : "",
                         s.redundant_owner ? "; redundant owner offered" : "");
  std::vector<std::string> classes;
  for (const auto c : s.classes) classes.push_back(fmt::format("{}", c));
  out.transport = fmt::format("class {}, {} (offered: {})", classes.empty() ? "none" : joined(classes), s.trigger_asked,
                              s.triggers.empty() ? "none" : joined(s.triggers));
  owners_of(s, out);
  out.ot = direction_of(s.ot, "T->O");
  out.to = direction_of(s.to, "O->T");
  if (s.config_instance != 0)
    out.configuration = fmt::format("instance {}, {}", s.config_instance, plural(s.config_data.size(), "byte"));
  out.note = s.cannot_express;
  return out;
}

}  // namespace edsc::connections
