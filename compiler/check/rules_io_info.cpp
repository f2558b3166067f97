// [IO_Info] and [Variant_IO_Info]: the DeviceNet predefined connection set
// (EDS_FORMAT.md §3.4, §3.5, §7 rules 13 and 36-42).
#include <array>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "check/context.hpp"

namespace edsc {

namespace {

using model::io_connection;

constexpr std::array<const char*, 4> info_names{"PollInfo", "StrobeInfo", "COSInfo", "CyclicInfo"};
constexpr std::array<std::uint16_t, 4> info_bits{model::io_poll, model::io_strobe, model::io_cos, model::io_cyclic};

std::string data_name(const model::io_data& d) { return fmt::format("{}{}", d.output ? "Output" : "Input", d.number); }

void check_mask(const check_context& ctx, const model::value& mask, std::string_view what) {
  if (!mask.is_integer()) return;
  const auto m = mask.as_uint();
  if (m & 0xFFE0) {
    ctx.report(
        diag_id::io_info_mask_reserved, ctx.where(mask),
        fmt::format("{} mask 0x{:04X} sets reserved bits 0x{:04X} (only 0x000F are defined)", what, m, m & 0xFFE0));
  } else if (m & model::io_multicast_poll) {
    ctx.report(diag_id::io_info_mask_multicast, ctx.where(mask),
               fmt::format("{} mask 0x{:04X} sets bit 4 (multicast poll), whose meaning is unconfirmed", what, m));
  }
}

void check_data(const check_context& ctx, const model::io_data& d, std::string_view section) {
  const auto name = data_name(d);
  check_mask(ctx, d.mask, fmt::format("{} connection", name));
  if (d.path_size.is_integer() && d.path.ok()) {
    if (const auto* p = ctx.dev.path_of(d.path); p != nullptr && p->byte_count != d.path_size.as_uint()) {
      auto& diag = ctx.report(diag_id::io_info_path_size, ctx.where(d.path_size),
                              fmt::format("{} path size is {} but the path holds {}", name, d.path_size.as_uint(),
                                          plural(p->byte_count, "byte")));
      diag.notes.push_back({ctx.where(d.path), "the path is here"});
      diag.fixits.push_back({ctx.where(d.path_size), std::to_string(p->byte_count)});
    }
  }
  if (d.size.is_integer() && d.significant_bits.is_integer()) {
    const auto bytes = d.size.as_uint();
    const auto bits = d.significant_bits.as_uint();
    if (bits > 8 * bytes) {
      ctx.report(diag_id::io_info_significant_bits, ctx.where(d.significant_bits),
                 fmt::format("{} declares {} significant bits but carries only {} ({} bits)", name, bits,
                             plural(bytes, "byte"), 8 * bytes));
    } else if (bits != 0 && bytes > 1 && bits <= 8 * (bytes - 1)) {
      const auto unused = bytes - (bits + 7) / 8;
      ctx.report(
          diag_id::io_info_significant_bits_low, ctx.where(d.significant_bits),
          fmt::format("{} declares {} for {} bytes: the last {} {} nothing; "
                      "write 0 (all bits) or {}",
                      name, plural(bits, "significant bit"), bytes, unused == 1 ? "byte" : plural(unused, "byte"),
                      noun(unused, "carries", "carry"), 8 * bytes));
    }
    if (bytes > 8 && section == "IO_Info") {
      ctx.report(diag_id::io_info_fragmented, ctx.where(d.size),
                 fmt::format("{} is {} bytes: over 8 bytes DeviceNet needs fragmented I/O", name, bytes));
    }
    if (d.output && bytes > 1 && d.mask.is_integer() && (d.mask.as_uint() & model::io_strobe)) {
      ctx.report(diag_id::io_info_strobe_output_size, ctx.where(d.size),
                 fmt::format("{} allows bit-strobe but is {} bytes; the strobe command carries 1 bit per "
                             "node",
                             name, bytes));
    }
  }
}

const model::io_data* resolve(const model::io_info& io, const model::value& v, bool output) {
  const auto* ref = v.as_ref();
  if (ref == nullptr || !ref->resolved()) return nullptr;
  const auto& list = output ? io.outputs : io.inputs;
  return ref->target < list.size() ? &list[ref->target] : nullptr;
}

void check_default_ref(const check_context& ctx, const model::io_info& io, const model::io_connection_info& c,
                       const model::value& v, bool output) {
  if (!v.is_integer() || v.as_uint() == 0) return;
  const auto type = static_cast<std::size_t>(c.type);
  const auto* target = resolve(io, v, output);
  const char* kind = output ? "Output" : "Input";
  if (target == nullptr) {
    ctx.report(output ? diag_id::io_info_default_output : diag_id::io_info_default_input, ctx.where(v),
               fmt::format("{} names {}{} as its default {}, but there is no {}{}", info_names[type], kind, v.as_uint(),
                           output ? "output" : "input", kind, v.as_uint()));
    return;
  }
  if (target->mask.is_integer() && (target->mask.as_uint() & info_bits[type]) == 0) {
    ctx.report_with_note(diag_id::io_info_default_mask, ctx.where(v),
                         fmt::format("{} uses {} but {}'s connection mask 0x{:04X} does not allow {}", info_names[type],
                                     data_name(*target), data_name(*target), target->mask.as_uint(), info_names[type]),
                         ctx.where(target->mask), fmt::format("{} is declared here", data_name(*target)));
  }
}

void check_connections(const check_context& ctx, const model::io_info& io) {
  std::uint16_t present = 0;
  for (const auto& c : io.connections) {
    const auto type = static_cast<std::size_t>(c.type);
    present |= info_bits[type];
    check_mask(ctx, c.mask, info_names[type]);
    check_default_ref(ctx, io, c, c.default_input, false);
    check_default_ref(ctx, io, c, c.default_output, true);
    if (!c.mask.is_integer()) continue;
    const auto m = c.mask.as_uint();
    if ((m & info_bits[type]) == 0) {
      ctx.report(
          diag_id::io_info_compat_self, ctx.where(c.mask),
          fmt::format("{} compatibility mask 0x{:04X} does not include its own connection type", info_names[type], m));
    }
    if ((c.type == io_connection::cos && (m & model::io_cyclic)) ||
        (c.type == io_connection::cyclic && (m & model::io_cos))) {
      ctx.report(diag_id::io_info_cos_cyclic, ctx.where(c.mask),
                 fmt::format("{} mask 0x{:04X} allows COS and Cyclic together; they share one connection "
                             "instance and exclude each other",
                             info_names[type], m));
    }
  }
  if (io.default_mask.is_integer()) {
    const auto def = io.default_mask.as_uint();
    for (std::size_t t = 0; t < info_bits.size(); ++t) {
      if ((def & info_bits[t]) && !(present & info_bits[t])) {
        ctx.report(diag_id::io_info_default_missing_info, ctx.where(io.default_mask),
                   fmt::format("Default 0x{:04X} selects {} but there is no {} entry", def,
                               std::string_view(info_names[t]).substr(0, std::string_view(info_names[t]).size() - 4),
                               info_names[t]));
      }
    }
  }
}

void check_unreferenced(const check_context& ctx, const model::io_info& io) {
  for (const auto* list : {&io.inputs, &io.outputs}) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const auto& d = (*list)[i];
      bool used = false;
      for (const auto& c : io.connections) {
        const auto& v = d.output ? c.default_output : c.default_input;
        used = used || (v.as_ref() != nullptr && v.as_ref()->target == i);
      }
      if (!used) {
        ctx.report(diag_id::io_info_unreferenced, ctx.entry_keyword(d.from),
                   fmt::format("{} is not the default input or output of any connection", data_name(d)));
      }
    }
  }
}

// [Variant_IO_Info] (our reading, EDS_FORMAT.md §3.5): the same data set in
// another size; path and connection mask are expected to match the twin.
void check_variants(const check_context& ctx) {
  const auto& io = ctx.dev.io;
  for (const auto* list : {&ctx.dev.variant_io.inputs, &ctx.dev.variant_io.outputs}) {
    for (const auto& v : *list) {
      check_data(ctx, v, "Variant_IO_Info");
      const auto& twins = v.output ? io.outputs : io.inputs;
      const model::io_data* twin = nullptr;
      for (const auto& t : twins) twin = t.number == v.number ? &t : twin;
      if (twin == nullptr) {
        ctx.report(diag_id::variant_io_mismatch, ctx.entry_keyword(v.from),
                   fmt::format("[Variant_IO_Info] {} has no {} in [IO_Info]", data_name(v), data_name(v)));
        continue;
      }
      if (v.mask.is_integer() && twin->mask.is_integer() && v.mask.as_uint() != twin->mask.as_uint()) {
        ctx.report_with_note(diag_id::variant_io_mismatch, ctx.where(v.mask),
                             fmt::format("variant {} connection mask 0x{:04X} differs from [IO_Info]'s 0x{:04X}",
                                         data_name(v), v.mask.as_uint(), twin->mask.as_uint()),
                             ctx.where(twin->mask), "the [IO_Info] entry is here");
      }
      if (v.path.ok() && twin->path.ok() && v.path.text != twin->path.text) {
        ctx.report_with_note(diag_id::variant_io_mismatch, ctx.where(v.path),
                             fmt::format("variant {} path differs from [IO_Info]'s", data_name(v)),
                             ctx.where(twin->path), "the [IO_Info] entry is here");
      }
    }
  }
}

}  // namespace

void check_io_info(const check_context& ctx) {
  const auto& io = ctx.dev.io;
  if (io.section != model::none && !ctx.devicenet()) {
    ctx.report(diag_id::network_section_mismatch, ctx.section_name(io.section),
               "[IO_Info] describes DeviceNet connections, but the file is not classified DeviceNet");
  }
  if (io.section != model::none) {
    check_mask(ctx, io.default_mask, "Default");
    check_connections(ctx, io);
    for (const auto* list : {&io.inputs, &io.outputs}) {
      for (const auto& d : *list) check_data(ctx, d, "IO_Info");
    }
    check_unreferenced(ctx, io);
  }
  if (ctx.dev.variant_io.section != model::none && !ctx.devicenet()) {
    ctx.report(diag_id::network_section_mismatch, ctx.section_name(ctx.dev.variant_io.section),
               "[Variant_IO_Info] describes DeviceNet connections, but the file is not classified DeviceNet");
  }
  check_variants(ctx);
}

}  // namespace edsc
