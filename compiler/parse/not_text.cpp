#include "parse/not_text.hpp"

#include <array>
#include <cstring>

#include <fmt/format.h>

namespace edsc {

namespace {

bool starts_with(std::string_view bytes, std::string_view magic) { return bytes.substr(0, magic.size()) == magic; }

std::string_view encoding_of_bom(std::string_view b) {
  using namespace std::string_view_literals;
  // UTF-32 first: its little-endian mark begins with UTF-16's.
  if (starts_with(b, "\xFF\xFE\x00\x00"sv)) return "UTF-32LE";
  if (starts_with(b, "\x00\x00\xFE\xFF"sv)) return "UTF-32BE";
  if (starts_with(b, "\xFF\xFE"sv)) return "UTF-16LE";
  if (starts_with(b, "\xFE\xFF"sv)) return "UTF-16BE";
  return {};
}

// UTF-16 saved without a byte-order mark: ASCII text with a NUL beside every
// character. Judged on the first bytes, where an EDS starts with ASCII.
std::string_view bomless_utf16(std::string_view b) {
  const std::size_t n = std::min<std::size_t>(b.size() & ~std::size_t{1}, 64);
  if (n < 4) return {};
  std::size_t even_nul = 0, odd_nul = 0;
  for (std::size_t i = 0; i < n; ++i) (i % 2 == 0 ? even_nul : odd_nul) += b[i] == '\0' ? 1 : 0;
  if (odd_nul == n / 2 && even_nul == 0) return "UTF-16LE";
  if (even_nul == n / 2 && odd_nul == 0) return "UTF-16BE";
  return {};
}

struct magic {
  std::string_view bytes;
  std::string_view what;
};

// Formats a user may pass by mistake: a build's output, an archive of EDS
// files, a document or an icon instead of the text.
constexpr std::array<magic, 7> binary_magics{{
    {std::string_view("\x7F"
                      "ELF",
                      4),
     "an ELF executable or library"},
    {std::string_view("PK\x03\x04", 4), "a ZIP archive (unpack it and check the .eds files inside)"},
    {std::string_view("\x1F\x8B", 2), "a gzip archive (unpack it first)"},
    {std::string_view("MZ", 2), "a Windows executable"},
    {std::string_view("%PDF-", 5), "a PDF document"},
    {std::string_view("\x89PNG", 4), "a PNG image"},
    {std::string_view("\x00\x00\x01\x00", 4), "a Windows icon"},
}};

span first_byte(std::string_view b) { return {0, b.empty() ? 0u : 1u}; }

}  // namespace

std::optional<diagnostic> not_text(std::string_view bytes) {
  if (const auto enc = encoding_of_bom(bytes); !enc.empty()) {
    const auto family = enc.substr(0, 6);
    return make_diagnostic(family == "UTF-32" ? diag_id::input_utf32 : diag_id::input_utf16,
                           {0, enc.starts_with("UTF-32") ? 4u : 2u},
                           fmt::format("this file is {} (it starts with a byte-order mark); EDS files are "
                                       "ASCII, Latin-1 or UTF-8 text: convert it with "
                                       "`iconv -f {} -t UTF-8 FILE > FILE.utf8`",
                                       enc, family));
  }
  for (const auto& m : binary_magics) {
    // "MZ" alone is too short a proof on its own; a Windows executable also
    // holds NUL bytes, which the check below reports in the same words.
    if (starts_with(bytes, m.bytes) && (m.bytes.size() > 2 || std::memchr(bytes.data(), '\0', bytes.size())))
      return make_diagnostic(diag_id::input_binary, first_byte(bytes),
                             fmt::format("this is {}, not an EDS text file", m.what));
  }
  if (const auto enc = bomless_utf16(bytes); !enc.empty()) {
    return make_diagnostic(diag_id::input_utf16, first_byte(bytes),
                           fmt::format("this file looks like {} without a byte-order mark (a NUL byte beside "
                                       "every character); EDS files are ASCII, Latin-1 or UTF-8 text: convert "
                                       "it with `iconv -f {} -t UTF-8 FILE > FILE.utf8`",
                                       enc, enc));
  }
  if (const void* nul = std::memchr(bytes.data(), '\0', bytes.size())) {
    const auto at = static_cast<std::uint32_t>(static_cast<const char*>(nul) - bytes.data());
    return make_diagnostic(diag_id::input_nul_byte, {at, at + 1},
                           "NUL byte in input: this is not a text file, so nothing of it was read as EDS");
  }
  return std::nullopt;
}

}  // namespace edsc
