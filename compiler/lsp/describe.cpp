#include "lsp/describe.hpp"

#include <fmt/format.h>

#include "base/plural.hpp"
#include "connections/settings.hpp"
#include "connections/summary.hpp"
#include "model/decode.hpp"
#include "schema/cip_types.hpp"

namespace edsc::lsp {

namespace {

bool has(std::uint64_t v, unsigned b) { return ((v >> b) & 1u) != 0; }

// Appends `w` to a comma-separated list when `on`.
void add(std::string& s, bool on, std::string_view w) {
  if (on) s += s.empty() ? std::string(w) : fmt::format(", {}", w);
}

std::string_view class_words(schema::type_class c) {
  using schema::type_class;
  switch (c) {
    case type_class::signed_int: return "signed integer";
    case type_class::unsigned_int: return "unsigned integer";
    case type_class::bit_string: return "bit string";
    case type_class::real: return "floating point";
    case type_class::string: return "string";
    case type_class::epath: return "EPATH";
    case type_class::stringi: return "international string";
    case type_class::other: return "time";
  }
  return "";
}

std::string direction(std::string_view name, const model::direction_params& d) {
  std::string types, prios;
  add(types, d.type_null, "null");
  add(types, d.type_multicast, "multicast");
  add(types, d.type_p2p, "point-to-point");
  add(types, d.type_reserved, "reserved type");
  add(prios, d.prio_low, "low");
  add(prios, d.prio_high, "high");
  add(prios, d.prio_scheduled, "scheduled");
  add(prios, d.prio_reserved, "reserved priority");
  std::string sizes;
  add(sizes, d.fixed, "fixed");
  add(sizes, d.variable, "variable");
  return fmt::format("- {}: {} size; {}; {}; priority {}\n", name, sizes.empty() ? "no" : sizes,
                     connections::format_words(d.real_time_format), types.empty() ? "no connection type" : types,
                     prios.empty() ? "none" : prios);
}

}  // namespace

std::string other_bits(std::uint64_t v, std::uint64_t known) {
  std::string out;
  for (unsigned b = 0; b < 64; ++b)
    if (has(v & ~known, b)) out += fmt::format("{}{}", out.empty() ? "" : ", ", b);
  return out.empty() ? out : "bits " + out;
}

namespace {

// One line per set bit of `names`, then any bit beyond them.
template <std::size_t N>
std::string bit_lines(std::uint64_t v, const std::string_view (&names)[N], std::string_view others_note,
                      std::string_view none) {
  std::string out;
  for (unsigned b = 0; b < N; ++b)
    if (has(v, b)) out += fmt::format("- {}\n", names[b]);
  if (const auto o = other_bits(v, (std::uint64_t{1} << N) - 1); !o.empty())
    out += fmt::format("- also {}{}\n", o, others_note);
  return out.empty() ? std::string(none) : out;
}

}  // namespace

std::string describe_param_descriptor(std::uint64_t v) {
  static constexpr std::string_view names[] = {"settable path (bit 0)",
                                               "enumerated strings (bit 1)",
                                               "scaling (bit 2)",
                                               "scaling links (bit 3)",
                                               "read only (bit 4)",
                                               "monitor: read often (bit 5)",
                                               "extended precision scaling (bit 6)"};
  return bit_lines(v, names, " (not standard)", "- no bits set: settable, not enumerated, no scaling\n");
}

std::string describe_io_mask(std::uint64_t v) {
  static constexpr std::string_view names[] = {"poll (bit 0)", "bit-strobe (bit 1)", "change of state (bit 2)",
                                               "cyclic (bit 3)", "multicast poll (bit 4, unconfirmed)"};
  return bit_lines(v, names, "", "- no connection type\n");
}

std::string describe_trigger(std::uint32_t v) {
  const auto t = model::decode_trigger(v);
  std::string classes;
  for (unsigned c = 0; c < 16; ++c)
    if (has(t.transport_classes, c)) classes += fmt::format("{}{}", classes.empty() ? "" : ", ", c);
  std::string triggers;
  add(triggers, t.trigger_cyclic, "cyclic");
  add(triggers, t.trigger_cos, "change of state");
  add(triggers, t.trigger_application, "application");
  std::string app;
  add(app, t.listen_only, "listen-only");
  add(app, t.input_only, "input-only");
  add(app, t.exclusive_owner, "exclusive owner");
  add(app, t.redundant_owner, "redundant owner");
  std::string out = fmt::format("- transport class {} (bits 0-15)\n", classes.empty() ? "none" : classes);
  out += fmt::format("- trigger: {} (bits 16-18)\n", triggers.empty() ? "none" : triggers);
  out += fmt::format("- application type: {} (bits 24-27)\n", app.empty() ? "none" : app);
  out += fmt::format("- direction: {} (bit 31)\n", t.server ? "server" : "client");
  if (t.reserved) out += fmt::format("- reserved {} set\n", other_bits(t.reserved, 0));
  return out;
}

std::string describe_connection_params(std::uint32_t v) {
  const auto p = model::decode_params(v);
  std::string out = direction("O→T", p.ot) + direction("T→O", p.to);
  if (p.reserved) out += fmt::format("- reserved {} set\n", other_bits(p.reserved, 0));
  return out;
}

std::string describe_type_code(std::uint64_t code) {
  bool legacy = false;
  const auto* t = schema::resolve_param_type(code, &legacy);
  if (!t) return fmt::format("unknown data type code 0x{:02X}", code);
  std::string size = t->size ? fmt::format(", {}", bytes_and_bits(t->size)) : ", variable length";
  std::string out = fmt::format("**{}** (0x{:02X}: {}{})", t->name, t->code, class_words(t->cls), size);
  if (legacy) out += fmt::format(" — legacy DeviceNet code {}", code);
  return out;
}

std::string bytes_and_bits(std::uint64_t bytes) {
  return fmt::format("{} ({} bits)", plural(bytes, "byte"), bytes * 8);
}

std::string bits_and_bytes(std::uint64_t bits) {
  if (bits < 8) return plural(bits, "bit");
  if (bits % 8 == 0) return fmt::format("{} bits ({})", bits, plural(bits / 8, "byte"));
  return fmt::format("{} ({} and {})", plural(bits, "bit"), plural(bits / 8, "byte"), plural(bits % 8, "bit"));
}

std::string describe_epath(const model::epath& p, const model::device& dev) {
  using model::segment_kind;
  if (p.symbolic) return "- a symbolic path: the tool asks for a tag name\n";
  std::string out;
  for (const auto& s : p.segments) {
    std::string value = s.has_param              ? fmt::format("[{}{}]", schema::stem_of(s.param.kind), s.param.number)
                        : !s.placeholder.empty() ? fmt::format("`{}` (filled in by the tool)", s.placeholder)
                                                 : fmt::format("{} (0x{:X})", s.value, s.value);
    if (s.has_param)
      if (const auto* prm = s.param.resolved() ? &dev.params[s.param.target] : nullptr; prm && prm->name.ok())
        value += fmt::format(" \"{}\"", prm->name.text);
    switch (s.kind) {
      case segment_kind::port: out += fmt::format("- port {}, link address {}\n", value, s.link_address); break;
      case segment_kind::class_id: out += fmt::format("- class {}\n", value); break;
      case segment_kind::instance: out += fmt::format("- instance {}\n", value); break;
      case segment_kind::member: out += fmt::format("- member {}\n", value); break;
      case segment_kind::connection_point: out += fmt::format("- connection point {}\n", value); break;
      case segment_kind::attribute: out += fmt::format("- attribute {}\n", value); break;
      case segment_kind::symbol: out += fmt::format("- symbol \"{}\"\n", s.symbol); break;
      case segment_kind::param: out += fmt::format("- {} (a segment chosen by the parameter)\n", value); break;
      case segment_kind::placeholder:
        out += fmt::format("- `{}`: a placeholder the configuration tool fills in when it connects\n", s.placeholder);
        break;
      case segment_kind::unknown: out += "- bytes edsc does not decode\n"; break;
    }
  }
  if (!p.complete) out += "- **incomplete**: the bytes end inside a segment\n";
  out += fmt::format("\n{}{}\n", plural(p.byte_count, "byte"), p.packed ? ", 16/32-bit values without pad bytes" : "");
  return out;
}

std::string entry_name(const cst::tree& t, const cst::entry& e, const schema::keyword_desc* k) {
  if (!k) return {};
  for (std::uint32_t i = 0; i < k->fields.size() && i < e.fields_count; ++i) {
    if (k->fields[i].name != "name" || k->fields[i].type != schema::value_type::string) continue;
    return string_text(t, t.field_of(e, i));
  }
  return {};
}

std::string string_text(const cst::tree& t, const cst::field& f) {
  if (f.kind != cst::field_kind::string) return {};
  std::string out;
  for (std::uint32_t p = 0; p < f.pieces_count(); ++p) {
    bool wide = false;
    out += model::decode::piece_body(t.text(t.piece_of(f, p)), wide);
  }
  return out;
}

namespace {

std::string direction_item(std::string_view name, const connections::direction_summary& d) {
  std::string out = fmt::format("- {}: {}", name, d.size);
  for (const auto* part : {&d.point, &d.types, &d.rpi})
    if (!part->empty()) out += "; " + *part;
  return out + "\n";
}

}  // namespace

std::string describe_connection(const model::device& dev, const model::connection& c) {
  if (!c.decoded) return {};  // the fields say nothing a scanner could use; their own hovers say why
  for (const auto& s : connections::describe_connections(dev)) {
    if (s.number != c.number || s.at.begin != c.from.where.begin) continue;
    const auto w = connections::summarize(s);
    std::string out = fmt::format("- kind: {}\n- transport: {}\n", w.kind, w.transport);
    if (!w.owner_label.empty()) out += fmt::format("- {}: {}\n", w.owner_label, w.owners);
    out += direction_item("O→T", w.ot) + direction_item("T→O", w.to);
    if (!w.configuration.empty()) out += fmt::format("- configuration: {}\n", w.configuration);
    if (!w.note.empty()) out += fmt::format("- no request: {}\n", w.note);
    return out;
  }
  return {};
}

std::string param_line(const model::device& dev, const model::param& p) {
  std::string out = p.name.ok() ? fmt::format("\"{}\"", p.name.text) : std::string("(no name)");
  if (p.type) out += fmt::format(" {}", p.type->name);
  auto raw = [&](const model::value& v) { return v.present() ? std::string(dev.raw(v)) : std::string(); };
  if (p.min.present() || p.max.present()) out += fmt::format(", {}..{}", raw(p.min), raw(p.max));
  if (p.default_value.present()) out += fmt::format(", default {}", raw(p.default_value));
  if (p.units.ok() && !p.units.text.empty()) out += fmt::format(" {}", p.units.text);
  return out;
}

}  // namespace edsc::lsp
