#pragma once
#include <string>
#include <string_view>

namespace edsc {

// Section names and keywords compare case-insensitively (a published file
// writes [variant_io_info]); this is the folded key.
[[nodiscard]] inline std::string fold_name(std::string_view name) {
  std::string out(name);
  for (auto& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

// The same equality without a folded copy.
[[nodiscard]] constexpr char fold_char(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }
[[nodiscard]] inline bool folded_equal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (fold_char(a[i]) != fold_char(b[i])) return false;
  return true;
}

}  // namespace edsc
