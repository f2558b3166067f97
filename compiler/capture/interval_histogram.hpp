#pragma once
// The intervals between a connection's frames, kept in a fixed number of
// buckets (exact below 128 us, then 64 per power of two: under 1 % off), so
// a connection watched for days takes the same memory as one watched for a
// second. The largest interval is kept exactly, with where it ended.
#include <array>
#include <cstdint>

namespace edsc::capture {

class interval_histogram {
 public:
  void add(std::uint64_t us, std::uint64_t frame);

  [[nodiscard]] std::uint64_t count() const { return count_; }
  // The interval at the q-th quantile (0 < q <= 1): the middle of its bucket
  // (the exact value below 128 us), kept within the least and the largest
  // interval seen, so a steady interval reads exactly. 0 when nothing was added.
  [[nodiscard]] std::uint64_t quantile(double q) const;
  [[nodiscard]] std::uint64_t worst() const { return worst_; }
  [[nodiscard]] std::uint64_t worst_frame() const { return worst_frame_; }  // the frame that ended it

  static constexpr std::size_t bucket_count = 128 + 64 * 57;
  [[nodiscard]] static std::size_t bucket_of(std::uint64_t us);
  [[nodiscard]] static std::uint64_t middle_of(std::size_t bucket);

 private:
  std::array<std::uint32_t, bucket_count> counts_{};
  std::uint64_t count_ = 0;
  std::uint64_t least_ = 0;
  std::uint64_t worst_ = 0;
  std::uint64_t worst_frame_ = 0;
};

}  // namespace edsc::capture
