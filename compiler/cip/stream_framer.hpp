#pragma once
// Cuts a TCP byte stream into whole encapsulation messages (the 24-byte
// header and the `length` bytes it announces), whatever the reads' splits.
// The one framer of every TCP side: the client's session, the simulator's
// server and the test servers. It holds no socket: bytes go in by `feed`,
// messages come out of `next`.
#include <cstddef>
#include <optional>

#include "base/result.hpp"
#include "cip/bytes.hpp"

namespace edsc::cip {

// The most data bytes one message may announce: all a 16-bit length holds.
inline constexpr std::size_t max_encap_data = 0xFFFF;

// Why the stream cannot be cut further. After one, the stream has lost its
// message boundaries: the side reading it drops the connection.
struct framing_error {
  enum class kind { length_over_bound };
  kind what = kind::length_over_bound;
  std::size_t length = 0;  // the length the header announced
  std::size_t bound = 0;
};

class stream_framer {
 public:
  explicit stream_framer(std::size_t max_data = max_encap_data) : max_data_(max_data) {}

  void feed(byte_view b) { buf_.insert(buf_.end(), b.begin(), b.end()); }
  // The next whole message once all its bytes came, else nothing yet.
  [[nodiscard]] result<std::optional<bytes>, framing_error> next();
  // The message under way: the bytes of it that came, and how many it needs
  // (24 until its header is whole, then the header's and its data's).
  [[nodiscard]] std::size_t pending() const { return buf_.size(); }
  [[nodiscard]] std::size_t wanted() const;

 private:
  bytes buf_;
  std::size_t max_data_;
};

}  // namespace edsc::cip
