#pragma once
#include <string>
#include <string_view>

#include "schema/text.hpp"

namespace edsc {

// Section names and keywords compare case-insensitively (a published file
// writes [variant_io_info]); this is the folded key.
[[nodiscard]] inline std::string fold_name(std::string_view name) {
  std::string out(name);
  for (auto& c : out) c = schema::ascii_lower(c);
  return out;
}

}  // namespace edsc
