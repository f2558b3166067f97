// Connections on the datasheet: DeviceNet [IO_Info] per predefined connection
// type and data set, EtherNet/IP ConnectionN with its bit fields in words, and
// the ProxyConnectN / ProxiedConnectN entries apart.
// A ConnectionN is shown as `edsc connection` shows it, from the same
// settings and the same words (connections/summary.hpp), so the page, the
// command and the C header never disagree.
#include <algorithm>

#include <fmt/format.h>

#include "connections/settings.hpp"
#include "connections/summary.hpp"
#include "doc/sheet_parts.hpp"
#include "facts/header_view.hpp"

namespace edsc::doc::detail {

namespace {

using model::value;

constexpr const char* io_type_names[] = {"Poll", "Bit-strobe", "Change of state", "Cyclic"};

std::string io_mask_text(std::uint64_t mask) {
  static constexpr const char* names[] = {"poll", "strobe", "COS", "cyclic", "multicast poll"};
  std::string out;
  for (int b = 0; b < 5; ++b)
    if ((mask & (1u << b)) != 0) join(out, ", ", std::string(names[b]));
  return out.empty() ? "none" : out;
}

std::string bytes_text(std::uint64_t n) { return fmt::format("{} byte{}", n, n == 1 ? "" : "s"); }

// "Input1 (Sensor), 3 bytes" for a default input/output reference.
std::string data_ref_text(const reader& r, const model::io_info& io, const value& v, bool output) {
  const auto* ref = v.as_ref();
  if (ref == nullptr) return v.is_integer() && v.as_uint() == 0 ? "none" : r.text(v);
  const auto label = fmt::format("{}{}", output ? "Output" : "Input", ref->number);
  const auto& list = output ? io.outputs : io.inputs;
  if (!ref->resolved() || ref->target >= list.size()) return label + " (missing)";
  const auto& d = list[ref->target];
  const auto name = r.text(d.name);
  return fmt::format("{}{}, {}", label, name.empty() ? "" : " \"" + name + "\"",
                     d.size.is_integer() ? bytes_text(d.size.as_uint()) : "size unknown");
}

void devicenet_rows(const reader& r, const emit::devicenet_facts& dn, sheet& s) {
  const auto& io = r.dev.io;
  auto& t = s.devicenet_io;
  t.head = {"Connection type", "Supported", "Default", "Produces (input)", "Consumes (output)", "Compatible with"};
  for (std::size_t i = 0; i < dn.types.size(); ++i) {
    const model::io_connection_info* info = nullptr;
    for (const auto& c : io.connections)
      if (static_cast<std::size_t>(c.type) == i && info == nullptr) info = &c;
    const bool in_default = io.default_mask.is_integer() && (io.default_mask.as_uint() & (1u << i)) != 0;
    std::vector<cell> row{{io_type_names[i], info != nullptr ? r.line(info->from) : 0},
                          {dn.types[i].supported ? "yes" : "no", 0, cell_style::flags},
                          {in_default ? "yes" : "", r.line(io.default_mask.from), cell_style::flags}};
    if (info != nullptr) {
      row.push_back({data_ref_text(r, io, info->default_input, false)});
      row.push_back({data_ref_text(r, io, info->default_output, true)});
      row.push_back({info->mask.is_integer() ? io_mask_text(info->mask.as_uint()) : r.text(info->mask)});
    } else {
      row.insert(row.end(), 3, cell{"", 0, cell_style::muted});
    }
    t.rows.push_back(std::move(row));
  }
}

void io_data_rows(const reader& r, const model::io_info& io, const char* prefix, sheet& s) {
  auto& t = s.io_data;
  t.head = {"Data", "Name", "Size", "Significant bits", "Connection types", "Path", "Help"};
  for (const auto* list : {&io.inputs, &io.outputs}) {
    for (const auto& d : *list) {
      const auto sig = d.significant_bits.is_integer() && d.significant_bits.as_uint() == 0
                           ? std::string("all")
                           : r.text(d.significant_bits);
      t.rows.push_back(
          {{fmt::format("{}{}{}", prefix, d.output ? "Output" : "Input", d.number), r.line(d.from), cell_style::code},
           r.at(d.name),
           {d.size.is_integer() ? bytes_text(d.size.as_uint()) : r.text(d.size), r.line(d.size.from),
            cell_style::number},
           {sig, r.line(d.significant_bits.from), cell_style::number},
           {d.mask.is_integer() ? io_mask_text(d.mask.as_uint()) : r.text(d.mask), r.line(d.mask.from)},
           {r.path_text(d.path), r.line(d.path.from)},
           r.at(d.help)});
    }
  }
}

std::string trigger_text(const model::trigger_transport& t) {
  std::string classes;
  for (int c = 0; c < 16; ++c)
    if ((t.transport_classes & (1u << c)) != 0) join(classes, ", ", std::to_string(c));
  std::vector<std::string> parts;
  parts.push_back(classes.empty() ? "no transport class" : "class " + classes);
  std::string trig;
  for (auto [on, name] : {std::pair{t.trigger_cyclic, "cyclic"}, std::pair{t.trigger_cos, "change of state"},
                          std::pair{t.trigger_application, "application"}})
    if (on) join(trig, ", ", std::string(name));
  if (!trig.empty()) parts.push_back(trig);
  for (auto [on, name] : {std::pair{t.exclusive_owner, "exclusive owner"}, std::pair{t.input_only, "input only"},
                          std::pair{t.listen_only, "listen only"}, std::pair{t.redundant_owner, "redundant owner"}})
    if (on) parts.push_back(name);
  if (t.server) parts.push_back("server");
  std::string out;
  for (const auto& p : parts) join(out, "\n", p);
  return out;
}

std::string direction_text(const model::direction_params& d) {
  std::string out;
  auto add = [&](bool on, const char* word) {
    if (on) join(out, ", ", std::string(word));
  };
  add(d.type_p2p, "point-to-point");
  add(d.type_multicast, "multicast");
  add(d.type_null, "null");
  add(d.fixed, "fixed");
  add(d.variable, "variable");
  add(d.prio_scheduled, "scheduled");
  add(d.prio_high, "high priority");
  add(d.prio_low, "low priority");
  static constexpr const char* formats[] = {
      "modeless",   "zero-length", "format 2", "heartbeat", "32-bit run/idle header",
      "CIP Safety", "format 6",    "format 7"};
  add(true, formats[d.real_time_format & 7]);
  return out;
}

// One direction of a connection: `head` (size, assembly), what the format
// names, RPI, bits.
std::string flow_text(const reader& r, std::string head, const value& format, const value& rpi,
                      const model::direction_params* bits) {
  std::string out = std::move(head);
  if (const auto* ref = format.as_ref()) join(out, "\n", r.ref_text(*ref));
  if (const auto* ref = rpi.as_ref())
    join(out, "\n", "RPI " + r.ref_text(*ref));
  else if (rpi.present())
    join(out, "\n", fmt::format("RPI {} µs", r.text(rpi)));
  if (bits != nullptr) join(out, "\n", direction_text(*bits));
  return out;
}

// The columns of a ConnectionN-layout table; `first` names the entry column.
std::vector<std::string> connection_head(const char* first) {
  return {first,           "Name", "Trigger and transport", "O→T (to the device)", "T→O (from the device)",
          "Configuration", "Path"};
}

// One row of a ConnectionN-layout entry: `entry` is its keyword and number,
// `ot` and `to` the head of each direction (size, assembly), `config` the
// configuration cell.
std::vector<cell> connection_row(const reader& r, const model::connection& c, std::string entry, std::string ot,
                                 std::string to, std::string config) {
  return {{std::move(entry), r.line(c.from), cell_style::code},
          r.at(c.name),
          {c.decoded ? trigger_text(c.tt) : r.text(c.trigger), r.line(c.trigger.from)},
          {flow_text(r, std::move(ot), c.ot_format, c.ot_rpi, c.decoded ? &c.cp.ot : nullptr), r.line(c.ot_size.from)},
          {flow_text(r, std::move(to), c.to_format, c.to_rpi, c.decoded ? &c.cp.to : nullptr), r.line(c.to_size.from)},
          {std::move(config)},
          {r.path_text(c.path), r.line(c.path.from)}};
}

// A size field as written: no header fact stands behind it (a proxy entry,
// a ConnectionN whose bit fields are no numbers).
std::string size_text(const reader& r, const value& v) {
  if (v.is_integer()) return bytes_text(v.as_uint());
  if (const auto* ref = v.as_ref()) return r.ref_text(*ref);
  return r.text(v);
}

// A direction's lines as `edsc connection` prints them (connections/summary.hpp).
std::string direction_cell(const connections::direction_summary& d) {
  std::string out = d.size;
  for (const auto* line : {&d.point, &d.types, &d.rpi})
    if (!line->empty()) join(out, "\n", *line);
  return out;
}

// A ConnectionN as `edsc connection` reads it: kind, transport, owners,
// sizes with their header bytes, RPI range and default, instances and
// configuration, in the command's words.
std::vector<cell> setting_row(const reader& r, const model::connection& c, const connections::connection_setting& s) {
  const auto words = connections::summarize(s);
  std::string kind = words.kind;
  join(kind, "\n", words.transport);
  if (!words.owner_label.empty()) join(kind, "\n", words.owner_label + " " + words.owners);
  if (!words.note.empty()) join(kind, "\n", "no request: " + words.note);
  return {{fmt::format("Connection{}", c.number), r.line(c.from), cell_style::code},
          r.at(c.name),
          {std::move(kind), r.line(c.trigger.from)},
          {direction_cell(words.ot), r.line(c.ot_size.from)},
          {direction_cell(words.to), r.line(c.to_size.from)},
          {words.configuration},
          {r.path_text(c.path), r.line(c.path.from)}};
}

void eip_rows(const reader& r, sheet& s) {
  auto& t = s.connections;
  t.head = connection_head("Connection");
  const auto settings = connections::describe_connections(r.dev);
  for (const auto& c : r.dev.connections) {
    const auto it = std::find_if(settings.begin(), settings.end(), [&](const auto& x) {
      return x.number == c.number && x.at.begin == c.from.where.begin;
    });
    if (it == settings.end()) continue;  // a repeated number: the command's first one wins, and so does the page
    t.rows.push_back(c.decoded ? setting_row(r, c, *it)
                               : connection_row(r, c, fmt::format("Connection{}", c.number), size_text(r, c.ot_size),
                                                size_text(r, c.to_size), ""));
  }
}

// "proxy: 4 bytes\nParam3 (...)": one configuration pair, empty when not given.
std::string config_text(const reader& r, const char* which, const value& size, const value& format) {
  std::string out = size_text(r, size);
  if (const auto* ref = format.as_ref()) join(out, ", ", r.ref_text(*ref));
  return out.empty() ? out : fmt::format("{}: {}", which, out);
}

// ProxyConnectN / ProxiedConnectN: the ConnectionN columns, every value as the
// file writes it (the C header knows nothing of them, so no sizes are derived).
void proxy_rows(const reader& r, sheet& s) {
  auto& t = s.proxy_connections;
  t.head = connection_head("Entry");
  for (const auto& c : r.dev.proxy_connections) {
    const char* keyword = c.kind == model::connection_kind::proxy ? "ProxyConnect" : "ProxiedConnect";
    std::string config = config_text(r, "proxy", c.proxy_config_size, c.proxy_config_format);
    join(config, "\n", config_text(r, "target", c.target_config_size, c.target_config_format));
    t.rows.push_back(connection_row(r, c, fmt::format("{}{}", keyword, c.number), size_text(r, c.ot_size),
                                    size_text(r, c.to_size), std::move(config)));
  }
}

}  // namespace

void build_connections(const reader& r, sheet& s) {
  std::vector<emit::header_issue> ignored;  // the findings panel says it better
  const auto facts = emit::collect_facts(r.dev, r.src, ignored);
  if (facts.devicenet) devicenet_rows(r, *facts.devicenet, s);
  io_data_rows(r, r.dev.io, "", s);
  io_data_rows(r, r.dev.variant_io, "Variant ", s);
  if (!r.dev.connections.empty()) eip_rows(r, s);
  proxy_rows(r, s);
}

}  // namespace edsc::doc::detail
