#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace edsc {

// "1 error", "2 errors": every count a summary prints, so singulars are right
// everywhere. Regular English plurals only (the words counted are).
[[nodiscard]] inline std::string plural(std::size_t n, std::string_view word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

}  // namespace edsc
