#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "source/span.hpp"

namespace edsc {

struct line_col {
  std::uint32_t line = 1;    // 1-based
  std::uint32_t column = 1;  // 1-based, counted in bytes
};

// The bytes of one input file and its display path. Line starts are computed
// only when a diagnostic needs a line/column, never while parsing.
class source_file {
 public:
  source_file(std::string path, std::string text);
  // Bytes read straight into their final buffer: `bytes` holds `size` bytes
  // and a NUL after them (as std::string would), none of them zero-filled
  // first.
  source_file(std::string path, std::unique_ptr<char[]> bytes, std::size_t size);

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] std::string_view text() const { return view_; }
  [[nodiscard]] std::string_view text(span s) const { return view_.substr(s.begin, s.size()); }
  [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(view_.size()); }

  [[nodiscard]] line_col position(std::uint32_t offset) const;
  // The physical line holding `line` (1-based), without its line terminator.
  [[nodiscard]] std::string_view line_text(std::uint32_t line) const;
  [[nodiscard]] std::uint32_t line_count() const;

 private:
  void index_lines() const;

  std::string path_;
  std::string text_;               // one of these two holds the bytes
  std::unique_ptr<char[]> bytes_;
  std::string_view view_;          // of whichever does
  mutable std::once_flag indexed_;
  mutable std::vector<std::uint32_t> line_starts_;
};

}  // namespace edsc
