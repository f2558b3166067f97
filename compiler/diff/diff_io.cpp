// DeviceNet I/O: [IO_Info] per connection type and per data set, and
// [Variant_IO_Info], the alternative sizes a configuration tool offers.
#include <array>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "cst/cst.hpp"
#include "diff/context.hpp"
#include "diff/pairing.hpp"

namespace edsc::diff::detail {

namespace {

using model::io_data;
using model::io_info;

// The connection types by their bit of a mask. Bit 4 (multicast poll, not
// confirmed) and the reserved bits above it are not named; `at` makes a
// loop that reads past bit 3 fail instead of reading past the array.
constexpr auto type_names = std::to_array<const char*>({"Poll", "Strobe", "COS", "Cyclic"});

std::optional<std::uint64_t> size_of(const io_data& d) {
  if (!d.size.is_integer() || d.size.negative) return std::nullopt;
  return d.size.as_uint();
}

std::string bytes(std::optional<std::uint64_t> n) {
  if (!n) return "an unknown number of bytes";
  return plural(*n, "byte");
}

std::string data_label(const io_data& d) {
  const auto name = text_of(d.name);
  return fmt::format("{}{}{}", d.output ? "Output" : "Input", d.number,
                     name.empty() ? std::string() : fmt::format(" \"{}\"", brief(name, 40)));
}

const io_data* find(const io_info& io, bool output, std::uint32_t number) {
  for (const auto& d : output ? io.outputs : io.inputs)
    if (d.number == number) return &d;
  return nullptr;
}

// The connection types whose xxxInfo names this data set as their default.
std::string carried_by(const io_info& io, const io_data& d) {
  std::string names;
  for (const auto& c : io.connections) {
    const auto* r = (d.output ? c.default_output : c.default_input).as_ref();
    if (r == nullptr || r->number != d.number) continue;
    if (!names.empty()) names += " and ";
    names += type_names[static_cast<int>(c.type)];
  }
  return names;
}

// Connection type t exists when a data set may be used with it or its xxxInfo
// names data (DEVICENET_FIRMWARE.md §1; the same reading as `edsc header`).
bool supported(const io_info& io, unsigned t) {
  for (const auto* list : {&io.inputs, &io.outputs})
    for (const auto& d : *list)
      if (d.mask.is_integer() && (d.mask.as_uint() >> t) & 1u) return true;
  for (const auto& c : io.connections) {
    if (static_cast<unsigned>(c.type) != t) continue;
    for (const auto* v : {&c.default_input, &c.default_output})
      if (const auto* r = v->as_ref(); r != nullptr && r->resolved()) return true;
  }
  return false;
}

const model::io_connection_info* info_of(const io_info& io, unsigned t) {
  for (const auto& c : io.connections)
    if (static_cast<unsigned>(c.type) == t) return &c;
  return nullptr;
}

std::uint64_t mask_of(const value& v) { return v.is_integer() ? v.as_uint() : 0; }

std::string type_list(std::uint64_t mask) {
  std::string s;
  for (unsigned t = 0; t < 4; ++t)
    if ((mask >> t) & 1u) s += (s.empty() ? "" : ", ") + std::string(type_names.at(t));
  return s.empty() ? "none" : s;
}

struct io_pass {
  context& c;
  const io_info& x;
  const io_info& y;
  bool variant;
  std::string section;  // "[IO_Info]"

  void size_change(const io_data& p, const io_data& q) {
    const auto from = size_of(p), to = size_of(q);
    std::string message = fmt::format("{} -> {}", bytes(from), bytes(to));
    if (!same(c.a, p.significant_bits, c.b, q.significant_bits))
      message +=
          fmt::format(" (significant bits {} -> {})", shown(c.a, p.significant_bits), shown(c.b, q.significant_bits));
    const char* image = q.output ? "output" : "input";
    const char* flow = q.output ? "sends" : "receives";
    std::string why;
    if (variant) {
      why = fmt::format("a configuration that chose this {}-byte alternative no longer finds it", from.value_or(0));
    } else {
      const auto types = carried_by(y, q);
      if (!types.empty()) why = types + " connections carry it by default. ";
      why += fmt::format(
          "A scanner configured for {} from this node {} {}: it reports a size mismatch for the node and exchanges "
          "no I/O with it until its scanlist is edited; once edited, the node takes {} of the scanner's {} image, "
          "so every node mapped after it moves",
          bytes(from), q.output ? "expects to send" : flow, bytes(to), bytes(to), image);
      if (from && to && *to != *from) why += " by " + bytes(*to > *from ? *to - *from : *from - *to);
      why += '.';
      if (c.out.keys.exact_match) why += " Keying cannot catch it: the identity is unchanged.";
      if (const auto* alt = find(c.b.variant_io, q.output, q.number); alt && size_of(*alt) == from)
        why += fmt::format(" The old {}-byte size stays selectable in [Variant_IO_Info].", from.value_or(0));
    }
    auto& d = c.add(group::io, impact::breaking, "io-size", section + ' ' + data_label(q), message, why);
    d.before = at(c.a, p.size);
    d.after = at(c.b, q.size);
  }

  void data_pair(const io_data& p, const io_data& q) {
    const auto subject = section + ' ' + data_label(q);
    auto field = [&](const value& u, const value& v, impact i, const char* kind, const char* what, const char* why) {
      c.field(group::io, subject, u, v, i, kind, what, why);
    };
    if (!same(c.a, p.size, c.b, q.size)) {
      size_change(p, q);
    } else {
      field(p.significant_bits, q.significant_bits, impact::cosmetic, "io-significant-bits", "significant bits",
            "the same bytes move; only how many of their bits carry data changed");
    }
    const auto m0 = mask_of(p.mask), m1 = mask_of(q.mask);
    if (m0 != m1) {
      const bool lost = (m0 & ~m1) != 0;
      auto& d = c.add(group::io, lost ? impact::breaking : impact::additive, "io-connection-mask", subject,
                      fmt::format("usable with {} -> {}", type_list(m0), type_list(m1)),
                      lost ? fmt::format("a scanner that exchanges it over {} can no longer do so", type_list(m0 & ~m1))
                           : std::string("more connection types may carry it; existing ones still do"));
      d.before = at(c.a, p.mask);
      d.after = at(c.b, q.mask);
    }
    field(p.path, q.path, impact::breaking, "io-path", "path",
          "the data comes from another object attribute: what the scanner receives means something else");
    field(p.name, q.name, impact::cosmetic, "io-name", "name", "tools show the new name");
    field(p.help, q.help, impact::cosmetic, "io-help", "help text", "documentation only");
    if (same(c.a, p.path, c.b, q.path))
      field(p.path_size, q.path_size, impact::cosmetic, "io-field", "path size", "no effect on a configuration");
  }

  void data_sets(bool output) {
    const auto& xs = output ? x.outputs : x.inputs;
    const auto& ys = output ? y.outputs : y.inputs;
    const auto m = pair_by_key(xs, ys, [](const io_data& d) { return std::uint64_t{d.number}; });
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const auto& p = xs[i];
      c.cover(p.from, {});
      if (const auto* q = m.partner[i]) {
        data_pair(p, *q);
        continue;
      }
      auto& d = c.add(group::io, impact::breaking, "io-data-removed", section + ' ' + data_label(p), "removed",
                      variant ? "a configuration that chose this alternative size no longer finds it"
                              : "a scanner that exchanges this data with the node can no longer do so");
      d.before = at(p.from, bytes(size_of(p)));
    }
    for (std::size_t j = 0; j < ys.size(); ++j) {
      const auto& q = ys[j];
      c.cover({}, q.from);
      if (m.paired[j]) continue;
      auto& d = c.add(group::io, impact::additive, "io-data-added", section + ' ' + data_label(q),
                      fmt::format("added ({})", bytes(size_of(q))),
                      "new data a scanner may choose; nothing configured changes");
      d.after = at(q.from, bytes(size_of(q)));
    }
  }

  void connection_types() {
    for (unsigned t = 0; t < 4; ++t) {
      const auto* ci = info_of(x, t);
      const auto* di = info_of(y, t);
      if (ci) c.cover(ci->from, {});
      if (di) c.cover({}, di->from);
      const bool s0 = supported(x, t), s1 = supported(y, t);
      const auto subject = fmt::format("{} {} connection", section, type_names[t]);
      if (s0 && !s1) {
        auto& d = c.add(group::io, impact::breaking, "io-connection-removed", subject, "no longer supported",
                        fmt::format("a scanner configured to use {} with this node cannot allocate it", type_names[t]));
        if (ci) d.before = at(ci->from);
        continue;
      }
      if (!s0 && s1) {
        auto& d = c.add(group::io, impact::additive, "io-connection-added", subject, "now supported",
                        "a new choice for scanners; existing configurations do not use it");
        if (di) d.after = at(di->from);
        continue;
      }
      if (!s0 || !ci || !di) continue;
      for (const bool output : {false, true}) {
        const auto& u = output ? ci->default_output : ci->default_input;
        const auto& v = output ? di->default_output : di->default_input;
        if (same(c.a, u, c.b, v)) continue;
        const auto* r0 = u.as_ref();
        const auto* r1 = v.as_ref();
        const auto* p = r0 ? find(x, output, r0->number) : nullptr;
        const auto* q = r1 ? find(y, output, r1->number) : nullptr;
        const auto n0 = p ? size_of(*p) : std::optional<std::uint64_t>(0);
        const auto n1 = q ? size_of(*q) : std::optional<std::uint64_t>(0);
        auto& d = c.add(group::io, n0 == n1 ? impact::cosmetic : impact::breaking, "io-connection-default", subject,
                        fmt::format("default {} {} -> {} ({} -> {})", output ? "output" : "input", shown(c.a, u),
                                    shown(c.b, v), bytes(n0), bytes(n1)),
                        n0 == n1 ? "the connection carries another data set of the same size"
                                 : "a scanner configured for the old size reports a size mismatch for the node");
        d.before = at(c.a, u);
        d.after = at(c.b, v);
      }
      const auto m0 = mask_of(ci->mask), m1 = mask_of(di->mask);
      if (m0 != m1) {
        const bool lost = (m0 & ~m1) != 0;
        auto& d = c.add(group::io, lost ? impact::breaking : impact::additive, "io-connection-mask", subject,
                        fmt::format("may run together with {} -> {}", type_list(m0), type_list(m1)),
                        lost ? "a scanner that opens these connection types together is refused"
                             : "more combinations are allowed; existing ones still are");
        d.before = at(c.a, ci->mask);
        d.after = at(c.b, di->mask);
      }
    }
  }

  void run() {
    if (x.section == model::none && y.section == model::none) return;
    c.cover(x.default_from, y.default_from);
    if (x.section == model::none || y.section == model::none) {
      section_presence();
      return;
    }
    if (!variant) {
      connection_types();
      const auto& u = x.default_mask;
      const auto& v = y.default_mask;
      if (!same(c.a, u, c.b, v)) {
        auto& d = c.add(group::io, impact::cosmetic, "io-default", section + " Default",
                        fmt::format("default connection types {} -> {}", type_list(mask_of(u)), type_list(mask_of(v))),
                        "what a tool proposes for a new configuration; existing configurations keep theirs");
        d.before = at(c.a, u);
        d.after = at(c.b, v);
      }
    }
    data_sets(false);
    data_sets(true);
  }

  void section_presence() {
    const bool added = x.section == model::none;
    const auto& io = added ? y : x;
    const auto& dev = added ? c.b : c.a;
    std::string sets;
    bool keeps_old = added && variant;
    for (const auto* list : {&io.inputs, &io.outputs})
      for (const auto& d : *list) {
        sets += (sets.empty() ? "" : ", ") + data_label(d) + " (" + bytes(size_of(d)) + ")";
        if (added)
          c.cover({}, d.from);
        else
          c.cover(d.from, {});
        if (keeps_old) {
          const auto* old = find(c.a.io, d.output, d.number);
          keeps_old = old != nullptr && size_of(*old) == size_of(d);
        }
      }
    for (const auto& ci : io.connections) added ? c.cover({}, ci.from) : c.cover(ci.from, {});
    std::string why;
    if (variant)
      why = added ? (keeps_old && !sets.empty()
                         ? std::string("the old size stays selectable: a scanner can still be configured for it")
                         : std::string("new alternative sizes a configuration tool offers"))
                  : std::string("configurations that chose one of these alternative sizes no longer find it");
    else
      why = added ? "DeviceNet I/O is now described; nothing configured changes"
                  : "scanners can no longer configure this node's DeviceNet I/O from the file";
    auto& d =
        c.add(group::io, added ? impact::additive : impact::breaking, added ? "io-section-added" : "io-section-removed",
              section, fmt::format("{}{}", added ? "added" : "removed", sets.empty() ? "" : ": " + sets), why);
    const auto where = model::origin{model::none, dev.tree->sections[io.section].header};
    (added ? d.after : d.before) = at(where, section);
  }
};

}  // namespace

void compare_io(context& c) {
  io_pass{c, c.a.io, c.b.io, false, "[IO_Info]"}.run();
  io_pass{c, c.a.variant_io, c.b.variant_io, true, "[Variant_IO_Info]"}.run();
}

}  // namespace edsc::diff::detail
