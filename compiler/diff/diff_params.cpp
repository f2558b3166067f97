// Parameters: matched by content and name before number, so that a
// renumbered parameter is reported as one renumbering, not as a removal and
// an unrelated addition; then compared field by field.
#include <map>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "diff/context.hpp"
#include "model/slots.hpp"

namespace edsc::diff::detail {

namespace {

using model::param;

bool is_text_slot(value param::*s) {
  return s == &param::name || s == &param::help || s == &param::international_name ||
         s == &param::international_units || s == &param::international_help;
}

// Everything a parameter says, its enumeration included; `with_text` false
// leaves out name and help texts (to find a renamed parameter).
std::string content(const device& d, const param& p, bool with_text) {
  std::string s = fmt::format("{}|", static_cast<int>(p.kind));
  for (const auto slot : model::slots::param)
    if (with_text || !is_text_slot(slot)) s += key(d, p.*slot) + '|';
  for (const auto& v : p.extra) s += key(d, v) + '|';
  if (p.enum_index != model::none)
    for (const auto& e : d.enums[p.enum_index].pairs)
      s += key(d, e.val) + '=' + (with_text ? key(d, e.text) : "") + ';';
  if (p.enum_par_index != model::none)
    for (const auto& e : d.enum_pars[p.enum_par_index].strings) s += (with_text ? key(d, e) : "") + ';';
  return s;
}

std::string label(const param& p) {
  const auto name = text_of(p.name);
  return name.empty() ? fmt::format("Param{}", p.number) : fmt::format("Param{} \"{}\"", p.number, brief(name, 40));
}

bool unsigned_bits(const schema::cip_type_info& t) {
  return t.cls == schema::type_class::unsigned_int || t.cls == schema::type_class::bit_string;
}

std::optional<double> numeric(const value& v) {
  if (!v.ok() || (v.kind != model::value_kind::integer && v.kind != model::value_kind::real)) return std::nullopt;
  return v.as_real();
}

struct matcher {
  const device& a;
  const device& b;
  std::vector<std::uint32_t>& match;  // a index -> b index
  std::vector<bool> taken;            // b index taken

  void pair(std::uint32_t i, std::uint32_t j) {
    match[i] = j;
    taken[j] = true;
  }

  // One pass with one key: first every unmatched old parameter that has an
  // unmatched new one with the same key and number, then the rest with the
  // first unmatched new one of that key in file order. So a parameter that
  // kept its number is never taken by an identical one that moved, and
  // identical entries (a vendor's repeated ParamN) pair in order.
  template <class Key>
  void by(Key&& k) {
    std::unordered_map<std::string, std::vector<std::uint32_t>> index;
    for (std::uint32_t j = 0; j < b.params.size(); ++j)
      if (!taken[j]) index[k(b, b.params[j])].push_back(j);
    std::vector<const std::vector<std::uint32_t>*> same_key(a.params.size(), nullptr);
    for (std::uint32_t i = 0; i < a.params.size(); ++i) {
      if (match[i] != model::none) continue;
      const auto it = index.find(k(a, a.params[i]));
      if (it != index.end()) same_key[i] = &it->second;
    }
    for (const bool same_number : {true, false}) {
      for (std::uint32_t i = 0; i < a.params.size(); ++i) {
        if (match[i] != model::none || !same_key[i]) continue;
        for (const auto j : *same_key[i]) {
          if (taken[j] || (same_number && b.params[j].number != a.params[i].number)) continue;
          pair(i, j);
          break;
        }
      }
    }
  }
};

void compare_enum(context& c, const param& p, const param& q, const std::string& subject) {
  // EnumN: value -> text.
  std::map<std::string, std::string> old_e, new_e;
  if (p.enum_index != model::none)
    for (const auto& e : c.a.enums[p.enum_index].pairs) old_e.emplace(key(c.a, e.val), key(c.a, e.text));
  if (q.enum_index != model::none)
    for (const auto& e : c.b.enums[q.enum_index].pairs) new_e.emplace(key(c.b, e.val), key(c.b, e.text));
  // [EnumPar]: position -> text.
  if (p.enum_par_index != model::none) {
    const auto& s = c.a.enum_pars[p.enum_par_index].strings;
    for (std::size_t i = 0; i < s.size(); ++i) old_e.emplace(fmt::format("{}", i), key(c.a, s[i]));
  }
  if (q.enum_par_index != model::none) {
    const auto& s = c.b.enum_pars[q.enum_par_index].strings;
    for (std::size_t i = 0; i < s.size(); ++i) new_e.emplace(fmt::format("{}", i), key(c.b, s[i]));
  }
  std::vector<std::string> removed, added, renamed;
  for (const auto& [v, t] : old_e) {
    const auto it = new_e.find(v);
    if (it == new_e.end())
      removed.push_back(fmt::format("{} {}", v, t));
    else if (it->second != t)
      renamed.push_back(fmt::format("{} {} -> {}", v, t, it->second));
  }
  for (const auto& [v, t] : new_e)
    if (!old_e.count(v)) added.push_back(fmt::format("{} {}", v, t));
  auto list = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + brief(x, 40);
    return s;
  };
  const auto where = at(q.from);
  if (!removed.empty()) {
    auto& d = c.add(group::parameters, impact::breaking, "param-enum-removed", subject,
                    "enumerated values removed: " + list(removed),
                    "a configuration holding one of these values now sets a value the device does not list");
    d.after = where;
  }
  if (!added.empty()) {
    auto& d = c.add(group::parameters, impact::additive, "param-enum-added", subject,
                    "enumerated values added: " + list(added), "new choices; configured values stay valid");
    d.after = where;
  }
  if (!renamed.empty()) {
    auto& d = c.add(group::parameters, impact::cosmetic, "param-enum-text", subject,
                    "enumeration texts changed: " + list(renamed), "tools show the new texts; values are unchanged");
    d.after = where;
  }
}

void compare_range(context& c, const param& p, const param& q, const std::string& subject) {
  if (same(c.a, p.min, c.b, q.min) && same(c.a, p.max, c.b, q.max)) return;
  const auto lo0 = numeric(p.min), lo1 = numeric(q.min), hi0 = numeric(p.max), hi1 = numeric(q.max);
  const bool numbers = lo0 && lo1 && hi0 && hi1;
  const bool narrower = !numbers || *lo1 > *lo0 || *hi1 < *hi0;
  auto& d = c.add(group::parameters, narrower ? impact::breaking : impact::additive,
                  narrower ? "param-range-narrowed" : "param-range-widened", subject,
                  fmt::format("range {} .. {} -> {} .. {}", shown(c.a, p.min), shown(c.a, p.max), shown(c.b, q.min),
                              shown(c.b, q.max)),
                  narrower ? "a configured value outside the new range is refused when the configuration is downloaded"
                           : "every configured value stays within range");
  d.before = at(c.a, p.min);
  d.after = at(c.b, q.min);
}

void compare_descriptor(context& c, const param& p, const param& q, const std::string& subject) {
  if (same(c.a, p.descriptor, c.b, q.descriptor)) return;
  const auto x = p.descriptor.is_integer() ? p.descriptor.as_uint() : 0;
  const auto y = q.descriptor.is_integer() ? q.descriptor.as_uint() : 0;
  const bool now_read_only = (y & model::pd_read_only) && !(x & model::pd_read_only);
  const bool now_writable = (x & model::pd_read_only) && !(y & model::pd_read_only);
  auto& d = now_read_only ? c.add(group::parameters, impact::breaking, "param-read-only", subject,
                                  fmt::format("became read-only (descriptor {} -> {})", shown(c.a, p.descriptor),
                                              shown(c.b, q.descriptor)),
                                  "a configuration that writes it is refused by the device")
            : now_writable
                ? c.add(group::parameters, impact::additive, "param-writable", subject,
                        fmt::format("became writable (descriptor {} -> {})", shown(c.a, p.descriptor),
                                    shown(c.b, q.descriptor)),
                        "configurations may now set it")
                : c.add(group::parameters, impact::cosmetic, "param-descriptor", subject,
                        fmt::format("descriptor {} -> {}", shown(c.a, p.descriptor), shown(c.b, q.descriptor)),
                        "how tools present the value (scaling, enumeration, monitoring); the value a "
                        "configuration holds is unchanged");
  d.before = at(c.a, p.descriptor);
  d.after = at(c.b, q.descriptor);
}

void compare_pair(context& c, const param& p, const param& q) {
  const auto subject = label(q);
  auto field = [&](const value& u, const value& v, impact i, const char* kind, const char* what, const char* why) {
    c.field(group::parameters, subject, u, v, i, kind, what, why);
  };
  if (p.number != q.number) {
    const auto* there = c.b.find_param(p.number);
    auto& d = c.add(group::parameters, impact::breaking, "param-renumbered", subject,
                    fmt::format("renumbered: Param{} is now Param{}", p.number, q.number),
                    fmt::format("configurations address parameters by instance number: a configuration that sets "
                                "Param{} now reaches {}",
                                p.number, there ? label(*there) : std::string("no parameter")));
    d.before = at(p.from, fmt::format("Param{}", p.number));
    d.after = at(q.from, fmt::format("Param{}", q.number));
  }
  field(p.name, q.name, impact::cosmetic, "param-name", "name", "tools show the new name; the instance is the same");
  // BYTE and USINT (WORD and UINT...) put the same bytes on the wire.
  const bool same_encoding = p.type && q.type && p.type->size == q.type->size && p.type->size != 0 &&
                             unsigned_bits(*p.type) && unsigned_bits(*q.type);
  auto type_name = [](const device& d, const param& x) {
    return x.type ? fmt::format("{} ({})", x.type->name, shown(d, x.data_type)) : shown(d, x.data_type);
  };
  if (!same(c.a, p.data_type, c.b, q.data_type)) {
    auto& d =
        c.add(group::parameters, same_encoding ? impact::cosmetic : impact::breaking, "param-type", subject,
              fmt::format("data type {} -> {}", type_name(c.a, p), type_name(c.b, q)),
              same_encoding ? "same size and encoding: tools show the value differently (hex or decimal); configured "
                              "values stay valid"
                            : "a configured value is sent in the old type's encoding and is refused or misread");
    d.before = at(c.a, p.data_type);
    d.after = at(c.b, q.data_type);
  }
  field(p.data_size, q.data_size, impact::breaking, "param-size", "data size",
        "a configured value no longer has the size the device expects");
  compare_range(c, p, q, subject);
  field(p.default_value, q.default_value, impact::cosmetic, "param-default", "default",
        "existing configurations keep their values; new ones start from the new default");
  compare_descriptor(c, p, q, subject);
  field(p.link_path, q.link_path, impact::breaking, "param-link-path", "link path",
        "the parameter now maps to another object attribute: what a configuration writes lands elsewhere");
  field(p.units, q.units, impact::cosmetic, "param-units", "units", "tools show the new units; values are unchanged");
  field(p.help, q.help, impact::cosmetic, "param-help", "help text", "documentation only");
  for (const auto slot : {&param::scaling_multiplier, &param::scaling_divisor, &param::scaling_base,
                          &param::scaling_offset, &param::multiplier_link, &param::divisor_link, &param::base_link,
                          &param::offset_link, &param::decimal_precision})
    field(p.*slot, q.*slot, impact::cosmetic, "param-scaling", "display scaling",
          "tools show the value scaled differently; the value a configuration holds is unchanged");
  for (const auto slot : {&param::international_name, &param::international_units, &param::international_help,
                          &param::reserved, &param::link_path_size})
    field(p.*slot, q.*slot, impact::cosmetic, "param-field", "field", "no effect on a configuration");
  compare_enum(c, p, q, subject);
}

}  // namespace

void compare_params(context& c) {
  c.param_match.assign(c.a.params.size(), model::none);
  matcher m{c.a, c.b, c.param_match, std::vector<bool>(c.b.params.size(), false)};
  m.by([](const device& d, const param& p) { return content(d, p, true); });
  m.by([](const device& d, const param& p) { return fmt::format("{}|{}", static_cast<int>(p.kind), key(d, p.name)); });
  m.by([](const device& d, const param& p) { return content(d, p, false); });
  // What is left at the same number was edited in place (name and type
  // together, as a vendor does when a WORD becomes a UINT "Qualifier").
  m.by([](const device&, const param& p) { return fmt::format("{}|{}", static_cast<int>(p.kind), p.number); });

  for (std::uint32_t i = 0; i < c.a.params.size(); ++i) {
    const auto& p = c.a.params[i];
    c.cover(p.from, {});
    if (c.param_match[i] == model::none) {
      auto& d = c.add(group::parameters, impact::breaking, "param-removed", label(p), "removed",
                      "a configuration that sets it fails when downloaded, and data that referred to it is gone");
      d.before = at(p.from, label(p));
      continue;
    }
    compare_pair(c, p, c.b.params[c.param_match[i]]);
  }
  for (std::uint32_t j = 0; j < c.b.params.size(); ++j) {
    const auto& q = c.b.params[j];
    c.cover({}, q.from);
    if (m.taken[j]) continue;
    auto& d = c.add(group::parameters, impact::additive, "param-added", label(q), "added",
                    "existing configurations leave it at its default");
    d.after = at(q.from, label(q));
  }
  for (const auto& e : c.a.enums) c.cover(e.from, {});
  for (const auto& e : c.b.enums) c.cover({}, e.from);
  for (const auto& e : c.a.enum_pars) c.cover(e.from, {});
  for (const auto& e : c.b.enum_pars) c.cover({}, e.from);
}

}  // namespace edsc::diff::detail
