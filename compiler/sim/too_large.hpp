#pragma once
// Internal to the simulator: the `too-large` event, logged when a reply or a
// frame does not fit the length field that would carry it and so is not
// sent cut (the TCP connection of a CIP reply is closed, a class 1
// connection whose frames cannot be sent is closed).
#include <fmt/format.h>

#include "cip/bytes.hpp"
#include "sim/objects.hpp"

namespace edsc::sim {

inline void log_too_large(state& s, const char* what, const cip::encode_error& e) {
  log_event(
      s, "too-large",
      fmt::format("\"what\":\"{}\",\"field\":\"{}\",\"length\":{},\"limit\":{}", what, e.field, e.length, e.limit));
}

}  // namespace edsc::sim
