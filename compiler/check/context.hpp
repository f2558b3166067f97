#pragma once
#include "cst/cst.hpp"
#include "diag/diagnostic.hpp"
#include "model/device.hpp"

namespace edsc {

// What every rule family sees: the lossless tree (syntax-level rules, exact
// spans), the typed model, the networks the file is checked for, and where to
// put findings.
struct check_context {
  const cst::tree& tree;
  const model::device& dev;
  std::uint8_t networks;  // model::network bits (detected, or --network)
  diagnostics& out;

  diagnostic& report(diag_id id, span where, std::string message) const {
    return out.emplace_back(make_diagnostic(id, where, std::move(message)));
  }
  diagnostic& report_with_note(diag_id id, span where, std::string message, span note_at, std::string note) const {
    auto& d = report(id, where, std::move(message));
    d.notes.push_back({note_at, std::move(note)});
    return d;
  }

  // Where to point for a value: the field itself, or its entry's keyword when
  // the field is absent, or the section header when the entry is.
  // A field exactly as written, for messages.
  [[nodiscard]] std::string_view raw(const model::value& v) const { return tree.text(v.from.where); }
  [[nodiscard]] span where(const model::value& v) const {
    if (!v.from.where.empty() || v.present()) return v.from.where;
    if (v.from.entry != model::none) return tree.entries[v.from.entry].keyword;
    return {};
  }
  [[nodiscard]] span entry_keyword(const model::origin& o) const {
    return o.entry != model::none ? tree.entries[o.entry].keyword : o.where;
  }
  [[nodiscard]] span section_name(std::uint32_t section) const {
    return section != model::none ? tree.sections[section].name : span{};
  }
  [[nodiscard]] bool devicenet() const { return (networks & model::net_devicenet) != 0; }
};

// Runs every registered rule family, in a fixed order.
void run_checks(const check_context& ctx);

}  // namespace edsc
