#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "cst/cst.hpp"
#include "edit/edit_error.hpp"
#include "edit/splice.hpp"
#include "source/source_file.hpp"

namespace edsc::edit {

// Targeted changes on the lossless tree. Each operation parses the current
// bytes, computes byte-range replacements and applies them, so every byte
// outside the edited fields stays as it was. Inserted lines use the file's
// own line ending and the indentation of their neighbours. An operation is
// refused with an edit_error (nothing changed) when an address or a value is
// wrong.
class editor {
 public:
  editor(std::string path, std::string text);

  // `Section.Keyword[.field]=value`; field by schema name or 1-based number.
  [[nodiscard]] edited set(std::string_view assignment);
  // `Section.Keyword=field, field, ...` at the end of an existing section.
  [[nodiscard]] edited add_entry(std::string_view assignment);
  [[nodiscard]] edited remove_entry(std::string_view path);
  // An empty section; [Device Classification] goes after [Device], others at the end.
  [[nodiscard]] edited add_section(std::string_view name);
  [[nodiscard]] edited remove_section(std::string_view name);
  // DeviceNet I/O resizing: `Input1=3` or `Output2=4:20` (size[:significant bits]).
  [[nodiscard]] edited resize(std::string_view spec);

  [[nodiscard]] const std::string& text() const { return text_; }
  [[nodiscard]] std::string_view eol() const { return eol_; }
  // One line per change and per adjustment made on the user's behalf.
  [[nodiscard]] const std::vector<std::string>& log() const { return log_; }

 private:
  // The operations above, throwing edit_error.
  void do_set(std::string_view assignment);
  void do_add_entry(std::string_view assignment);
  void do_remove_entry(std::string_view path);
  void do_add_section(std::string_view name);
  void do_remove_section(std::string_view name);
  void do_resize(std::string_view spec);
  void reparse();
  void commit(std::vector<replacement> changes);
  // Where a new line belongs after the last entry of `section` (or its header).
  [[nodiscard]] std::uint32_t end_of_section_content(std::uint32_t section) const;
  [[nodiscard]] std::string entry_indent(std::uint32_t section) const;
  [[nodiscard]] std::string insert_entry_text(std::uint32_t section, std::string_view keyword,
                                              std::string_view body) const;
  [[nodiscard]] replacement new_section(std::string_view name, std::string_view first_entry) const;
  [[nodiscard]] replacement field_change(std::uint32_t entry, std::uint32_t index, std::string value) const;
  [[nodiscard]] replacement keep_comment_column(span where, std::string value) const;

  std::string path_;
  std::string text_;
  std::string eol_;
  std::unique_ptr<source_file> src_;
  cst::tree tree_;
  std::vector<std::string> log_;
};

}  // namespace edsc::edit
