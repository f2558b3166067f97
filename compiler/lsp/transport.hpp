#pragma once
// The LSP base protocol: each message is a header part ("Content-Length: N",
// optionally "Content-Type: ...", each line ending in CRLF), an empty line,
// then N bytes of JSON.
#include <cstddef>
#include <functional>
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
  std::string body;   // kind::message
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
  [[nodiscard]] bool buffered() const { return pos_ < buf_.size(); }

 private:
  std::optional<frame> next_or_blank();  // nullopt: skipped blank lines
  bool fill();                           // false at end of input
  std::string_view pending() const { return std::string_view(buf_).substr(pos_); }

  read_fn read_;
  std::string buf_;
  std::size_t pos_ = 0;
  bool eof_ = false;
};

// The framed bytes of one message.
[[nodiscard]] std::string frame_message(std::string_view body);

}  // namespace edsc::lsp
