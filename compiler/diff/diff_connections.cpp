// EtherNet/IP connections ([Connection Manager] ConnectionN): what an
// originator configured with the old file asks for, against what the new
// file offers: triggers and transports, sizes, assembly instances, formats.
#include <fmt/format.h>

#include "diff/context.hpp"
#include "facts/header_parts.hpp"

namespace edsc::diff::detail {

namespace {

using model::connection;

std::string label(const connection& c) {
  const auto name = text_of(c.name);
  return name.empty() ? fmt::format("Connection{}", c.number)
                      : fmt::format("Connection{} \"{}\"", c.number, brief(name, 40));
}

// Bits set in `x` and clear in `y`, and the other way round.
struct bit_change {
  std::uint64_t lost = 0, gained = 0;
};
bit_change bits(const value& u, const value& v) {
  const auto x = u.is_integer() ? u.as_uint() : 0, y = v.is_integer() ? v.as_uint() : 0;
  return {x & ~y, y & ~x};
}

void compare_pair(context& c, const connection& p, const connection& q, const emit::eip_connection_facts& f0,
                  const emit::eip_connection_facts& f1) {
  const auto subject = "[Connection Manager] " + label(q);
  auto add = [&](impact i, const char* kind, std::string message, std::string why, const value& u, const value& v) {
    auto& d = c.add(group::connections, i, kind, subject, std::move(message), std::move(why));
    d.before = at(c.a, u);
    d.after = at(c.b, v);
  };
  for (const auto& [u, v, what] : {std::tuple{&p.trigger, &q.trigger, "trigger and transport"},
                                   std::tuple{&p.params, &q.params, "connection parameters"}}) {
    if (same(c.a, *u, c.b, *v)) continue;
    const auto ch = bits(*u, *v);
    const bool format_changed =
        u == &p.params && p.decoded && q.decoded &&
        (p.cp.ot.real_time_format != q.cp.ot.real_time_format || p.cp.to.real_time_format != q.cp.to.real_time_format);
    const bool lost = ch.lost != 0 || format_changed || !u->is_integer() || !v->is_integer();
    add(lost ? impact::breaking : impact::additive, u == &p.trigger ? "connection-trigger" : "connection-params",
        fmt::format("{} {} -> {}", what, shown(c.a, *u), shown(c.b, *v)),
        lost ? (format_changed ? std::string("the real-time format (run/idle header, heartbeat) changed: an originator "
                                             "configured with the old file frames the data differently and is refused")
                               : fmt::format("options a configured originator may use were withdrawn (bits 0x{:X}): "
                                             "its connection request can be refused",
                                             ch.lost))
             : fmt::format("new options (bits 0x{:X}); what was configured is still offered", ch.gained),
        *u, *v);
  }
  struct sized {
    std::uint32_t a, b;
    const char* what;
    const value *u, *v;
  };
  for (const auto& s :
       {sized{f0.output_size, f1.output_size, "O->T size", &p.ot_size, &q.ot_size},
        sized{f0.input_size, f1.input_size, "T->O size", &p.to_size, &q.to_size},
        sized{f0.config_size, f1.config_size, "configuration size", &p.target_config_size, &q.target_config_size}}) {
    if (s.a == s.b) continue;
    add(impact::breaking, "connection-size", fmt::format("{} {} -> {} bytes", s.what, s.a, s.b),
        "an originator configured with the old size is refused (invalid connection size), and data mapped after "
        "this device in its tags moves",
        *s.u, *s.v);
  }
  for (const auto& s : {sized{f0.output_instance, f1.output_instance, "O->T assembly instance", &p.path, &q.path},
                        sized{f0.input_instance, f1.input_instance, "T->O assembly instance", &p.path, &q.path},
                        sized{f0.config_instance, f1.config_instance, "configuration instance", &p.path, &q.path}}) {
    if (s.a == s.b) continue;
    add(impact::breaking, "connection-instance", fmt::format("{} {} -> {}", s.what, s.a, s.b),
        "an originator configured with the old file connects to another assembly", *s.u, *s.v);
  }
  const bool instances_same = f0.output_instance == f1.output_instance && f0.input_instance == f1.input_instance &&
                              f0.config_instance == f1.config_instance;
  auto field = [&](const value& u, const value& v, impact i, const char* kind, const char* what, const char* why) {
    c.field(group::connections, subject, u, v, i, kind, what, why);
  };
  if (instances_same)
    field(p.path, q.path, impact::breaking, "connection-path", "path",
          "an originator configured with the old path asks for something the device may no longer serve");
  field(p.ot_rpi, q.ot_rpi, impact::cosmetic, "connection-rpi", "O->T RPI",
        "the interval a tool proposes; configured intervals stay");
  field(p.to_rpi, q.to_rpi, impact::cosmetic, "connection-rpi", "T->O RPI",
        "the interval a tool proposes; configured intervals stay");
  field(p.name, q.name, impact::cosmetic, "connection-name", "name", "tools show the new name");
  field(p.help, q.help, impact::cosmetic, "connection-help", "help text", "documentation only");
  for (const auto slot : {&connection::ot_format, &connection::to_format, &connection::proxy_config_size,
                          &connection::proxy_config_format, &connection::target_config_format,
                          &connection::safety_async, &connection::safety_max_consumers})
    field(p.*slot, q.*slot, impact::cosmetic, "connection-field", "field",
          "sizes and instances are unchanged; the data layout itself is compared under I/O");
}

const connection* find(const device& d, std::uint32_t number) {
  for (const auto& x : d.connections)
    if (x.number == number) return &x;
  return nullptr;
}

const emit::eip_connection_facts* facts(const std::vector<emit::eip_connection_facts>& fs, std::uint32_t number) {
  for (const auto& f : fs)
    if (f.number == number) return &f;
  return nullptr;
}

}  // namespace

void compare_connections(context& c) {
  std::vector<emit::header_issue> ignored;  // the checker reports these; a diff compares what is there
  const auto fa = emit::collect_connections(c.a, ignored);
  const auto fb = emit::collect_connections(c.b, ignored);
  for (const auto& p : c.a.connections) {
    c.cover(p.from, {});
    const auto* q = find(c.b, p.number);
    if (q == nullptr) {
      auto& d = c.add(group::connections, impact::breaking, "connection-removed", "[Connection Manager] " + label(p),
                      "removed", "an originator configured with this connection can no longer open it");
      d.before = at(p.from, label(p));
      continue;
    }
    if (&p != find(c.a, p.number)) continue;  // a repeated number: the first one counts
    const auto* f0 = facts(fa, p.number);
    const auto* f1 = facts(fb, p.number);
    if (f0 && f1) compare_pair(c, p, *q, *f0, *f1);
  }
  for (const auto& q : c.b.connections) {
    c.cover({}, q.from);
    if (find(c.a, q.number)) continue;
    auto& d = c.add(group::connections, impact::additive, "connection-added", "[Connection Manager] " + label(q),
                    "added", "a new connection an originator may choose; configured ones are unchanged");
    d.after = at(q.from, label(q));
  }
}

}  // namespace edsc::diff::detail
