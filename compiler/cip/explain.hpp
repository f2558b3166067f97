#pragma once
// A reply's status explained: its ODVA name, what usually causes it and what
// to look at in the EDS, all from the columns of cip/codes.def. `edsc
// explain` prints these; verify, sim and live can say the same words.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"
#include "cip/codes.hpp"

namespace edsc::cip {

enum class status_kind : std::uint8_t { general, extended };

struct status_explanation {
  status_kind kind = status_kind::general;
  std::uint16_t code = 0;
  std::string_view words;  // ODVA's name; empty: a code cip/codes.def lacks
  std::string_view cause;  // what usually brings it
  std::string_view eds;    // what to look at in the EDS; empty where the EDS plays no part
  [[nodiscard]] bool known() const { return !words.empty(); }
};

[[nodiscard]] status_explanation explain(general_status s);
[[nodiscard]] status_explanation explain(extended_status s);

// A reply's status: the general one and, under 0x01 (connection failure),
// the extended one, the first additional status word.
[[nodiscard]] std::vector<status_explanation> explain_status(std::uint8_t general,
                                                             std::span<const std::uint16_t> additional);

// "0x01", "0x0127": a general status in two hex digits, an extended one in four.
[[nodiscard]] std::string hex_of(const status_explanation& e);

// An extended status given after a general status other than 0x01.
struct status_pair_error {
  std::uint16_t general = 0, extended = 0;
  [[nodiscard]] std::string what() const;
};

// Codes as a person lists them: up to 0xFF a general status, above it an
// extended one, which is read with the general status right before it
// (that must be 0x01) or alone.
[[nodiscard]] result<std::vector<status_explanation>, status_pair_error> explain_codes(
    std::span<const std::uint16_t> codes);

}  // namespace edsc::cip
