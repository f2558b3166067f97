#include "capture/interval_histogram.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace edsc::capture {

std::size_t interval_histogram::bucket_of(std::uint64_t us) {
  if (us < 128) return static_cast<std::size_t>(us);
  // us >> shift lies in [64, 128): its six low bits pick one of 64 buckets.
  const auto shift = static_cast<unsigned>(std::bit_width(us)) - 7;
  return 128 + 64 * (shift - 1) + static_cast<std::size_t>((us >> shift) - 64);
}

std::uint64_t interval_histogram::middle_of(std::size_t bucket) {
  if (bucket < 128) return bucket;
  const auto shift = static_cast<unsigned>((bucket - 128) / 64) + 1;
  const std::uint64_t low = (64 + (bucket - 128) % 64) << shift;
  return low + (std::uint64_t{1} << shift) / 2;
}

void interval_histogram::add(std::uint64_t us, std::uint64_t frame) {
  auto& n = counts_[bucket_of(us)];
  if (n < std::numeric_limits<std::uint32_t>::max()) ++n;  // a bucket saturates rather than wraps
  ++count_;
  if (us < least_ || count_ == 1) least_ = us;
  if (us > worst_ || count_ == 1) {
    worst_ = us;
    worst_frame_ = frame;
  }
}

std::uint64_t interval_histogram::quantile(double q) const {
  if (count_ == 0) return 0;
  // The rank of the q-th quantile, 1-based: the smallest value with at least
  // q of the intervals at or below it.
  const auto rank = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (std::size_t b = 0; b < bucket_count; ++b) {
    seen += counts_[b];
    if (seen >= rank && counts_[b] > 0) return std::clamp(middle_of(b), least_, worst_);
  }
  return worst_;
}

}  // namespace edsc::capture
