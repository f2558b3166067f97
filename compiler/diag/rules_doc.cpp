#include "diag/rules_doc.hpp"

#include <fmt/format.h>

namespace edsc {

namespace {

void fenced(std::string& out, std::string_view label, std::string_view code) {
  out += fmt::format("{}:\n\n```\n{}\n```\n\n", label, code);
}

}  // namespace

std::string render_rules_markdown() {
  std::string out =
      "# Diagnostics\n\n"
      "Generated from `compiler/diag/catalogue.def` by `edsc rules --markdown`;\n"
      "do not edit by hand (a test fails when this file is stale).\n\n"
      "Each id can be used with `-W<id>`, `-Wno-<id>`, `-Werror=<id>`; each group name\n"
      "with the same flags applies to all of its diagnostics. Diagnostics of the group\n"
      "`pedantic` are off unless `-Wpedantic` or their own `-W<id>` turns them on.\n\n"
      "Severities follow the policy in [severity.md](severity.md): an error only\n"
      "where the file is certainly wrong, and each error rule states its basis.\n\n"
      "| id | severity | group | summary |\n|---|---|---|---|\n";
  for (const auto& r : all_rules()) {
    out +=
        fmt::format("| [`{}`](#{}) | {} | {} | {} |\n", r.name, r.name, to_string(r.default_level), r.group, r.summary);
  }
  for (const auto& r : all_rules()) out += "\n" + render_rule_markdown(r);
  return out;
}

std::string render_rule_markdown(const rule_info& r) {
  std::string out = fmt::format("## {}\n\n", r.name);
  out += fmt::format("Default severity: {}. Group: `{}`.\n\n", to_string(r.default_level), r.group);
  if (const auto basis = basis_of(r.id); !basis.empty()) out += fmt::format("Basis: {}.\n\n", basis);
  out += fmt::format("{}\n\n", r.explanation);
  fenced(out, "Triggers it", r.bad);
  fenced(out, "Does not", r.good);
  out.pop_back();
  return out;
}

std::string render_rule_text(const rule_info& r) {
  return fmt::format("{} ({}, group {})\n  {}\n\n{}\n\nTriggers it:\n{}\n\nDoes not:\n{}\n", r.name,
                     to_string(r.default_level), r.group, r.summary, r.explanation, r.bad, r.good);
}

}  // namespace edsc
