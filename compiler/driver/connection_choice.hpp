#pragma once
// The connection of an EDS a user names on the command line, for the
// commands that read one (`edsc connection`, `edsc explain --eds`): by its
// number or name, and the located diagnostics when the file has none or not
// that one.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"
#include "connections/settings.hpp"
#include "diag/diagnostic.hpp"
#include "parse/parser.hpp"
#include "source/source_file.hpp"

namespace edsc::driver::connection_choice {

// `3`, `Connection3` or a name (field 13, any case).
[[nodiscard]] bool names(const connections::connection_setting& s, std::string_view which);
// `Connection1 "Owner", Connection2 "Input Only"`: what the file has.
[[nodiscard]] std::string listed(const std::vector<connections::connection_setting>& all);
// A located diagnostic on standard error; returns exit_findings.
int report(const source_file& src, diag_id id, span where, std::string message);
// The syntax errors of a file whose connections cannot be read reliably,
// printed; true when there were some.
[[nodiscard]] bool report_syntax(const source_file& src, const diagnostics& diags);

// An EDS read for its connections: the text, the tree and model (which
// point into each other, so the whole stays where it was built), and every
// ConnectionN's settings.
struct connection_file {
  std::unique_ptr<source_file> src;
  parse_result parsed;
  model::device dev;
  std::vector<connections::connection_setting> all;
};
// `path` read, parsed and lowered, or the exit status after saying why: 2
// when it cannot be read, 1 (located) for text that is no EDS, syntax errors
// or no ConnectionN.
[[nodiscard]] result<std::unique_ptr<connection_file>, int> read_connections(const std::string& path);
// The connection `which` names in `f`, or exit 1 after a located diagnostic
// listing the ones it has.
[[nodiscard]] result<const connections::connection_setting*, int> pick(const connection_file& f,
                                                                       std::string_view which);

}  // namespace edsc::driver::connection_choice
