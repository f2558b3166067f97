#pragma once
// Escaping for everything `edsc doc` writes: an EDS string is text, never markup.
#include <string>
#include <string_view>

namespace edsc::doc {

// HTML/XML text and attribute values: & < > " ' become references; control
// characters other than tab and line breaks (not allowed in XML) are dropped.
void append_escaped(std::string& out, std::string_view text);
[[nodiscard]] std::string escaped(std::string_view text);

// Markdown table cells and inline text: HTML-escaped, and the characters
// Markdown gives meaning to (| * _ ` [ ] < > # \) backslash-escaped or
// replaced; line breaks become <br>.
[[nodiscard]] std::string md_escaped(std::string_view text);

// A file name as a relative link (href, Markdown link): every byte but the
// unreserved ones of RFC 3986 (letters, digits, - . _ ~) percent-encoded, so
// '#', '?', '%', ':', '\\', spaces, line breaks and bytes that are not UTF-8
// all reach the file system as the name has them.
[[nodiscard]] std::string url_escaped(std::string_view name);

// Appends `item` to the list in `out`, `sep` between items.
inline void join(std::string& out, std::string_view sep, std::string_view item) {
  if (!out.empty()) out += sep;
  out += item;
}

}  // namespace edsc::doc
