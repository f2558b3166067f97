// [Connection Manager] ConnectionN (EDS_FORMAT.md §3.11, §5, §7 rules 29-35):
// the two bit masks, then how sizes, formats and the path agree with the
// assemblies they name. Rules 31-35 are heuristics from observed files.
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "check/context.hpp"
#include "schema/cip_types.hpp"

namespace edsc {

// Defined in rules_assembly.cpp and rules_port.cpp.
std::string assembly_name(const model::assembly& a);
std::optional<std::uint64_t> assembly_bytes(const model::assembly& a);
void check_assemblies(const check_context& ctx);
void check_ports_and_icon(const check_context& ctx);

namespace {

using schema::ref_kind;

bool kind_between(ref_kind k, ref_kind first, ref_kind last) {
  return static_cast<int>(k) >= static_cast<int>(first) && static_cast<int>(k) <= static_cast<int>(last);
}

const model::assembly* format_assembly(const check_context& ctx, const model::value& v) {
  const auto* r = v.as_ref();
  if (r == nullptr || !r->resolved() || !kind_between(r->kind, ref_kind::assem, ref_kind::proxied_assem_exa))
    return nullptr;
  return &ctx.dev.assemblies[r->target];
}

const model::param* param_ref(const check_context& ctx, const model::value& v) {
  const auto* r = v.as_ref();
  if (r == nullptr || !r->resolved() || !kind_between(r->kind, ref_kind::param, ref_kind::proxied_param))
    return nullptr;
  return &ctx.dev.params[r->target];
}

span assembly_size_at(const check_context& ctx, const model::assembly& a) {
  return a.size.present() ? ctx.where(a.size) : ctx.entry_keyword(a.from);
}

// One direction of a connection, with what its fields say.
struct direction {
  const char* name;  // "O->T" / "T->O"
  const model::direction_params& bits;
  const model::value& rpi;
  const model::value& size;
  const model::value& format;
  unsigned fixed_bit, type_bit;  // for messages
};

// Both directions of connection type NULL only: a NULL forward open, which
// pings or configures the target and moves no data (Rockwell "Ping"
// connections are written `0x00000000, 0x00110000`). It needs no transport
// class, application type or heartbeat.
bool null_connection(const model::connection& c) {
  const auto only_null = [](const model::direction_params& d) {
    return d.type_null && !d.type_multicast && !d.type_p2p;
  };
  return only_null(c.cp.ot) && only_null(c.cp.to);
}

void check_trigger(const check_context& ctx, const std::string& cn, const model::connection& c) {
  const auto& tt = c.tt;
  const auto raw = static_cast<std::uint32_t>(c.trigger.as_uint());
  if (tt.reserved != 0) {
    ctx.report(diag_id::connection_trigger_reserved, ctx.where(c.trigger),
               fmt::format("{} trigger/transport 0x{:08X} sets reserved bits 0x{:08X} (bits 19-23 and 28-30 must be 0)",
                           cn, raw, tt.reserved));
  }
  if (null_connection(c)) return;
  if (tt.transport_classes == 0) {
    ctx.report(diag_id::connection_no_transport_class, ctx.where(c.trigger),
               fmt::format("{} trigger/transport 0x{:08X} names no transport class (bits 0-15)", cn, raw));
  }
  const int app = int{tt.listen_only} + int{tt.input_only} + int{tt.exclusive_owner} + int{tt.redundant_owner};
  if (app != 1) {
    ctx.report(diag_id::connection_application_type, ctx.where(c.trigger),
               fmt::format("{} trigger/transport 0x{:08X} sets {} application types (bits 24-27); expected exactly "
                           "one of listen-only, input-only, exclusive owner, redundant owner",
                           cn, raw, app == 0 ? "no" : std::to_string(app)));
  }
}

void check_params_bits(const check_context& ctx, const std::string& cn, const model::connection& c) {
  const auto raw = static_cast<std::uint32_t>(c.params.as_uint());
  // Bits 4-7 (bytes per slot) are obsolete rather than reserved: not checked.
  constexpr std::uint32_t reserved = 0x88888800u;  // bits 11, 15, 19, 23, 27, 31
  if (raw & reserved) {
    ctx.report(diag_id::connection_params_reserved, ctx.where(c.params),
               fmt::format("{} connection parameters 0x{:08X} set reserved bits 0x{:08X} (bits 11, 15, 19, 23, 27, 31 "
                           "must be 0)",
                           cn, raw, raw & reserved));
  }
  for (const auto& [name, fmt_value] :
       {std::pair{"O->T", c.cp.ot.real_time_format}, std::pair{"T->O", c.cp.to.real_time_format}}) {
    if (fmt_value >= 6) {
      ctx.report(diag_id::connection_real_time_format, ctx.where(c.params),
                 fmt::format("{} {} real-time format is {}, which is undefined", cn, name, fmt_value));
    } else if (fmt_value == 1 || fmt_value == 2) {
      ctx.report(diag_id::connection_real_time_format_unverified, ctx.where(c.params),
                 fmt::format("{} {} real-time format is {}, whose meaning is unverified", cn, name, fmt_value));
    }
  }
}

bool has_data(const direction& d) {
  if (d.format.present()) return true;
  return d.size.present() && !(d.size.is_integer() && d.size.as_uint() == 0);
}

void check_direction_bits(const check_context& ctx, const std::string& cn, const model::connection& c,
                          const direction& d) {
  if (!has_data(d)) return;
  const bool size_kind = d.bits.fixed || d.bits.variable;
  const bool conn_type = d.bits.type_null || d.bits.type_multicast || d.bits.type_p2p;
  if (size_kind && conn_type) return;
  const auto missing = !size_kind && !conn_type ? "neither fixed/variable size nor a connection type"
                       : !size_kind             ? "neither fixed nor variable size"
                                                : "no connection type";
  ctx.report(
      diag_id::connection_direction_bits, ctx.where(c.params),
      fmt::format("{} carries {} data but its connection parameters 0x{:08X} allow {} for {} (bits {}-{}, {}-{})", cn,
                  d.name, c.params.as_uint(), missing, d.name, d.fixed_bit, d.fixed_bit + 1, d.type_bit,
                  d.type_bit + 2));
}

void check_rpi(const check_context& ctx, const std::string& cn, const direction& d) {
  const auto* p = param_ref(ctx, d.rpi);
  if (p == nullptr || p->type == nullptr || p->type->code == schema::code::UDINT) return;
  ctx.report_with_note(
      diag_id::connection_rpi_type, ctx.where(d.rpi),
      fmt::format("{} {} RPI names {}, a {}; RPIs are UDINT microseconds", cn, d.name, d.rpi.text, p->type->name),
      ctx.where(p->data_type), fmt::format("{} data type is given here", d.rpi.text));
}

void check_size(const check_context& ctx, const std::string& cn, const direction& d) {
  const auto* a = format_assembly(ctx, d.format);
  if (a == nullptr) return;
  const auto bytes = assembly_bytes(*a);
  if (!bytes) return;
  if (d.size.is_integer() && d.size.as_uint() != *bytes) {
    ctx.report_with_note(diag_id::connection_size_format, ctx.where(d.size),
                         fmt::format("{} {} size is {} but its format {} is {}", cn, d.name,
                                     plural(d.size.as_uint(), "byte"), assembly_name(*a), plural(*bytes, "byte")),
                         assembly_size_at(ctx, *a), fmt::format("{} size is given here", assembly_name(*a)));
    return;
  }
  const auto* p = param_ref(ctx, d.size);
  if (p == nullptr) return;
  const bool below = p->min.is_integer() && p->min.as_int() > static_cast<std::int64_t>(*bytes);
  const bool above = p->max.is_integer() && p->max.as_int() < static_cast<std::int64_t>(*bytes);
  if (!below && !above) return;
  ctx.report_with_note(
      diag_id::connection_size_format, ctx.where(d.size),
      fmt::format("{} {} size {} ranges {}..{}, which excludes the {} of its format {}", cn, d.name, d.size.text,
                  ctx.raw(p->min), ctx.raw(p->max), plural(*bytes, "byte"), assembly_name(*a)),
      assembly_size_at(ctx, *a), fmt::format("{} size is given here", assembly_name(*a)));
}

// O->T data size as far as the file tells: the size field, else the format's.
std::optional<std::uint64_t> effective_size(const check_context& ctx, const direction& d) {
  if (d.size.is_integer()) return d.size.as_uint();
  if (d.size.present()) return std::nullopt;
  if (const auto* a = format_assembly(ctx, d.format)) return assembly_bytes(*a);
  return std::nullopt;
}

void check_heartbeat(const check_context& ctx, const std::string& cn, const model::connection& c, const direction& ot) {
  const auto size = effective_size(ctx, ot);
  if (!size || null_connection(c)) return;
  const auto format = c.cp.ot.real_time_format;
  if (format == 3 && *size != 0) {
    ctx.report(diag_id::connection_heartbeat_size, ctx.where(c.params),
               fmt::format("{} O->T real-time format is 3 (heartbeat) but O->T carries {}", cn, plural(*size, "byte")));
  } else if (format != 3 && *size == 0 && ot.size.present()) {
    ctx.report(diag_id::connection_heartbeat_size, ctx.where(ot.size),
               fmt::format("{} O->T size is 0 but its real-time format is {}, not 3 (heartbeat)", cn, format));
  }
}

// The instance an assembly is addressed by: the one its Path names. Without
// a Path there is no evidence (the N of AssemN is a name, not an address).
std::optional<std::uint32_t> assembly_instance(const check_context& ctx, const model::assembly& a) {
  if (const auto* p = ctx.dev.path_of(a.path); p != nullptr && !p->segments.empty()) {
    for (const auto& s : p->segments) {
      if (s.kind == model::segment_kind::instance || s.kind == model::segment_kind::connection_point) {
        if (!s.value_known()) return std::nullopt;
        return s.value;
      }
    }
  }
  return std::nullopt;
}

void check_points(const check_context& ctx, const std::string& cn, const model::connection& c, const direction& ot,
                  const direction& to) {
  const auto* path = ctx.dev.path_of(c.path);
  if (path == nullptr) return;
  std::vector<const model::epath_segment*> points;
  for (const auto& s : path->segments)
    if (s.kind == model::segment_kind::connection_point) points.push_back(&s);
  // With a single point it is unclear which direction it serves: not checked.
  if (points.size() != 2) return;
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& d = i == 0 ? ot : to;
    const auto* a = format_assembly(ctx, d.format);
    if (a == nullptr || !points[i]->value_known()) continue;
    const auto inst = assembly_instance(ctx, *a);
    if (!inst || *inst == points[i]->value) continue;
    ctx.report_with_note(
        diag_id::connection_point_mismatch, ctx.where(c.path),
        fmt::format("{} path names {} connection point {} (0x{:02X}) but its {} format {} is "
                    "instance {} (0x{:02X})",
                    cn, d.name, points[i]->value, points[i]->value, d.name, assembly_name(*a), *inst, *inst),
        ctx.where(a->path), fmt::format("{} is addressed here", assembly_name(*a)));
  }
}

}  // namespace

namespace {

void check_connections(const check_context& ctx) {
  for (const auto& c : ctx.dev.connections) {
    const auto cn = fmt::format("Connection{}", c.number);
    const direction ot{"O->T", c.cp.ot, c.ot_rpi, c.ot_size, c.ot_format, 0, 16};
    const direction to{"T->O", c.cp.to, c.to_rpi, c.to_size, c.to_format, 2, 20};
    if (c.decoded) {
      check_trigger(ctx, cn, c);
      check_params_bits(ctx, cn, c);
      check_direction_bits(ctx, cn, c, ot);
      check_direction_bits(ctx, cn, c, to);
      check_heartbeat(ctx, cn, c, ot);
    }
    for (const auto* d : {&ot, &to}) {
      check_rpi(ctx, cn, *d);
      check_size(ctx, cn, *d);
    }
    check_points(ctx, cn, c, ot, to);
  }
}

}  // namespace

// The registry's single entry point for the assembly, connection, port,
// modular and icon rules: assemblies first, since connections lean on them.
void check_connection_family(const check_context& ctx) {
  check_assemblies(ctx);
  check_connections(ctx);
  check_ports_and_icon(ctx);
}

}  // namespace edsc
