#pragma once
// The LSP base protocol: each message is a header part ("Content-Length: N",
// optionally "Content-Type: ...", each line ending in CRLF), an empty line,
// then N bytes of JSON.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace edsc::lsp {

// Larger messages are refused (the body is skipped): edsc reads EDS files of
// at most 256 MiB, and a document travels JSON-escaped.
inline constexpr std::size_t max_message_bytes = 512u * 1024 * 1024;
inline constexpr std::size_t max_header_bytes = 64u * 1024;

// Reads up to `n` bytes into `buf`; 0 means end of input.
using read_fn = std::function<std::size_t(char* buf, std::size_t n)>;

struct frame {
  enum class kind { message, bad_header, end } what = kind::end;
  // kind::message: the bytes in the reader's buffer, valid until its next
  // next(): a document's text arrives in one message of up to hundreds of
  // kilobytes, and the server only decodes it.
  std::string_view body;
  std::string error;  // kind::bad_header: what was wrong (the header was skipped)
};

// Splits a byte stream into message bodies. A bad header (no or an invalid
// Content-Length, a header part too long) is reported and skipped, and
// reading goes on after it, so one broken message does not end the session.
class frame_reader {
 public:
  explicit frame_reader(read_fn read) : read_(std::move(read)) {}

  [[nodiscard]] frame next();
  // Bytes already read and not yet handed out: the next message may be here.
  [[nodiscard]] bool buffered() const { return pos_ < end_; }

 private:
  std::optional<frame> next_or_blank();  // nullopt: skipped blank lines
  // Reads once into room for at least `want` more bytes; false at end of
  // input. Moves the pending bytes (not their offsets from pos_).
  bool fill(std::size_t want = 65536);
  std::string_view pending() const { return {buf_.get() + pos_, end_ - pos_}; }

  read_fn read_;
  // Bytes are read straight into place: [pos_, end_) are read and not yet
  // handed out, [end_, capacity_) is room.
  std::unique_ptr<char[]> buf_;
  std::size_t capacity_ = 0;
  std::size_t pos_ = 0;
  std::size_t end_ = 0;
  bool eof_ = false;
};

// The framed bytes of one message.
[[nodiscard]] std::string frame_message(std::string_view body);

}  // namespace edsc::lsp
