#pragma once
#include "cst/cst.hpp"
#include "diag/diagnostic.hpp"

namespace edsc {

// What every rule family sees: the lossless tree (for syntax-level rules and
// exact spans) and where to put its findings.
struct check_context {
  const cst::tree& tree;
  diagnostics& out;

  void report(diag_id id, span where, std::string message) const {
    out.push_back(make_diagnostic(id, where, std::move(message)));
  }
  diagnostic& report_with_note(diag_id id, span where, std::string message, span note_at,
                               std::string note) const {
    auto& d = out.emplace_back(make_diagnostic(id, where, std::move(message)));
    d.notes.push_back({note_at, std::move(note)});
    return d;
  }
};

// Runs every registered rule family, in a fixed order.
void run_checks(const check_context& ctx);

}  // namespace edsc
