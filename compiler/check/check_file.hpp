#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "cst/cst.hpp"
#include "diag/policy.hpp"
#include "diag/report.hpp"
#include "model/device.hpp"

namespace edsc {

struct check_options {
  diag_policy policy;
  std::uint8_t networks = 0;  // model::network bits from --network; 0: detect
};

// The whole front end on one source: the tree, the model and every
// diagnostic after the user's policy. `edsc check` and the authoring commands
// (which judge an edit's result before writing it) share it, so a file is
// judged the same way everywhere. Not movable: tree and model point into
// `source`.
struct analysis {
  std::unique_ptr<source_file> source;
  cst::tree tree;
  model::device dev;
  diagnostics syntax;  // the parser's own findings (a subset of `diags`)
  diagnostics diags;   // sorted by position

  analysis() = default;
  analysis(const analysis&) = delete;
  analysis& operator=(const analysis&) = delete;

  [[nodiscard]] std::string_view text() const { return source->text(); }
  [[nodiscard]] bool has_syntax_errors() const { return count_at_least(syntax, severity::error) > 0; }
  [[nodiscard]] std::size_t errors() const { return count_at_least(diags, severity::error); }
};

[[nodiscard]] std::unique_ptr<analysis> analyze(std::unique_ptr<source_file> source, const check_options& options);

struct checked_file {
  file_report report;
  std::optional<std::string> io_error;  // set when the file could not be read
};

// The whole front end on one file: read, parse, check, then the user's
// severity policy. Safe to call from several threads at once.
[[nodiscard]] checked_file check_file(const std::string& path, const check_options& options);
// The same on bytes already read (standard input) or mapped: a mapped file
// that shrank while it was checked is reported as such, with no findings.
[[nodiscard]] checked_file check_source(std::unique_ptr<source_file> source, const check_options& options);

}  // namespace edsc
