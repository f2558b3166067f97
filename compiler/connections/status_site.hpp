#pragma once
// What a Connection Manager status says of one ConnectionN: the EDS field it
// points at and the numbers the EDS gives there ("the device accepts 34 bytes
// O->T; the EDS says 32 + 2 sequence + 4 run/idle = 38"), for `edsc explain
// --eds FILE --connection N`. The numbers are the settings `edsc connection`
// prints (connections/settings.hpp), so they are what a scanner configured
// from the EDS sends.
#include <cstdint>
#include <optional>
#include <string>

#include "cip/codes.hpp"
#include "connections/settings.hpp"
#include "source/source_file.hpp"

namespace edsc::connections {

struct status_site {
  span where;         // the field; the entry where the field is empty
  std::string field;  // "Connection1 field 4, O->T size"; "[Device] ProdCode"
  std::string words;  // the EDS's numbers, and the device's where the reply gives them
};

// The statuses whose reply carries a second additional word edsc reads: the
// size the device accepts (0x0126 configuration, 0x0127 O->T, 0x0128 T->O).
[[nodiscard]] bool takes_accepted_size(cip::extended_status status);

// Where `status` points in the EDS for the connection `s`, with `accepted`
// the reply's second additional word (takes_accepted_size); none where the
// EDS plays no part in the status. `src`, where given, adds the lines of the
// fields the words name (an RPI parameter's). `edsc explain --eds` and
// `verify --live` both say a refusal with it.
[[nodiscard]] std::optional<status_site> status_site_of(const model::device& dev, const source_file* src,
                                                        const connection_setting& s, cip::extended_status status,
                                                        std::optional<std::uint16_t> accepted);

}  // namespace edsc::connections
