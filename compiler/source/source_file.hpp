#pragma once
#include <atomic>
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
  std::uint32_t column = 1;  // 1-based, counted in bytes; a byte-order mark counts none
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
  // Bytes someone else holds (a mapped file): `owner` keeps them, and a NUL
  // after them, alive for as long as this source; `changed`, when given,
  // turns true should they stop being the file's (see changed()).
  source_file(std::string path, std::shared_ptr<const void> owner, std::string_view bytes,
              const std::atomic<bool>* changed = nullptr);

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] std::string_view text() const { return view_; }
  [[nodiscard]] std::string_view text(span s) const { return view_.substr(s.begin, s.size()); }
  [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(view_.size()); }
  // True when the file shrank under its mapping while it was read
  // (io/map_file.hpp): some bytes then read as zeros, and nothing made of
  // them is about the file.
  [[nodiscard]] bool changed() const { return changed_ != nullptr && changed_->load(std::memory_order_acquire); }

  [[nodiscard]] line_col position(std::uint32_t offset) const;
  // The physical line holding `line` (1-based), without its line terminator
  // (nor, on line 1, a byte-order mark).
  [[nodiscard]] std::string_view line_text(std::uint32_t line) const;
  [[nodiscard]] std::uint32_t line_count() const;

 private:
  void index_lines() const;

  std::string path_;
  std::string text_;                   // holds the bytes,
  std::shared_ptr<const void> owner_;  // or owns what holds them (a buffer, a mapping)
  std::string_view view_;              // of whichever does
  const std::atomic<bool>* changed_ = nullptr;
  mutable std::once_flag indexed_;
  mutable std::vector<std::uint32_t> line_starts_;
};

}  // namespace edsc
