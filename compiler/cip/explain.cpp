// The statuses of cip/codes.def with their cause and EDS columns, looked up
// by code, and codes as a person lists them read into explanations.
#include "cip/explain.hpp"

#include <fmt/format.h>

namespace edsc::cip {

namespace {

#define GENERAL_STATUS(sym, code, words, cause, eds) {status_kind::general, code, words, cause, eds},
#define EXTENDED_STATUS(sym, code, words, cause, eds) {status_kind::extended, code, words, cause, eds},
constexpr status_explanation statuses[] = {
#include "cip/codes.def"
};

status_explanation look_up(status_kind kind, std::uint16_t c) {
  for (const auto& s : statuses)
    if (s.kind == kind && s.code == c) return s;
  return {kind, c, {}, {}, {}};
}

std::string named(const status_explanation& e) {
  return e.known() ? fmt::format("{} ({})", hex_of(e), e.words) : hex_of(e);
}

}  // namespace

status_explanation explain(general_status s) { return look_up(status_kind::general, code(s)); }
status_explanation explain(extended_status s) { return look_up(status_kind::extended, code(s)); }

std::vector<status_explanation> explain_status(std::uint8_t general, std::span<const std::uint16_t> additional) {
  std::vector<status_explanation> out{explain(general_status{general})};
  if (general_status{general} == general_status::connection_failure && !additional.empty())
    out.push_back(explain(extended_status{additional[0]}));
  return out;
}

std::string hex_of(const status_explanation& e) {
  return e.kind == status_kind::general ? fmt::format("0x{:02X}", e.code) : fmt::format("0x{:04X}", e.code);
}

std::string status_pair_error::what() const {
  return fmt::format("extended status {} follows general status {}, but an extended status comes only after {}",
                     hex_of(look_up(status_kind::extended, extended)), named(look_up(status_kind::general, general)),
                     named(explain(general_status::connection_failure)));
}

result<std::vector<status_explanation>, status_pair_error> explain_codes(std::span<const std::uint16_t> codes) {
  std::vector<status_explanation> out;
  for (std::size_t i = 0; i < codes.size(); ++i) {
    if (codes[i] <= 0xFF) {
      out.push_back(explain(general_status{static_cast<std::uint8_t>(codes[i])}));
      continue;
    }
    // Right after a general status, an extended one is that status's.
    const bool after_general = i > 0 && codes[i - 1] <= 0xFF;
    if (after_general && general_status{static_cast<std::uint8_t>(codes[i - 1])} != general_status::connection_failure)
      return fail(status_pair_error{codes[i - 1], codes[i]});
    out.push_back(explain(extended_status{codes[i]}));
  }
  return out;
}

}  // namespace edsc::cip
