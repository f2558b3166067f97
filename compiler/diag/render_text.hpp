#pragma once
#include <string>
#include <string_view>

#include "diag/diagnostic.hpp"
#include "source/source_file.hpp"

namespace edsc {

struct text_style {
  bool color = false;
};

// Appends one diagnostic, compiler style:
//   path:line:col: error: message [id]
//      12 |     Input1 = 1, 6, 0x0006, "Sensor", 6 "20 04 24 01 30 03";
//         |                                       ^
//         |                                       ,
// then its notes the same way.
void render_text(const source_file& src, const diagnostic& d, const text_style& style, std::string& out);
// The same naming `shown_path` instead of the source's path: for findings in
// text that goes elsewhere (an edit's result, located in its output).
void render_text(const source_file& src, std::string_view shown_path, const diagnostic& d, const text_style& style,
                 std::string& out);

}  // namespace edsc
