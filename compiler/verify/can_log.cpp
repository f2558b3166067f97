#include "verify/can_log.hpp"

#include <cctype>

#include <fmt/format.h>

namespace edsc::verify {

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_ws(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    const auto start = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

// An identifier in hex, with or without 0x; false when not hex or too long.
bool parse_id(std::string_view s, can_frame& f) {
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) s.remove_prefix(2);
  if (s.empty() || s.size() > 8) return false;
  std::uint32_t v = 0;
  for (const char c : s) {
    const int d = hex_digit(c);
    if (d < 0) return false;
    v = v * 16 + static_cast<std::uint32_t>(d);
  }
  // candump writes 29-bit identifiers with 8 digits, 11-bit ones with 3.
  f.extended = s.size() == 8 || v > 0x7FF;
  if (f.extended && v > 0x1FFFFFFF) return false;
  f.id = v;
  return true;
}

// Hex bytes, packed ("000E01") or separated by spaces ("00 0E 01").
std::optional<std::string> parse_bytes(std::string_view s, std::vector<std::uint8_t>& out) {
  int high = -1;
  for (const char c : s) {
    if (c == ' ' || c == '\t') {
      if (high >= 0) return "a data byte has one hex digit";
      continue;
    }
    const int d = hex_digit(c);
    if (d < 0) return fmt::format("'{}' is not a hex digit", c);
    if (high < 0) {
      high = d;
    } else {
      out.push_back(static_cast<std::uint8_t>(high * 16 + d));
      high = -1;
    }
  }
  if (high >= 0) return "the data has an odd number of hex digits";
  if (out.size() > 8) return fmt::format("{} data bytes; a classic CAN frame holds at most 8", out.size());
  return std::nullopt;
}

// `(1699999999.123456) can0 44C#000E010101`, the -l and -L formats.
std::optional<std::string> read_candump_log(std::string_view line, can_frame& f) {
  const auto close = line.find(')');
  if (close == std::string_view::npos) return "no ')' after the timestamp";
  const auto stamp = line.substr(1, close - 1);
  try {
    std::size_t used = 0;
    f.time = std::stod(std::string(stamp), &used);
    if (used != stamp.size()) return fmt::format("'{}' is not a timestamp", stamp);
  } catch (const std::exception&) {
    return fmt::format("'{}' is not a timestamp", stamp);
  }
  const auto words = split_ws(line.substr(close + 1));
  if (words.size() != 2) return "expected '(time) interface id#data'";
  const auto frame = words[1];
  const auto hash = frame.find('#');
  if (hash == std::string_view::npos) return fmt::format("'{}' has no '#' between identifier and data", frame);
  if (!parse_id(frame.substr(0, hash), f)) return fmt::format("'{}' is not a CAN identifier", frame.substr(0, hash));
  auto data = frame.substr(hash + 1);
  if (!data.empty() && data[0] == '#') return "a CAN FD frame (##); DeviceNet uses classic CAN";
  if (!data.empty() && (data[0] == 'R' || data[0] == 'r')) {
    f.remote = true;
    return std::nullopt;
  }
  std::string cleaned;  // candump -L may separate bytes with '.'
  for (const char c : data)
    if (c != '.') cleaned += c;
  return parse_bytes(cleaned, f.data);
}

// `can0  44C   [5]  00 0E 01 01 01`, candump's default screen output.
std::optional<std::string> read_candump_screen(const std::vector<std::string_view>& words, can_frame& f) {
  if (!parse_id(words[1], f)) return fmt::format("'{}' is not a CAN identifier", words[1]);
  const auto len = words[2].substr(1, words[2].size() - 2);
  if (len == "R" || len.empty()) return "a length written as '[...]' is expected";
  std::string bytes;
  for (std::size_t i = 3; i < words.size(); ++i) bytes += std::string(words[i]) + " ";
  if (auto err = parse_bytes(bytes, f.data)) return err;
  if (std::to_string(f.data.size()) != len) return fmt::format("[{}] bytes announced, {} given", len, f.data.size());
  return std::nullopt;
}

// `step <TAB> dir <TAB> can_id <TAB> data`.
std::optional<std::string> read_tsv(std::string_view line, can_frame& f) {
  std::vector<std::string_view> cols;
  for (std::size_t start = 0;;) {
    const auto tab = line.find('\t', start);
    cols.push_back(trim(line.substr(start, tab == std::string_view::npos ? tab : tab - start)));
    if (tab == std::string_view::npos) break;
    start = tab + 1;
  }
  if (cols.size() < 3 || cols.size() > 4) return "expected step, dir, can_id and data separated by tabs";
  if (cols[1] != "M" && cols[1] != "S") return fmt::format("dir '{}' is neither M (master) nor S (slave)", cols[1]);
  f.dir = cols[1][0];
  if (!parse_id(cols[2], f)) return fmt::format("'{}' is not a CAN identifier", cols[2]);
  return cols.size() == 4 ? parse_bytes(cols[3], f.data) : std::nullopt;
}

}  // namespace

can_log read_can_log(std::string_view text) {
  can_log log;
  std::uint32_t line_no = 0;
  for (std::size_t start = 0; start < text.size();) {
    auto end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    ++line_no;
    auto raw = text.substr(start, end - start);
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    const span where{static_cast<std::uint32_t>(start), static_cast<std::uint32_t>(start + raw.size())};
    start = end + 1;
    const auto line = trim(raw);
    if (line.empty() || line[0] == '#' || line.rfind("step\t", 0) == 0) continue;
    can_frame f;
    f.line = line_no;
    f.where = where;
    std::optional<std::string> err;
    const auto words = split_ws(line);
    if (line[0] == '(') {
      err = read_candump_log(line, f);
    } else if (line.find('\t') != std::string_view::npos && words.size() >= 3 && words[1].size() == 1) {
      err = read_tsv(line, f);
    } else if (words.size() >= 3 && words[2].size() >= 2 && words[2].front() == '[' && words[2].back() == ']') {
      err = read_candump_screen(words, f);
    } else {
      err = "not a candump (-l, -L or screen) line nor a step/dir/can_id/data TSV row";
    }
    if (err)
      log.problems.push_back({line_no, where, std::move(*err)});
    else
      log.frames.push_back(std::move(f));
  }
  return log;
}

}  // namespace edsc::verify
