#include "check/check_file.hpp"

#include "check/context.hpp"

#include <algorithm>

#include "io/read_file.hpp"
#include "lower/lower.hpp"
#include "parse/parser.hpp"

namespace edsc {

checked_file check_file(const std::string& path, const check_options& options) {
  checked_file out;
  auto read = io::read_source(path);
  if (auto* err = std::get_if<io::io_error>(&read)) {
    out.io_error = err->message;
    return out;
  }
  out.report.source = std::move(std::get<std::unique_ptr<source_file>>(read));
  auto parsed = parse(*out.report.source);
  out.report.diags = std::move(parsed.diags);
  const auto dev = lower(parsed.tree, out.report.diags);
  const std::uint8_t networks = options.networks != 0 ? options.networks : dev.classes.networks;
  run_checks(check_context{parsed.tree, dev, networks, out.report.diags});
  std::stable_sort(out.report.diags.begin(), out.report.diags.end(),
                   [](const diagnostic& a, const diagnostic& b) { return a.where.begin < b.where.begin; });
  options.policy.apply(out.report.diags);
  return out;
}

}  // namespace edsc
