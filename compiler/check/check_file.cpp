#include "check/check_file.hpp"

#include <algorithm>

#include "check/context.hpp"
#include "io/map_file.hpp"
#include "lower/lower.hpp"
#include "parse/parser.hpp"

namespace edsc {

std::unique_ptr<analysis> analyze(std::unique_ptr<source_file> source, const check_options& options) {
  auto a = std::make_unique<analysis>();
  a->source = std::move(source);
  auto parsed = parse(*a->source);
  a->tree = std::move(parsed.tree);
  a->syntax = parsed.diags;
  a->diags = std::move(parsed.diags);
  a->dev.tree = &a->tree;
  // Not EDS text: the input diagnostic is the whole verdict. Lowering an empty
  // tree would add "missing [File]" and the like, all consequences of it.
  if (!parsed.not_text) {
    a->dev = lower(a->tree, a->diags);
    a->dev.tree = &a->tree;
    const std::uint8_t networks = options.networks != 0 ? options.networks : a->dev.classes.networks;
    run_checks(check_context{a->tree, a->dev, networks, a->diags});
  }
  std::stable_sort(a->diags.begin(), a->diags.end(),
                   [](const diagnostic& x, const diagnostic& y) { return x.where.begin < y.where.begin; });
  options.policy.apply(a->diags);
  options.policy.apply(a->syntax);
  return a;
}

checked_file check_file(const std::string& path, const check_options& options) {
  // Mapped, not read: `check` is what runs over whole libraries.
  auto read = io::map_source(path);
  if (!read) {
    checked_file out;
    out.io_error = read.error().message;
    return out;
  }
  return check_source(std::move(read.value()), options);
}

checked_file check_source(std::unique_ptr<source_file> source, const check_options& options) {
  checked_file out;
  auto a = analyze(std::move(source), options);
  // Zeros stood in for part of the file: what was found is not about it.
  if (a->source->changed()) {
    out.io_error = io::changed_while_read(a->source->path()).message;
    return out;
  }
  // The source is heap-held, so it outlives the tree and model that point into it.
  out.report.source = std::move(a->source);
  out.report.diags = std::move(a->diags);
  return out;
}

}  // namespace edsc
