#include "cip/status.hpp"

#include <fmt/format.h>

#include "cip/codes.hpp"

namespace edsc::cip {

namespace {

std::string code_and_text(std::string_view hex, std::string_view text) {
  return text.empty() ? fmt::format("{} (unknown code)", hex) : fmt::format("{} {}", hex, text);
}

#define IDENTITY_BIT(sym, mask, words) identity_bit::sym,
constexpr identity_bit identity_bits[] = {
#include "cip/codes.def"
};

}  // namespace

std::string describe_status(std::uint8_t general, std::span<const std::uint16_t> additional) {
  auto out = code_and_text(fmt::format("0x{:02X}", general), words_of(general_status{general}));
  if (additional.empty()) return out;
  // The extended status is the first additional word only under general
  // 0x01; elsewhere the words are object-specific and shown as numbers.
  std::size_t i = 0;
  if (general_status{general} == general_status::connection_failure) {
    out +=
        ", extended " + code_and_text(fmt::format("0x{:04X}", additional[0]), words_of(extended_status{additional[0]}));
    i = 1;
  }
  if (i < additional.size()) {
    out += " (additional";
    for (; i < additional.size(); ++i) out += fmt::format(" 0x{:04X}", additional[i]);
    out += ")";
  }
  return out;
}

std::string describe_identity_status(std::uint16_t status) {
  std::string out = fmt::format("0x{:04X}", status);
  std::string words;
  const auto add = [&](std::string_view w) { words += fmt::format("{}{}", words.empty() ? "" : ", ", w); };
  for (const auto b : identity_bits)
    if (status & code(b)) add(words_of(b));
  if (const auto state = words_of(device_state_of(status)); !state.empty()) add(state);
  return words.empty() ? out : fmt::format("{} ({})", out, words);
}

std::uint16_t extended_of(std::uint8_t general, std::span<const std::uint16_t> additional) {
  return general == code(general_status::connection_failure) && !additional.empty() ? additional[0] : 0;
}

const char* busy_reason(std::uint8_t general, std::uint16_t extended) {
  if (general != code(general_status::connection_failure)) return nullptr;
  switch (extended_status{extended}) {
    case extended_status::connection_in_use: return "a connection with the same identity is already open";
    case extended_status::ownership_conflict: return "another scanner owns what it connects to";
    case extended_status::out_of_connections: return "the device has no connection free";
    default: return nullptr;
  }
}

}  // namespace edsc::cip
