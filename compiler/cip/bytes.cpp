#include "cip/bytes.hpp"

#include <fmt/format.h>

#include "base/plural.hpp"

namespace edsc::cip {

bool reader::need(std::size_t n, const char* field) {
  if (failed_) return false;
  if (b_.size() - pos_ >= n) return true;
  fail(fmt::format("{} cut short: {} needed, {} left", field, plural(n, "byte"), b_.size() - pos_));
  return false;
}

std::string encode_error::what() const {
  return fmt::format("{} of {} does not fit its field: at most {}", field, length, limit);
}

}  // namespace edsc::cip
