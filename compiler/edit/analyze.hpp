#pragma once
#include <memory>
#include <string>

#include "check/check_file.hpp"
#include "cst/cst.hpp"
#include "diag/diagnostic.hpp"
#include "model/device.hpp"
#include "source/source_file.hpp"

namespace edsc::edit {

// The whole front end on bytes held in memory (an edit's result before it is
// written): the tree, the model and every diagnostic after the user's policy.
// Not movable: the tree and the model point into `source`.
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

[[nodiscard]] std::unique_ptr<analysis> analyze(std::string path, std::string bytes,
                                                const check_options& options = {});

}  // namespace edsc::edit
