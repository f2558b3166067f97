// Everything no group judged, entry by entry: an entry is known by its
// section and keyword (case-insensitive, as EDS readers match them) and its
// occurrence, and compared on its typed fields.
#include <cctype>
#include <map>

#include <fmt/format.h>

#include "cst/cst.hpp"
#include "diff/context.hpp"
#include "model/visit.hpp"

namespace edsc::diff::detail {

namespace {

struct entry_view {
  std::uint32_t entry = model::none;
  std::string section, keyword;  // as written in the file
  std::vector<const value*> fields;
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& ch : out) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return out;
}

// Uncovered entries by (section, keyword, occurrence), in file order.
std::map<std::string, entry_view> entries_of(const device& d, const std::unordered_set<std::uint32_t>& covered) {
  std::map<std::uint32_t, entry_view> by_entry;
  model::for_each_value(d, [&](const value& v) {
    const auto e = v.from.entry;
    if (e == model::none || e >= d.tree->entries.size() || covered.count(e)) return;
    auto& view = by_entry[e];
    view.entry = e;
    view.fields.push_back(&v);
  });
  std::map<std::string, entry_view> out;
  std::map<std::string, int> seen;
  for (auto& [e, view] : by_entry) {
    // `A = 1;` and `A = 1, ;` say the same.
    while (!view.fields.empty() && !view.fields.back()->present()) view.fields.pop_back();
    const auto& ce = d.tree->entries[e];
    view.section =
        ce.section == cst::npos ? std::string() : std::string(d.tree->text(d.tree->sections[ce.section].name));
    view.keyword = std::string(d.tree->text(ce.keyword));
    auto k = lower(view.section) + '|' + lower(view.keyword);
    k += fmt::format("#{}", seen[k]++);
    out.emplace(std::move(k), std::move(view));
  }
  return out;
}

std::string fields_text(const device& d, const entry_view& e) {
  std::string s;
  for (const auto* v : e.fields) s += (s.empty() ? "" : ", ") + shown(d, *v);
  while (s.size() >= 2 && s.substr(s.size() - 2) == ", ") s.resize(s.size() - 2);  // trailing empty fields
  return s;
}

struct verdict {
  impact level;
  const char* why;
};

// What an entry outside the groups means for a configured network, by section.
verdict judge(const device& a, const entry_view* x, const device& b, const entry_view* y) {
  const auto section = lower((x ? x : y)->section);
  if (!x) return {impact::additive, "new information; nothing configured changes"};
  if (section == "file") return {impact::cosmetic, "file information: no effect on the device or its configuration"};
  if (section == "device")
    return {impact::cosmetic, "descriptive identity: scanners key on vendor, type, code and revision only"};
  if (section == "device classification")
    return {impact::breaking, "the networks the file declares changed: tools stop offering the device where it was"};
  bool text_only = y != nullptr && x->fields.size() == y->fields.size();
  if (text_only)
    for (std::size_t i = 0; i < x->fields.size(); ++i)
      if (!same(a, *x->fields[i], b, *y->fields[i]) &&
          (x->fields[i]->kind != model::value_kind::string || y->fields[i]->kind != model::value_kind::string))
        text_only = false;
  if (text_only) return {impact::cosmetic, "text only"};
  if (section == "capacity" && y && x->fields.size() == 1 && y->fields.size() == 1 && x->fields[0]->is_integer() &&
      y->fields[0]->is_integer())
    return y->fields[0]->as_int() < x->fields[0]->as_int()
               ? verdict{impact::breaking, "a configuration that uses more than the new limit is refused"}
               : verdict{impact::additive, "a higher limit; configurations within the old one still fit"};
  if (section == "port")
    return {impact::breaking, "routes configured through this port (connection paths) may no longer be valid"};
  return {impact::cosmetic, "edsc knows of no effect of this entry on a configured network"};
}

}  // namespace

void compare_entries(context& c) {
  const auto xs = entries_of(c.a, c.covered_a);
  const auto ys = entries_of(c.b, c.covered_b);
  auto grp = [](const entry_view& e) {
    const auto s = lower(e.section);
    return s == "device" || s == "device classification" ? group::identity : group::other;
  };
  auto subject = [](const entry_view& e) { return fmt::format("[{}] {}", e.section, e.keyword); };
  for (const auto& [k, x] : xs) {
    const auto it = ys.find(k);
    const entry_view* y = it == ys.end() ? nullptr : &it->second;
    if (y == nullptr) {
      const auto v = judge(c.a, &x, c.b, nullptr);
      // A removal is never better than a change: additive cannot apply.
      auto& d = c.add(grp(x), v.level == impact::additive ? impact::cosmetic : v.level, "entry-removed", subject(x),
                      "removed (was " + brief(fields_text(c.a, x)) + ")", v.why);
      d.before = {c.a.tree->entries[x.entry].where.begin, fields_text(c.a, x)};
      continue;
    }
    bool equal = x.fields.size() == y->fields.size();
    for (std::size_t i = 0; equal && i < x.fields.size(); ++i) equal = same(c.a, *x.fields[i], c.b, *y->fields[i]);
    if (equal) continue;
    const auto v = judge(c.a, &x, c.b, y);
    auto& d = c.add(grp(*y), v.level, "entry-changed", subject(*y),
                    brief(fields_text(c.a, x)) + " -> " + brief(fields_text(c.b, *y)), v.why);
    d.before = {c.a.tree->entries[x.entry].where.begin, fields_text(c.a, x)};
    d.after = {c.b.tree->entries[y->entry].where.begin, fields_text(c.b, *y)};
  }
  for (const auto& [k, y] : ys) {
    if (xs.count(k)) continue;
    const auto v = judge(c.a, nullptr, c.b, &y);
    auto& d = c.add(grp(y), v.level, "entry-added", subject(y), "added: " + brief(fields_text(c.b, y)), v.why);
    d.after = {c.b.tree->entries[y.entry].where.begin, fields_text(c.b, y)};
  }
}

}  // namespace edsc::diff::detail
