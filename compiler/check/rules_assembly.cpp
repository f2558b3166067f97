// [Assembly] member layouts (EDS_FORMAT.md §3.10, §7 rules 24-28). Unresolved
// references (rule 23) belong to the generic reference rule, so every check
// here silently skips what does not resolve.
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "check/context.hpp"
#include "schema/cip_types.hpp"

namespace edsc {

// Also used by the [Connection Manager] rules (declared there as well).
std::string assembly_name(const model::assembly& a);
std::optional<std::uint64_t> assembly_bytes(const model::assembly& a);

namespace {

using schema::ref_kind;

bool in_range(ref_kind k, ref_kind first, ref_kind last) {
  return static_cast<int>(k) >= static_cast<int>(first) && static_cast<int>(k) <= static_cast<int>(last);
}
bool names_assembly(const model::reference& r) {
  return in_range(r.kind, ref_kind::assem, ref_kind::proxied_assem_exa);
}
bool names_variant(const model::reference& r) { return in_range(r.kind, ref_kind::variant, ref_kind::variant_exa); }

// A resolved reference to an assembly (any of the AssemN family).
const model::assembly* target_assembly(const check_context& ctx, const model::value& v) {
  const auto* r = v.as_ref();
  if (r == nullptr || !r->resolved() || !names_assembly(*r)) return nullptr;
  return &ctx.dev.assemblies[r->target];
}

// A lone empty field after the last pair is a trailing comma (`16, Param1, ;`),
// not a member whose half went missing.
bool odd_members(const model::assembly& a) { return a.dangling.present(); }

void check_odd_members(const check_context& ctx, const model::assembly& a) {
  if (!odd_members(a)) return;
  ctx.report(diag_id::assembly_odd_members, ctx.where(a.dangling),
             fmt::format("{} has an odd number of member fields: the last member size '{}' has no reference "
                         "field (write `{},` for padding)",
                         assembly_name(a), ctx.raw(a.dangling), ctx.raw(a.dangling)));
}

void check_total(const check_context& ctx, const model::assembly& a) {
  if (!a.size.is_integer() || a.members.empty() || odd_members(a)) return;  // odd: which half is missing?
  std::uint64_t bits = 0;
  for (const auto& m : a.members) {
    if (!m.size.is_integer()) return;  // a ParamN-sized or missing member: the total is unknown
    bits += m.size.as_uint();
  }
  const auto bytes = a.size.as_uint();
  if (bits == 8 * bytes) return;
  // Members that add up to the Size itself were counted in bytes, not bits.
  // No fix-it: either side may be the wrong one.
  ctx.report(diag_id::assembly_size_mismatch, ctx.where(a.size),
             fmt::format("{} Size is {} ({} bits) but its members add up to {}{}", assembly_name(a),
                         plural(bytes, "byte"), 8 * bytes, plural(bits, "bit"),
                         bits == bytes ? " (the member sizes look like bytes; they count bits)" : ""));
}

// Packed layouts (Rockwell files especially) give a parameter fewer bits
// than its type when its values need no more: a USINT of 0..3 in 2 bits.
// Only limits written in the file count as evidence against the packing;
// empty limits (common with enumerated parameters) do not.
bool range_fits(const model::param& p, std::uint64_t bits) {
  if (p.type->cls != schema::type_class::signed_int && p.type->cls != schema::type_class::unsigned_int &&
      p.type->cls != schema::type_class::bit_string) {
    return false;
  }
  if (bits == 0 || bits >= 63) return false;
  const bool has_lo = p.min.is_integer();
  const bool has_hi = p.max.is_integer();
  const std::int64_t lo = has_lo ? p.min.as_int() : 0;
  const std::int64_t hi = has_hi ? p.max.as_int() : 0;
  if (lo >= 0) return hi < (std::int64_t{1} << bits);
  const std::int64_t half = std::int64_t{1} << (bits - 1);
  return lo >= -half && hi < half;
}

void check_member_widths(const check_context& ctx, const model::assembly& a) {
  for (const auto& m : a.members) {
    if (!m.size.is_integer()) continue;
    const auto bits = m.size.as_uint();
    const auto* r = m.ref.as_ref();
    if (r == nullptr || !r->resolved() || r->has_bit()) continue;  // `Param10:3` is one bit by design
    if (const auto* inner = target_assembly(ctx, m.ref)) {
      const auto inner_bytes = assembly_bytes(*inner);
      if (inner_bytes && bits != 8 * *inner_bytes) {
        ctx.report_with_note(
            diag_id::assembly_member_assembly_size, ctx.where(m.size),
            fmt::format("{} gives member {} {} but {} is {} ({} bits)", assembly_name(a), m.ref.text,
                        plural(bits, "bit"), m.ref.text, plural(*inner_bytes, "byte"), 8 * *inner_bytes),
            inner->size.present() ? ctx.where(inner->size) : ctx.entry_keyword(inner->from),
            fmt::format("{} size is given here", m.ref.text));
      }
      continue;
    }
    if (!in_range(r->kind, ref_kind::param, ref_kind::proxied_param)) continue;
    const auto& p = ctx.dev.params[r->target];
    if (p.type == nullptr || p.type->size == 0) continue;  // strings, EPATH, STRINGI: length varies
    if (bits == 8u * p.type->size || (bits < 8u * p.type->size && range_fits(p, bits))) continue;
    const bool narrow = bits < 8u * p.type->size;
    ctx.report_with_note(
        diag_id::assembly_member_param_size, ctx.where(m.size),
        fmt::format("{} gives member {} {} but {} is {} ({} bits){}", assembly_name(a), m.ref.text, plural(bits, "bit"),
                    m.ref.text, p.type->name, 8 * p.type->size, narrow ? " and its range does not fit in fewer" : ""),
        ctx.where(narrow ? p.max : p.data_type),
        fmt::format("{} {} is given here", m.ref.text, narrow ? "maximum" : "data type"));
  }
}

// One containment link: assembly `from` reaches assembly `to` through the
// member reference `via` (directly, or through a VariantN selection).
struct link {
  std::uint32_t to;
  const model::value* via;
};

std::vector<std::vector<link>> containment_graph(const check_context& ctx) {
  const auto& dev = ctx.dev;
  std::vector<std::vector<link>> out(dev.assemblies.size());
  for (std::uint32_t i = 0; i < dev.assemblies.size(); ++i) {
    for (const auto& m : dev.assemblies[i].members) {
      const auto* r = m.ref.as_ref();
      if (r == nullptr || !r->resolved()) continue;
      if (names_assembly(*r)) out[i].push_back({r->target, &m.ref});
      if (!names_variant(*r)) continue;
      for (const auto& ch : dev.variants[r->target].choices) {
        for (const auto* t : {&ch.target, &ch.when_clear}) {
          const auto* tr = t->as_ref();
          if (tr != nullptr && tr->resolved() && names_assembly(*tr)) out[i].push_back({tr->target, &m.ref});
        }
      }
    }
  }
  return out;
}

// Iterative depth-first search (files may chain many assemblies): every
// back edge closes one cycle, reported where it closes.
void check_cycles(const check_context& ctx) {
  const auto graph = containment_graph(ctx);
  enum : std::uint8_t { unseen, open, done };
  std::vector<std::uint8_t> state(graph.size(), unseen);
  struct frame {
    std::uint32_t node;
    std::size_t next;
  };
  for (std::uint32_t root = 0; root < graph.size(); ++root) {
    if (state[root] != unseen) continue;
    std::vector<frame> stack{{root, 0}};
    state[root] = open;
    while (!stack.empty()) {
      auto& top = stack.back();
      if (top.next == graph[top.node].size()) {
        state[top.node] = done;
        stack.pop_back();
        continue;
      }
      const auto& l = graph[top.node][top.next++];
      if (state[l.to] == unseen) {
        state[l.to] = open;
        stack.push_back({l.to, 0});
        continue;
      }
      if (state[l.to] != open) continue;
      std::size_t start = 0;
      while (stack[start].node != l.to) ++start;
      std::string names;
      for (std::size_t i = start; i < stack.size(); ++i)
        names += assembly_name(ctx.dev.assemblies[stack[i].node]) + " -> ";
      names += assembly_name(ctx.dev.assemblies[l.to]);
      const auto& first = graph[stack[start].node][stack[start].next - 1];
      ctx.report_with_note(diag_id::assembly_cycle, ctx.where(*l.via),
                           fmt::format("assemblies contain each other: {}", names), ctx.where(*first.via),
                           "the cycle starts with this member");
    }
  }
}

void check_variants(const check_context& ctx) {
  for (const auto& v : ctx.dev.variants) {
    if (v.kind == model::variant_kind::bitstring_variant) continue;  // its triples select by bit, not by value
    const auto name = fmt::format("{}{}", v.kind == model::variant_kind::variant ? "Variant" : "VariantExa", v.number);
    if (!v.selector.present()) {
      ctx.report(diag_id::variant_incomplete, ctx.where(v.selector),
                 fmt::format("{} has no selector (field 6): its layout cannot be confirmed", name));
    }
    if (v.choices.size() < 2) {
      ctx.report(
          diag_id::variant_incomplete, ctx.entry_keyword(v.from),
          fmt::format("{} offers {}; a variant needs at least two", name, plural(v.choices.size(), "selection")));
    }
  }
}

}  // namespace

std::string assembly_name(const model::assembly& a) {
  const auto kind = static_cast<ref_kind>(static_cast<int>(ref_kind::assem) + static_cast<int>(a.kind));
  return fmt::format("{}{}", schema::stem_of(kind), a.number);
}

// Bytes of an assembly: its Size, else (Size empty) what numeric members add up to.
std::optional<std::uint64_t> assembly_bytes(const model::assembly& a) {
  if (a.size.is_integer()) return a.size.as_uint();
  if (a.size.present() || a.members.empty()) return std::nullopt;
  std::uint64_t bits = 0;
  for (const auto& m : a.members) {
    if (!m.size.is_integer()) return std::nullopt;
    bits += m.size.as_uint();
  }
  if (bits % 8 != 0) return std::nullopt;
  return bits / 8;
}

void check_assemblies(const check_context& ctx) {
  for (const auto& a : ctx.dev.assemblies) {
    check_odd_members(ctx, a);
    check_total(ctx, a);
    check_member_widths(ctx, a);
  }
  check_cycles(ctx);
  check_variants(ctx);
}

}  // namespace edsc
