#pragma once
// Internal to the diff: what the comparers of each group share.
#include <string>
#include <unordered_set>
#include <vector>

#include "diff/diff.hpp"
#include "model/device.hpp"

namespace edsc::diff::detail {

using model::device;
using model::value;

// A value as text: `shown` for people, `key` for equality (integers in
// decimal whatever their spelling, keywords in lower case, blanks in EPATHs
// and datasets collapsed). Absent values are empty.
[[nodiscard]] std::string shown(const device& d, const value& v);
[[nodiscard]] std::string key(const device& d, const value& v);
[[nodiscard]] bool same(const device& a, const value& x, const device& b, const value& y);
// A string value's text (empty when it is not a string).
[[nodiscard]] std::string_view text_of(const value& v);
// Shortened for one line of text output.
[[nodiscard]] std::string brief(std::string_view s, std::size_t max = 60);

struct context {
  const device& a;  // before
  const device& b;  // after
  const options& opt;
  result& out;
  // CST entries a dedicated comparer has judged; the entry-level pass skips them.
  std::unordered_set<std::uint32_t> covered_a, covered_b;
  // Parameter matching: for each a.params index, the b.params index (or none).
  std::vector<std::uint32_t> param_match;

  void cover(const model::origin& x, const model::origin& y) {
    if (x.entry != model::none) covered_a.insert(x.entry);
    if (y.entry != model::none) covered_b.insert(y.entry);
  }
  // One difference when a field differs: "what old -> new" (help texts:
  // "help text changed", their values kept in before/after).
  void field(group g, const std::string& subject, const value& u, const value& v, impact i, const char* kind,
             std::string_view what, const char* why);
  difference& add(group g, impact i, std::string kind, std::string subject, std::string message,
                  std::string consequence) {
    auto& d = out.differences.emplace_back();
    d.in = g;
    d.level = i;
    d.kind = std::move(kind);
    d.subject = std::move(subject);
    d.message = std::move(message);
    d.consequence = std::move(consequence);
    return d;
  }
};

// A value missing with its whole entry is in neither place of that file.
[[nodiscard]] inline side at(const device& d, const value& v) {
  if (!v.present() && v.from.entry == model::none) return {};
  return {v.from.where.begin, shown(d, v)};
}
[[nodiscard]] inline side at(const model::origin& o, std::string what = {}) { return {o.where.begin, std::move(what)}; }

void compare_identity(context& c);
void compare_params(context& c);
void compare_io(context& c);
void compare_assemblies(context& c);
void compare_connections(context& c);
void compare_entries(context& c);

}  // namespace edsc::diff::detail
