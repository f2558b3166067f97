#pragma once
// A string's length in a message, in the unit the limit it is held to is
// defined in: device strings of one byte per character count bytes, and say
// how many characters those are when UTF-8 makes the two differ.
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "base/utf8.hpp"

namespace edsc {

// "33 bytes", or "33 bytes (32 characters)" for UTF-8 text.
[[nodiscard]] inline std::string byte_length(std::string_view text) {
  const auto chars = utf8::characters(text);
  return chars == text.size() ? plural(text.size(), "byte")
                              : fmt::format("{} ({})", plural(text.size(), "byte"), plural(chars, "character"));
}

}  // namespace edsc
