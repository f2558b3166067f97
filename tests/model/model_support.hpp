#pragma once
// Lowers EDS text held by the test, keeping source, tree and model alive together.
#include <memory>
#include <string>

#include "lower/lower.hpp"
#include "parse/parser.hpp"

namespace edsc::test {

struct lowered {
  std::unique_ptr<source_file> src;
  parse_result parsed;
  model::device dev;
};

inline std::unique_ptr<lowered> lower_text(std::string text, std::string path = "test.eds") {
  auto l = std::make_unique<lowered>();
  l->src = std::make_unique<source_file>(std::move(path), std::move(text));
  l->parsed = parse(*l->src);
  diagnostics d;
  l->dev = lower(l->parsed.tree, d);
  return l;
}

// The source text a value's origin points at.
inline std::string_view at(const lowered& l, const model::value& v) { return l.src->text(v.from.where); }

}  // namespace edsc::test
