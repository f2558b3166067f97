// Assemblies: sizes and member layout. A member is known by what it refers
// to (a parameter through the parameter matching, so renumbering alone moves
// no data), and reported when its bits moved.
#include <map>

#include <fmt/format.h>

#include "cst/cst.hpp"
#include "diff/context.hpp"
#include "diff/pairing.hpp"
#include "facts/header_parts.hpp"

namespace edsc::diff::detail {

namespace {

using model::assembly;

struct placed {
  std::string id;     // what the member is, the same in both files
  std::string label;  // for people
  std::optional<std::uint64_t> offset, bits;
  const model::assembly_member* m = nullptr;
};

std::string bit_range(const placed& p) {
  if (!p.offset || !p.bits) return "bits unknown";
  if (*p.bits == 0) return fmt::format("at bit {}", *p.offset);
  if (*p.bits == 1) return fmt::format("bit {}", *p.offset);
  return fmt::format("bits {}-{}", *p.offset, *p.offset + *p.bits - 1);
}

// `new_index` maps a parameter of this file to the index in the new file's
// params that identifies it (identity for the new file, the matching for the old).
std::vector<placed> layout(const device& d, const assembly& a, const std::vector<std::uint32_t>* to_new) {
  std::vector<placed> out;
  std::optional<std::uint64_t> offset = 0;
  std::map<std::string, int> seen;
  for (const auto& m : a.members) {
    placed p;
    p.m = &m;
    p.offset = offset;
    p.bits = emit::number_or_param_default(d, m.size);
    if (offset && p.bits)
      offset = *offset + *p.bits;
    else
      offset.reset();
    if (!m.ref.present()) continue;  // padding
    if (const auto* r = m.ref.as_ref(); r != nullptr && r->kind == schema::ref_kind::param && r->resolved()) {
      const auto& q = d.params[r->target];
      const auto j = to_new ? (*to_new)[r->target] : r->target;
      p.id = j == model::none ? fmt::format("gone:{}", r->target) : fmt::format("param:{}", j);
      if (r->has_bit()) p.id += fmt::format(":{}", static_cast<std::uint32_t>(r->bit));
      const auto name = text_of(q.name);
      p.label = name.empty() ? shown(d, m.ref) : fmt::format("{} \"{}\"", shown(d, m.ref), brief(name, 40));
    } else {
      p.id = "value:" + key(d, m.ref);
      p.label = shown(d, m.ref);
    }
    p.id += fmt::format("#{}", seen[p.id]++);
    out.push_back(std::move(p));
  }
  return out;
}

std::string label(const device& d, const assembly& a) {
  const auto name = text_of(a.name);
  const auto kw =
      a.from.entry != model::none ? d.tree->text(d.tree->entries[a.from.entry].keyword) : std::string_view("Assem");
  return name.empty() ? std::string(kw) : fmt::format("{} \"{}\"", kw, brief(name, 40));
}

void compare_pair(context& c, const assembly& x, const assembly& y) {
  const auto subject = "[Assembly] " + label(c.b, y);
  auto field = [&](const value& u, const value& v, impact i, const char* kind, const char* what, const char* why) {
    c.field(group::io, subject, u, v, i, kind, what, why);
  };
  field(x.size, y.size, impact::breaking, "assembly-size", "size",
        "a connection configured for the old size is refused with a size mismatch, and data mapped after it moves");
  field(x.path, y.path, impact::breaking, "assembly-path", "path",
        "the assembly is another instance: connections configured for the old one reach something else");
  field(x.name, y.name, impact::cosmetic, "assembly-name", "name", "tools show the new name");
  field(x.descriptor, y.descriptor, impact::cosmetic, "assembly-descriptor", "descriptor", "no effect on the data");

  const auto old_members = layout(c.a, x, &c.param_match);
  const auto new_members = layout(c.b, y, nullptr);
  std::map<std::string, const placed*> before;
  for (const auto& p : old_members) before.emplace(p.id, &p);
  for (const auto& q : new_members) {
    const auto it = before.find(q.id);
    if (it == before.end()) {
      auto& d = c.add(group::io, impact::additive, "assembly-member-added", subject,
                      fmt::format("member {} added at {}", q.label, bit_range(q)),
                      "new data in the assembly; if other members kept their bits, configured data stays in place");
      d.after = at(c.b, q.m->ref);
      continue;
    }
    const auto& p = *it->second;
    before.erase(it);
    if (p.offset == q.offset && p.bits == q.bits) continue;
    auto& d = c.add(group::io, impact::breaking, "assembly-member-moved", subject,
                    fmt::format("member {} moved: {} -> {}", q.label, bit_range(p), bit_range(q)),
                    "a scanner or program that reads these bits where they were now reads other data");
    d.before = at(c.a, p.m->ref);
    d.after = at(c.b, q.m->ref);
  }
  for (const auto& p : old_members) {
    if (!before.count(p.id)) continue;
    auto& d = c.add(group::io, impact::breaking, "assembly-member-removed", subject,
                    fmt::format("member {} at {} removed", p.label, bit_range(p)),
                    "data a configuration reads or writes through this assembly is gone");
    d.before = at(c.a, p.m->ref);
  }
}

}  // namespace

void compare_assemblies(context& c) {
  const auto m = pair_by_key(c.a.assemblies, c.b.assemblies, [](const assembly& x) {
    return std::uint64_t{static_cast<std::uint32_t>(x.kind)} << 32 | x.number;
  });
  for (std::size_t i = 0; i < c.a.assemblies.size(); ++i) {
    const auto& x = c.a.assemblies[i];
    c.cover(x.from, {});
    if (const auto* y = m.partner[i]) {
      compare_pair(c, x, *y);
      continue;
    }
    auto& d = c.add(group::io, impact::breaking, "assembly-removed", "[Assembly] " + label(c.a, x), "removed",
                    "connections configured with this assembly can no longer be made");
    d.before = at(x.from, label(c.a, x));
  }
  for (std::size_t j = 0; j < c.b.assemblies.size(); ++j) {
    const auto& y = c.b.assemblies[j];
    c.cover({}, y.from);
    if (m.paired[j]) continue;
    auto& d = c.add(group::io, impact::additive, "assembly-added", "[Assembly] " + label(c.b, y), "added",
                    "a new assembly; nothing configured uses it yet");
    d.after = at(y.from, label(c.b, y));
  }
}

}  // namespace edsc::diff::detail
