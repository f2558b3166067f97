#pragma once
#include "cst/cst.hpp"
#include "diag/diagnostic.hpp"

namespace edsc {

struct parse_result {
  cst::tree tree;
  diagnostics diags;      // syntax diagnostics, in source order
  bool not_text = false;  // the input is not EDS text: one input diagnostic, an empty tree
};

// Parses one EDS file into its lossless tree. Never throws on any input: every
// problem becomes a diagnostic and the tree still covers every byte.
[[nodiscard]] parse_result parse(const source_file& src);

}  // namespace edsc
