#include "cip/stream_framer.hpp"

#include <algorithm>

#include "cip/encap.hpp"

namespace edsc::cip {

namespace {

// The header's length field (bytes 2-3, little-endian).
std::size_t announced(const bytes& b) { return static_cast<std::size_t>(b[2] | (b[3] << 8)); }

}  // namespace

std::size_t stream_framer::wanted() const {
  if (buf_.size() < encap_header_size) return encap_header_size;
  return encap_header_size + announced(buf_);
}

result<std::optional<bytes>, framing_error> stream_framer::next() {
  if (buf_.size() < encap_header_size) return std::optional<bytes>{};
  const auto length = announced(buf_);
  if (length > max_data_) return fail(framing_error{framing_error::kind::length_over_bound, length, max_data_});
  const auto total = encap_header_size + length;
  if (buf_.size() < total) return std::optional<bytes>{};
  bytes msg(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(total));
  buf_.erase(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(total));
  return std::optional<bytes>{std::move(msg)};
}

}  // namespace edsc::cip
