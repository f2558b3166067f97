#include "check/verify.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "diag/catalogue.hpp"

namespace edsc::testing {

std::vector<expectation> read_expectations(const source_file& src) {
  std::vector<expectation> out;
  const std::string_view text = src.text();
  static constexpr std::string_view marker = "expected-";
  for (std::size_t at = text.find(marker); at != std::string_view::npos; at = text.find(marker, at + 1)) {
    std::size_t p = at + marker.size();
    const auto word_end = text.find_first_of("@{", p);
    if (word_end == std::string_view::npos) break;
    const auto level = parse_severity(text.substr(p, word_end - p));
    if (!level) continue;
    auto line = static_cast<std::int64_t>(src.position(static_cast<std::uint32_t>(at)).line);
    p = word_end;
    if (text[p] == '@') {
      const auto brace = text.find('{', p);
      line += std::stol(std::string(text.substr(p + 1, brace - p - 1)));
      p = brace;
    }
    if (text.substr(p, 2) != "{{") continue;
    const auto close = text.find("}}", p + 2);
    if (close == std::string_view::npos) break;
    out.push_back({static_cast<std::uint32_t>(line), *level, std::string(text.substr(p + 2, close - p - 2))});
  }
  return out;
}

namespace {

// Groups named by `verify-only:` lines; empty means every group.
std::vector<std::string> verified_groups(std::string_view text) {
  std::vector<std::string> groups;
  static constexpr std::string_view marker = "verify-only:";
  for (std::size_t at = text.find(marker); at != std::string_view::npos; at = text.find(marker, at + 1)) {
    std::size_t p = at + marker.size();
    const auto eol = text.find_first_of("\r\n", p);
    const auto line = text.substr(p, eol == std::string_view::npos ? std::string_view::npos : eol - p);
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && line[i] == ' ') ++i;
      const auto j = line.find(' ', i);
      const auto word = line.substr(i, j == std::string_view::npos ? std::string_view::npos : j - i);
      if (!word.empty()) groups.emplace_back(word);
      i = j == std::string_view::npos ? line.size() : j;
    }
  }
  return groups;
}

}  // namespace

std::vector<std::string> verify(const source_file& src, const diagnostics& all) {
  const auto groups = verified_groups(src.text());
  diagnostics diags;
  for (const auto& d : all) {
    const auto group = rule_of(d.id).group;
    if (groups.empty() || std::find(groups.begin(), groups.end(), group) != groups.end()) diags.push_back(d);
  }
  auto expected = read_expectations(src);
  std::vector<bool> met(expected.size(), false);
  std::vector<std::string> problems;
  for (const auto& d : diags) {
    const auto line = src.position(d.where.begin).line;
    const std::string full = fmt::format("{} [{}]", d.message, rule_of(d.id).name);
    bool found = false;
    for (std::size_t i = 0; i < expected.size() && !found; ++i) {
      const auto& e = expected[i];
      if (!met[i] && e.line == line && e.level == d.level && full.find(e.text) != std::string::npos) {
        met[i] = found = true;
      }
    }
    if (!found) problems.push_back(fmt::format("line {}: unexpected {}: {}", line, to_string(d.level), full));
  }
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (!met[i]) {
      problems.push_back(fmt::format("line {}: expected {} not seen: {{{{{}}}}}", expected[i].line,
                                     to_string(expected[i].level), expected[i].text));
    }
  }
  return problems;
}

}  // namespace edsc::testing
