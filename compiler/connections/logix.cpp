// The Generic Ethernet Module rows of one connection (logix.hpp). The
// dialog's fields are assembly instance numbers and sizes in the comm
// format's unit: a connection whose path holds anything else, or whose size
// is not a whole number of that unit, cannot be typed into it. Everything
// else the dialog is reported to do has no public source here and is only
// warned about, marked UNCONFIRMED (docs/connection.md lists each).
#include "connections/logix.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

namespace edsc::connections {

namespace {

// Sizes the dialog is commonly reported to take at most, in bytes (UNCONFIRMED).
constexpr std::uint32_t input_limit = 500, output_limit = 496, configuration_limit = 400;

bool fits(std::uint32_t bytes, logix_type t) { return bytes % unit_bytes(t) == 0; }

// Why the path is not three assembly instance numbers; empty when it is.
std::string path_refusal(const connection_setting& s) {
  for (const auto& p : s.path) {
    switch (p.kind) {
      case model::segment_kind::class_id:
        if (p.value && *p.value == 0x04) continue;
        return p.value ? fmt::format(
                             "its path names class 0x{:02X}; the dialog's instances are Assembly (class "
                             "0x04) instances",
                             *p.value)
                       : std::string("its path names a class the dialog cannot be given");
      case model::segment_kind::instance:
      case model::segment_kind::connection_point:
        if (p.role != path_role::none) continue;
        return "its path names more instances than the dialog's configuration, output and input rows";
      default:
        return fmt::format("its path has a {} segment; the dialog takes assembly instance numbers only",
                           segment_words(p.kind));
    }
  }
  return {};
}

std::string units_words(std::uint32_t bytes, logix_type t) {
  return fmt::format("{} bytes are not a whole number of {}s ({} bytes each)", bytes, type_name(t), unit_bytes(t));
}

// The chosen type, or why the sizes do not fit the one asked for.
std::string choose_type(const connection_setting& s, std::optional<logix_type> asked, logix_module& m) {
  const auto in = s.to.used ? s.to.data_size : 0u, out = s.ot.used ? s.ot.data_size : 0u;
  if (!asked) {
    for (const auto t : {logix_type::dint, logix_type::int16, logix_type::sint})
      if (fits(in, t) && fits(out, t)) {
        m.type = t;
        return {};
      }
  }
  m.type = *asked;
  if (!fits(in, m.type)) return "the input's " + units_words(in, m.type);
  if (!fits(out, m.type)) return "the output's " + units_words(out, m.type);
  return {};
}

logix_unicast unicast_of(const direction_setting& to) {
  const auto offers = [&](cip::conn_type t) {
    return std::find(to.types.begin(), to.types.end(), t) != to.types.end();
  };
  const bool p2p = offers(cip::conn_type::point_to_point), multi = offers(cip::conn_type::multicast);
  return p2p && !multi ? logix_unicast::yes : multi && !p2p ? logix_unicast::no : logix_unicast::either;
}

void note_limit(logix_module& m, std::string_view row, std::uint32_t bytes, std::uint32_t limit) {
  if (bytes > limit)
    m.unconfirmed.push_back(
        fmt::format("the {} has {} bytes, more than the {} bytes the dialog is reported to take "
                    "(UNCONFIRMED)",
                    row, bytes, limit));
}

void note_habits(const connection_setting& s, logix_module& m) {
  note_limit(m, "input", m.input.bytes, input_limit);
  note_limit(m, "output", m.output.bytes, output_limit);
  note_limit(m, "configuration", m.configuration.bytes, configuration_limit);
  if (std::find(s.triggers.begin(), s.triggers.end(), "cyclic") == s.triggers.end())
    m.unconfirmed.emplace_back(
        "the dialog is reported to open cyclic connections only; this one offers no cyclic "
        "trigger (UNCONFIRMED)");
  if (!m.input_only && s.ot.used && s.ot.data_size > 0 && !s.ot.run_idle)
    m.unconfirmed.emplace_back(
        "the Data formats are reported to send the 32-bit run/idle header in O->T data; this "
        "connection's O->T data has none, so the device may refuse the size (UNCONFIRMED)");
  if (s.to.used && s.to.run_idle)
    m.unconfirmed.emplace_back(
        "the T->O data has a 32-bit run/idle header; the dialog's formats are reported to "
        "expect none (UNCONFIRMED)");
  if (!s.to.used)
    m.unconfirmed.emplace_back(
        "the connection has no input (T->O null); the dialog's formats are reported to open "
        "one (UNCONFIRMED)");
  for (const auto* d : {&s.ot, &s.to})
    if (d->used && d->variable && !d->fixed)
      m.unconfirmed.emplace_back(
          "a direction offers a variable size only; the dialog is reported to ask a fixed "
          "size (UNCONFIRMED)");
}

}  // namespace

unsigned unit_bytes(logix_type t) {
  switch (t) {
    case logix_type::sint: return 1;
    case logix_type::int16: return 2;
    case logix_type::dint:
    case logix_type::real: return 4;
  }
  return 1;
}

std::string_view type_name(logix_type t) {
  switch (t) {
    case logix_type::sint: return "SINT";
    case logix_type::int16: return "INT";
    case logix_type::dint: return "DINT";
    case logix_type::real: return "REAL";
  }
  return "SINT";
}

logix_module logix_settings(const connection_setting& s, std::optional<logix_type> asked) {
  logix_module m;
  if (s.request.empty()) {
    m.refusal = s.cannot_express;
    return m;
  }
  m.refusal = path_refusal(s);
  if (m.refusal.empty()) m.refusal = choose_type(s, asked, m);
  if (!m.refusal.empty()) return m;
  m.input_only = s.kind.type != model::app_type::exclusive_owner;
  const auto unit = unit_bytes(m.type);
  if (s.to.used) m.input = {s.to.instance, s.to.data_size / unit, s.to.data_size};
  if (s.ot.used) m.output = {s.ot.instance, m.input_only ? 0 : s.ot.data_size / unit, s.ot.data_size};
  if (s.config_instance != 0)
    m.configuration = {s.config_instance, static_cast<std::uint32_t>(s.config_data.size()),
                       static_cast<std::uint32_t>(s.config_data.size())};
  // "- Run/Idle" follows the O->T format the EDS names (4), even where no
  // data follows and edsc's own request carries no header (plan.cpp).
  m.comm_format = fmt::format("{}Data - {}{}", m.input_only ? "Input " : "", type_name(m.type),
                              m.input_only && s.ot.format == 4 ? " - Run/Idle" : "");
  m.unicast = unicast_of(s.to);
  note_habits(s, m);
  return m;
}

}  // namespace edsc::connections
