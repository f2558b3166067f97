#include "edit/fix.hpp"

#include <fmt/format.h>

#include "edit/analyze.hpp"
#include "edit/splice.hpp"

namespace edsc::edit {

namespace {

// A repair loop that does not settle is a bug in some rule's fix-it; the
// bound keeps `fix` from spinning forever on it.
constexpr int max_passes = 8;

std::string shown(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if (c == '\t')
      out += "\\t";
    else
      out.push_back(c);
  }
  return out;
}

bool overlaps(const std::vector<replacement>& taken, span r) {
  for (const auto& t : taken) {
    if (r.begin < t.range.end && t.range.begin < r.end) return true;
    if (r.begin == t.range.begin && (r.empty() || t.range.empty())) return true;
  }
  return false;
}

}  // namespace

std::string describe_change(const source_file& src, const fixit& f) {
  if (f.range.empty()) return fmt::format("insert '{}'", shown(f.replacement));
  if (f.replacement.empty()) return fmt::format("remove '{}'", shown(src.text(f.range)));
  return fmt::format("replace '{}' with '{}'", shown(src.text(f.range)), shown(f.replacement));
}

fix_result fix_text(const std::string& path, std::string text, const check_options& options) {
  fix_result out;
  for (int pass = 1;; ++pass) {
    auto a = analyze(path, text, options);
    std::vector<replacement> changes;
    std::vector<applied_fix> this_pass;
    for (const auto& d : a->diags) {
      // A diagnostic's fix-its belong together: take all of them or none.
      std::vector<replacement> mine;
      bool clash = false;
      for (const auto& f : d.fixits) {
        clash = clash || overlaps(changes, f.range) || overlaps(mine, f.range);
        mine.push_back({f.range, f.replacement});
      }
      if (d.fixits.empty() || clash) continue;
      for (const auto& f : d.fixits) {
        const auto pos = a->source->position(f.range.begin);
        this_pass.push_back({fmt::format("{}:{}:{}", path, pos.line, pos.column), std::string(rule_of(d.id).name),
                             d.message, describe_change(*a->source, f), pass});
      }
      changes.insert(changes.end(), mine.begin(), mine.end());
    }
    if (changes.empty() || pass > max_passes) {
      out.converged = changes.empty();
      for (auto& d : a->diags)
        if (d.fixits.empty() || !out.converged) out.remaining.push_back(std::move(d));
      out.final_source = std::move(a->source);
      out.text = std::move(text);
      return out;
    }
    auto next = apply_replacements(text, std::move(changes));
    if (!next) {  // cannot happen: overlaps were filtered above
      out.converged = false;
      out.final_source = std::move(a->source);
      out.text = std::move(text);
      return out;
    }
    text = std::move(*next);
    out.applied.insert(out.applied.end(), this_pass.begin(), this_pass.end());
  }
}

}  // namespace edsc::edit
