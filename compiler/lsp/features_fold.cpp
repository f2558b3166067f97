// Folding ranges: sections, entries over several lines and comment blocks,
// read from the tree's sections, entries and comment tokens.
#include <algorithm>

#include "lsp/features.hpp"

namespace edsc::lsp {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// `s` without its trailing blanks and line breaks.
span trim_end(std::string_view text, span s) {
  while (s.end > s.begin && is_space(text[s.end - 1])) --s.end;
  return s;
}

bool spans_lines(std::string_view text, span s) {
  return text.substr(s.begin, s.size()).find_first_of("\r\n") != std::string_view::npos;
}

// Runs of three or more consecutive lines that hold a comment and nothing
// else but blanks.
void comment_blocks(const cst::tree& t, std::vector<fold>& out) {
  span run{};
  std::uint32_t run_lines = 0;
  bool line_start = true;    // only blanks since the last line break
  std::uint32_t breaks = 0;  // line breaks since the run's last comment
  const auto close = [&] {
    if (run_lines >= 3) out.push_back({run, true});
    run_lines = 0;
  };
  for (const auto tok : t.tokens) {
    switch (tok.kind) {
      case cst::token_kind::blank:
      case cst::token_kind::bom: break;
      case cst::token_kind::newline:
        line_start = true;
        if (++breaks > 1) close();  // a blank line ends the block
        break;
      case cst::token_kind::comment:
        if (!line_start) {
          close();  // after a value: not a comment line
        } else if (run_lines > 0 && breaks == 1) {
          run.end = tok.where.end;
          ++run_lines;
        } else {
          close();
          run = tok.where;
          run_lines = 1;
        }
        breaks = 0;
        line_start = false;
        break;
      default:
        line_start = false;
        close();
        break;
    }
  }
  close();
}

}  // namespace

std::vector<fold> folding_ranges(const analysis& a) {
  const auto& t = a.tree;
  const auto text = a.text();
  std::vector<fold> out;
  for (const auto& s : t.sections) out.push_back({s.where, false});
  for (const auto& e : t.entries) out.push_back({e.where, false});
  comment_blocks(t, out);
  // A section runs to the next header: its fold ends on its last non-blank line.
  for (auto& f : out) f.range = trim_end(text, f.range);
  std::erase_if(out, [&](const fold& f) { return !spans_lines(text, f.range); });
  std::sort(out.begin(), out.end(), [](const fold& x, const fold& y) {
    return x.range.begin != y.range.begin ? x.range.begin < y.range.begin : x.range.end > y.range.end;
  });
  return out;
}

}  // namespace edsc::lsp
