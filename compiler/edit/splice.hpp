#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "source/span.hpp"

namespace edsc::edit {

// One change to a buffer: replace `range` with `text` (an empty range inserts).
struct replacement {
  span range;
  std::string text;
};

// Applies non-overlapping replacements to `source` in one pass, from the end of
// the buffer to the start, so every range still refers to the original bytes.
// Returns nullopt when two ranges overlap (or two inserts share one offset):
// the caller decides which one wins.
[[nodiscard]] std::optional<std::string> apply_replacements(std::string_view source, std::vector<replacement> changes);

// The line ending a file uses: the most frequent of CRLF, LF and CR (LF for a
// file without any), so inserted lines match their neighbours.
[[nodiscard]] std::string_view dominant_eol(std::string_view text);

// Rewrites every line ending of `text` (CRLF, LF or CR) as `eol`.
[[nodiscard]] std::string with_eol(std::string_view text, std::string_view eol);

// Offsets of the physical line holding `offset`: its first byte and the byte
// of its line terminator (or the end of the buffer).
[[nodiscard]] std::uint32_t line_begin(std::string_view text, std::uint32_t offset);
[[nodiscard]] std::uint32_t line_end(std::string_view text, std::uint32_t offset);
// The offset just past the line terminator at `end` (== end at end of buffer).
[[nodiscard]] std::uint32_t after_eol(std::string_view text, std::uint32_t end);

// The blanks that start the line holding `offset`.
[[nodiscard]] std::string_view indentation(std::string_view text, std::uint32_t offset);

// True when only blanks stand between the start of its line and `offset`.
[[nodiscard]] bool starts_line(std::string_view text, std::uint32_t offset);

}  // namespace edsc::edit
