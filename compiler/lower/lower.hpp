#pragma once
#include "cst/cst.hpp"
#include "diag/diagnostic.hpp"
#include "model/device.hpp"

namespace edsc {

// Lowers a syntax tree into the typed device model, driven by the schema
// (compiler/schema/). Never throws and never drops data: entries outside the
// schema land in device::unknown, values that do not fit their type are kept
// as invalid values with their raw text. Lowering reports no validation
// findings (that is the checker's job); `diags` is reserved for that and left
// untouched today. Should memory run out, device::incomplete is set.
[[nodiscard]] model::device lower(const cst::tree& tree, diagnostics& diags);

}  // namespace edsc
