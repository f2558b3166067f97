#include "lsp/transport.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>

namespace edsc::lsp {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

// The Content-Length of a header part (lines separated by LF or CRLF), or an
// error message.
bool content_length(std::string_view header, std::size_t& length, std::string& error) {
  bool found = false;
  while (!header.empty()) {
    const auto eol = header.find('\n');
    const auto line = trim(header.substr(0, eol));
    header.remove_prefix(eol == std::string_view::npos ? header.size() : eol + 1);
    const auto colon = line.find(':');
    if (colon == std::string_view::npos) {
      error = "header line without ':'";
      return false;
    }
    if (!iequals(trim(line.substr(0, colon)), "Content-Length")) continue;  // Content-Type and the like
    const auto value = trim(line.substr(colon + 1));
    std::size_t n = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc{} || end != value.data() + value.size() || value.empty()) {
      error = "Content-Length is not a number";
      return false;
    }
    length = n;
    found = true;
  }
  if (!found) error = "no Content-Length header";
  return found;
}

}  // namespace

bool frame_reader::fill(std::size_t want) {
  if (eof_) return false;
  const std::size_t pending_bytes = end_ - pos_;
  if (capacity_ - end_ < want) {
    // Drop what was handed out; grow when that does not make the room.
    const std::size_t needed = pending_bytes + want;
    if (needed > capacity_) {
      const std::size_t grown = std::max(needed, capacity_ * 2);
      auto bigger = std::make_unique_for_overwrite<char[]>(grown);
      std::copy_n(buf_.get() + pos_, pending_bytes, bigger.get());
      buf_ = std::move(bigger);
      capacity_ = grown;
    } else {
      std::copy_n(buf_.get() + pos_, pending_bytes, buf_.get());
    }
    pos_ = 0;
    end_ = pending_bytes;
  }
  const auto n = read_(buf_.get() + end_, capacity_ - end_);
  if (n == 0) {
    eof_ = true;
    return false;
  }
  end_ += n;
  return true;
}

frame frame_reader::next() {
  for (;;) {
    auto f = next_or_blank();
    if (f) return std::move(*f);
  }
}

std::optional<frame> frame_reader::next_or_blank() {
  // The header ends at the first empty line; clients send CRLF, LF is taken too.
  std::size_t header_end = 0, body_begin = 0;
  std::size_t searched = 0;
  for (;;) {
    const auto p = pending();
    for (std::size_t i = searched; i < p.size(); ++i) {
      if (p[i] != '\n') continue;
      if (i >= 1 && p[i - 1] == '\n') {
        header_end = i - 1;
        body_begin = i + 1;
        break;
      }
      if (i >= 2 && p[i - 1] == '\r' && p[i - 2] == '\n') {
        header_end = i - 2;
        body_begin = i + 1;
        break;
      }
    }
    if (body_begin > 0) break;
    searched = p.size();
    if (p.size() > max_header_bytes) {
      pos_ = end_;  // skip it all: there is no telling where the next message starts
      return frame{frame::kind::bad_header, {}, "header part longer than 64 KiB"};
    }
    if (!fill()) {
      const bool junk = !trim(pending()).empty() && pending().find_first_not_of("\r\n") != std::string_view::npos;
      pos_ = end_;
      return junk ? frame{frame::kind::bad_header, {}, "input ended inside a header"} : frame{};
    }
  }
  // A message may start after stray line breaks (some clients end bodies with one).
  auto header = pending().substr(0, header_end);
  while (!header.empty() && (header.front() == '\r' || header.front() == '\n')) header.remove_prefix(1);
  std::size_t length = 0;
  std::string error;
  if (header.empty()) {  // only line breaks: skip them
    pos_ += body_begin;
    return std::nullopt;
  }
  if (!content_length(header, length, error)) {
    pos_ += body_begin;
    return frame{frame::kind::bad_header, {}, error};
  }
  if (length > max_message_bytes) {
    pos_ += body_begin;
    // Skip the body as it arrives, without keeping it.
    while (length > 0) {
      const auto take = std::min(length, end_ - pos_);
      pos_ += take;
      length -= take;
      if (length > 0 && !fill()) break;
    }
    return frame{frame::kind::bad_header, {}, "message larger than 512 MiB"};
  }
  pos_ += body_begin;
  // The rest of the body is read into room made for all of it at once (up
  // to 64 MiB: a header's claim alone does not get more memory than that).
  while (end_ - pos_ < length) {
    if (!fill(std::min<std::size_t>(length - (end_ - pos_), 64u << 20))) {
      pos_ = end_;
      return frame{frame::kind::bad_header, {}, "input ended inside a message body"};
    }
  }
  frame f{frame::kind::message, pending().substr(0, length), {}};
  pos_ += length;
  return f;
}

std::string frame_message(std::string_view body) {
  std::string out = "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n";
  out += body;
  return out;
}

}  // namespace edsc::lsp
