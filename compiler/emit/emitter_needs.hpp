#pragma once
// What `edsc header`, `header --stack opener` and `edsc sim` take from an EDS,
// and which of the file's errors touch it: those make the command refuse the
// file (exit 1, nothing written or served) instead of building from one of
// two values the file gives.
#include "cst/cst.hpp"
#include "diag/diagnostic.hpp"

namespace edsc::emit {

enum class emitter { header, opener_stack, simulator };

// The errors of `diags` (the file's `edsc check` findings) located in an
// entry `who` reads, or naming a section it reads written twice.
[[nodiscard]] diagnostics errors_touching(const cst::tree& tree, const diagnostics& diags, emitter who);

}  // namespace edsc::emit
