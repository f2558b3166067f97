// The comparison: each group in turn, then the entry-level pass over what no
// group judged, then the differences sorted into their groups.
#include "diff/diff.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "diff/context.hpp"

namespace edsc::diff {

namespace detail {

namespace {

std::optional<std::uint64_t> number(const value& v) {
  if (!v.is_integer() || v.negative) return std::nullopt;
  return v.as_uint();
}

identity_key key_of(const model::device_info& d) {
  return {number(d.vend_code), number(d.prod_type), number(d.prod_code), number(d.maj_rev), number(d.min_rev)};
}

std::string revision_text(const identity_key& k) {
  auto part = [](const std::optional<std::uint64_t>& n) { return n ? fmt::format("{}", *n) : std::string("?"); };
  return part(k.major) + "." + part(k.minor);
}

}  // namespace

// Vendor, device type, product code and revision: what a scanner compares
// with the node's Identity object (DEVICENET_FIRMWARE.md §1, DEVICENET_NETWORK.md §3).
void compare_identity(context& c) {
  const auto& x = c.a.identity;
  const auto& y = c.b.identity;
  auto& keys = c.out.keys;
  keys.before = key_of(x);
  keys.after = key_of(y);
  const bool same_product = keys.before.vendor == keys.after.vendor &&
                            keys.before.device_type == keys.after.device_type &&
                            keys.before.product_code == keys.after.product_code;
  const bool same_major = keys.before.major == keys.after.major;
  const bool same_minor = keys.before.minor == keys.after.minor;
  keys.exact_match = same_product && same_major && same_minor;
  keys.compatible_match =
      same_product && same_major &&
      (same_minor || (keys.before.minor && keys.after.minor && *keys.after.minor > *keys.before.minor));

  struct field {
    const value model::device_info::*slot;
    const char* name;
  };
  static constexpr field product[] = {{&model::device_info::vend_code, "vendor code (VendCode)"},
                                      {&model::device_info::prod_type, "device type (ProdType)"},
                                      {&model::device_info::prod_code, "product code (ProdCode)"}};
  for (const auto& f : product) {
    const auto& u = x.*f.slot;
    const auto& v = y.*f.slot;
    c.cover(u.from, v.from);
    if (same(c.a, u, c.b, v)) continue;
    auto& d = c.add(group::identity, impact::breaking, "identity-product", "[Device]",
                    fmt::format("{} changed from {} to {}", f.name, shown(c.a, u), shown(c.b, v)),
                    "a scanner configured with the old identity reports the node as Mismatch whatever its "
                    "revision keying; the node must be configured anew with the new file");
    d.before = at(c.a, u);
    d.after = at(c.b, v);
  }
  c.cover(x.maj_rev.from, y.maj_rev.from);
  c.cover(x.min_rev.from, y.min_rev.from);
  const auto was = revision_text(keys.before), now = revision_text(keys.after);
  if (!same(c.a, x.maj_rev, c.b, y.maj_rev)) {
    auto& d = c.add(group::identity, impact::breaking, "identity-major-revision", "[Device] MajRev",
                    fmt::format("major revision changed: {} -> {}", was, now),
                    "scanners keyed to exact match or to compatible revision report the node as Mismatch; "
                    "configuration tools register EDS files per major revision, so the new file is a new "
                    "device to them");
    d.before = at(c.a, x.maj_rev);
    d.after = at(c.b, y.maj_rev);
  } else if (!same(c.a, x.min_rev, c.b, y.min_rev)) {
    const bool newer = keys.compatible_match;
    const bool exact = c.opt.assumed == keying::exact;
    auto& d = newer ? c.add(group::identity, exact ? impact::breaking : impact::additive, "identity-minor-revision",
                            "[Device] MinRev", fmt::format("minor revision raised: {} -> {}", was, now),
                            "a scanner keyed to compatible revision accepts the node; one keyed to exact match "
                            "reports it as Mismatch until its key is changed to the new revision")
                    : c.add(group::identity, impact::breaking, "identity-minor-revision", "[Device] MinRev",
                            fmt::format("minor revision lowered: {} -> {}", was, now),
                            "the device is older than the one configured: scanners keyed to exact match or "
                            "to compatible revision report the node as Mismatch");
    d.before = at(c.a, x.min_rev);
    d.after = at(c.b, y.min_rev);
  }
}

void context::field(group g, const std::string& subject, const value& u, const value& v, impact i, const char* kind,
                    std::string_view what, const char* why) {
  if (same(a, u, b, v)) return;
  auto message = what == "help text" ? std::string("help text changed")
                                     : fmt::format("{} {} -> {}", what, brief(shown(a, u)), brief(shown(b, v)));
  auto& d = add(g, i, kind, subject, std::move(message), why);
  d.before = at(a, u);
  d.after = at(b, v);
}

}  // namespace detail

std::size_t result::count(impact i) const {
  return static_cast<std::size_t>(
      std::count_if(differences.begin(), differences.end(), [i](const difference& d) { return d.level == i; }));
}

std::string_view to_string(impact i) {
  switch (i) {
    case impact::cosmetic: return "cosmetic";
    case impact::additive: return "additive";
    case impact::breaking: return "breaking";
  }
  return "cosmetic";
}

std::string_view to_string(group g) {
  switch (g) {
    case group::identity: return "identity";
    case group::io: return "io";
    case group::parameters: return "parameters";
    case group::connections: return "connections";
    case group::other: return "other";
  }
  return "other";
}

std::string_view title(group g) {
  switch (g) {
    case group::identity: return "identity and keying";
    case group::io: return "I/O";
    case group::parameters: return "parameters";
    case group::connections: return "connections";
    case group::other: return "other entries";
  }
  return "other entries";
}

result compare(const model::device& before, const model::device& after, const options& opt) {
  result out;
  detail::context c{before, after, opt, out, {}, {}, {}};
  detail::compare_identity(c);
  detail::compare_params(c);
  detail::compare_io(c);
  detail::compare_assemblies(c);
  detail::compare_connections(c);
  detail::compare_entries(c);
  // Grouped; inside a group, in the order of the new file (removals where
  // they stood in the old one, after everything of the new file).
  auto position = [](const difference& d) {
    return d.after.present() ? std::uint64_t{d.after.offset} : (std::uint64_t{1} << 32) + d.before.offset;
  };
  std::stable_sort(out.differences.begin(), out.differences.end(), [&](const difference& l, const difference& r) {
    if (l.in != r.in) return l.in < r.in;
    return position(l) < position(r);
  });
  return out;
}

}  // namespace edsc::diff
