#pragma once
// Internal to the datasheet builder: reading model values as display text.
#include <string>

#include "doc/markup.hpp"
#include "doc/sheet.hpp"

namespace edsc::doc::detail {

struct reader {
  const model::device& dev;
  const source_file& src;

  [[nodiscard]] std::uint32_t line(std::uint32_t offset) const { return src.position(offset).line; }
  [[nodiscard]] std::uint32_t line(const model::origin& o) const {
    return o.where.empty() && o.entry == model::none ? 0 : line(o.where.begin);
  }
  [[nodiscard]] std::uint32_t section_line(std::uint32_t section) const;
  // A value as a reader wants it: strings decoded, numbers as written, UTF-8.
  [[nodiscard]] std::string text(const model::value& v) const;
  // `Param5` (and its name when it resolves to a parameter).
  [[nodiscard]] std::string ref_text(const model::reference& r, bool with_name = true) const;
  // An EPATH in words: "class 0x04, instance 100, attribute 3".
  [[nodiscard]] std::string path_text(const model::value& v) const;
  [[nodiscard]] cell at(const model::value& v, cell_style style = cell_style::plain) const {
    return {text(v), line(v.from), style};
  }
};

[[nodiscard]] std::string utf8(std::string_view s);
[[nodiscard]] std::string trimmed(std::string_view s);  // UTF-8, without surrounding blanks
[[nodiscard]] std::string param_name(const model::device& dev, std::uint32_t target);

void build_params(const reader& r, sheet& s);
void build_maps(const reader& r, sheet& s);
void build_connections(const reader& r, sheet& s);

}  // namespace edsc::doc::detail
