#pragma once
// Counted words and articles for every message edsc prints, so that "1
// entry", "2 entries" and "an EDS file" are right everywhere: no message
// spells a plural or an article by hand.
#include <cstddef>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace edsc {

// "1 error", "2 errors": the regular English plural (word + "s").
[[nodiscard]] inline std::string plural(std::size_t n, std::string_view word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

// "1 entry", "3 entries": a word whose plural is not word + "s".
[[nodiscard]] inline std::string plural(std::size_t n, std::string_view one, std::string_view many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

// The word alone, without its count: "byte" or "bytes".
[[nodiscard]] inline std::string_view noun(std::size_t n, std::string_view one, std::string_view many) {
  return n == 1 ? one : many;
}

// "a" or "an" before `words`, by how they are read aloud: "an EDS file", "an
// 8-bit value", "an error", "a UINT", "a DeviceNet node". Letters spelt out
// (the first two are capitals) take "an" when their name starts with a
// vowel sound (A, E, F, H, I, L, M, N, O, R, S, X); a word on "u" takes
// "an" (an unknown, an unsigned) unless it is read "you" (a unit, a user).
[[nodiscard]] inline std::string_view article(std::string_view words) {
  if (words.empty()) return "a";
  const char c = words[0];
  const bool spelt = words.size() > 1 && c >= 'A' && c <= 'Z' && words[1] >= 'A' && words[1] <= 'Z';
  if (spelt) return std::string_view("AEFHILMNORSX").find(c) != std::string_view::npos ? "an" : "a";
  // Eight, eleven, eighteen: "an 8-bit", "an 11-bit", "an 18 mm" (not "a 110").
  const bool teen =
      (words.starts_with("11") || words.starts_with("18")) && (words.size() == 2 || words[2] < '0' || words[2] > '9');
  if (c == '8' || teen) return "an";
  if (c == 'u' || c == 'U') {
    for (const std::string_view you : {"uni", "use", "usu", "uti", "Uni", "Use", "Usu", "Uti"})
      if (words.starts_with(you)) return "a";
    return "an";
  }
  return std::string_view("aeioAEIO").find(c) != std::string_view::npos ? "an" : "a";
}

// `words` after its article: "an EDS file".
[[nodiscard]] inline std::string with_article(std::string_view words) {
  return fmt::format("{} {}", article(words), words);
}

}  // namespace edsc
