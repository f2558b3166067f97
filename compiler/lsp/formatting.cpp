// textDocument/formatting: the layout of `edsc fmt`, as one edit.
#include "edit/fingerprint.hpp"
#include "edit/format.hpp"
#include "lsp/convert.hpp"
#include "lsp/handlers.hpp"

namespace edsc::lsp {

json on_formatting(session& s, const json& params) {
  auto& d = s.analysed(params);
  // edsc fmt has one layout: the client's tabSize and insertSpaces do not apply.
  if (d.analysed->has_syntax_errors())
    throw rpc_error(error_code::request_failed, "edsc fmt: not formatted: fix the syntax errors first");
  const auto out = edit::format(d.analysed->tree, {});
  if (!out) throw rpc_error(error_code::request_failed, "edsc fmt: not formatted: " + out.error().why);
  const std::string_view before = d.analysed->text();
  if (*out == before) return json::array();
  // Layout only: an edit that changes the meaning is a bug and is withheld.
  if (!edit::means_the_same(*d.analysed, d.path, *out))
    throw rpc_error(error_code::internal_error, "edsc fmt: formatting would change the file's meaning");
  return json::array({minimal_edit(d, *out)});
}

}  // namespace edsc::lsp
