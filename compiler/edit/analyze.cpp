#include "edit/analyze.hpp"

#include <algorithm>

#include "check/context.hpp"
#include "lower/lower.hpp"
#include "parse/parser.hpp"

namespace edsc::edit {

std::unique_ptr<analysis> analyze(std::string path, std::string bytes, const check_options& options) {
  // Same steps as check_file, so an edit is judged exactly as `edsc check` would judge the file.
  auto a = std::make_unique<analysis>();
  a->source = std::make_unique<source_file>(std::move(path), std::move(bytes));
  auto parsed = parse(*a->source);
  a->tree = std::move(parsed.tree);
  a->syntax = parsed.diags;
  a->diags = std::move(parsed.diags);
  a->dev = lower(a->tree, a->diags);
  a->dev.tree = &a->tree;
  const std::uint8_t networks = options.networks != 0 ? options.networks : a->dev.classes.networks;
  run_checks(check_context{a->tree, a->dev, networks, a->diags});
  std::stable_sort(a->diags.begin(), a->diags.end(),
                   [](const diagnostic& x, const diagnostic& y) { return x.where.begin < y.where.begin; });
  options.policy.apply(a->diags);
  options.policy.apply(a->syntax);
  return a;
}

}  // namespace edsc::edit
