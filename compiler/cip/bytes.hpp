#pragma once
// Little-endian bytes for the CIP wire format: an appending writer and a
// bounds-checked reader whose failures are located values, never exceptions.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "base/result.hpp"

namespace edsc::cip {

using bytes = std::vector<std::uint8_t>;
using byte_view = std::span<const std::uint8_t>;

// Where a decode stopped and why; `offset` counts from the start of the
// message the caller handed in (the encapsulation header, the UDP payload).
struct decode_error {
  std::size_t offset = 0;
  std::string what;
};

// A decoded value or the reason it could not be decoded.
template <class T>
using decoded = edsc::result<T, decode_error>;

// Why an encoder refused: the length or count it was handed does not fit the
// field that carries it on the wire (a frame is never sent truncated).
struct encode_error {
  std::string field;       // "encapsulation length", "request path size"
  std::size_t length = 0;  // what was asked, in the field's unit
  std::size_t limit = 0;   // the most the field holds
  [[nodiscard]] std::string what() const;
};
// An encoded message or why it cannot be sent.
using encoded = edsc::result<bytes, encode_error>;

// `length` when it is at most `limit` (the field's largest value), else the
// error naming `field`.
template <class Int>
[[nodiscard]] edsc::result<Int, encode_error> fit(std::size_t length, std::size_t limit, const char* field) {
  if (length > limit) return fail(encode_error{field, length, limit});
  return static_cast<Int>(length);
}

inline void put_u8(bytes& b, std::uint8_t v) { b.push_back(v); }
inline void put_u16(bytes& b, std::uint16_t v) {
  b.push_back(static_cast<std::uint8_t>(v));
  b.push_back(static_cast<std::uint8_t>(v >> 8));
}
inline void put_u32(bytes& b, std::uint32_t v) {
  put_u16(b, static_cast<std::uint16_t>(v));
  put_u16(b, static_cast<std::uint16_t>(v >> 16));
}
inline void put_bytes(bytes& b, byte_view v) { b.insert(b.end(), v.begin(), v.end()); }

// Reads fields in order; the first short read fails the reader, later reads
// return zeros, and error() says which field was cut and where.
class reader {
 public:
  explicit reader(byte_view b, std::size_t base = 0) : b_(b), base_(base) {}

  std::uint8_t u8(const char* field) {
    if (!need(1, field)) return 0;
    return b_[pos_++];
  }
  std::uint16_t u16(const char* field) {
    if (!need(2, field)) return 0;
    const auto v = static_cast<std::uint16_t>(b_[pos_] | (b_[pos_ + 1] << 8));
    pos_ += 2;
    return v;
  }
  std::uint32_t u32(const char* field) {
    if (!need(4, field)) return 0;
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | b_[pos_ + static_cast<std::size_t>(i)];
    pos_ += 4;
    return v;
  }
  // Big-endian, for the sockaddr of ListIdentity (network byte order).
  std::uint16_t be16(const char* field) {
    if (!need(2, field)) return 0;
    const auto v = static_cast<std::uint16_t>((b_[pos_] << 8) | b_[pos_ + 1]);
    pos_ += 2;
    return v;
  }
  byte_view take(std::size_t n, const char* field) {
    if (!need(n, field)) return {};
    const auto v = b_.subspan(pos_, n);
    pos_ += n;
    return v;
  }
  byte_view rest() {
    const auto v = b_.subspan(pos_);
    pos_ = b_.size();
    return v;
  }

  [[nodiscard]] bool ok() const { return !failed_; }
  [[nodiscard]] std::size_t offset() const { return base_ + pos_; }
  [[nodiscard]] std::size_t remaining() const { return b_.size() - pos_; }
  [[nodiscard]] const decode_error& error() const { return error_; }
  // Fails the reader with a reason of the caller's (a value out of range).
  decode_error fail(std::string what) {
    if (!failed_) {
      failed_ = true;
      error_ = {base_ + pos_, std::move(what)};
    }
    return error_;
  }

 private:
  bool need(std::size_t n, const char* field);

  byte_view b_;
  std::size_t base_ = 0, pos_ = 0;
  bool failed_ = false;
  decode_error error_;
};

}  // namespace edsc::cip
