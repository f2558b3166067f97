#pragma once
// Internal to the simulator: the objects a request reaches after its path
// is read, and the JSON lines they log.
#include <cstdint>
#include <string>

#include "cip/request.hpp"
#include "sim/state.hpp"

namespace edsc::sim {

namespace general {
inline constexpr std::uint8_t success = 0x00, connection_failure = 0x01, path_segment_error = 0x04,
                              path_unknown = 0x05, not_supported = 0x08, invalid_attribute_value = 0x09,
                              state_conflict = 0x0C, not_settable = 0x0E, not_enough_data = 0x13,
                              attribute_unsupported = 0x14, too_much_data = 0x15, object_does_not_exist = 0x16,
                              invalid_parameter = 0x20;
}

[[nodiscard]] cip::bytes connection_manager(state& s, const link& l, const cip::request& q,
                                            const cip::object_address& a, clock::time_point now);
// Class 0x0F from [Params] (parameter_object.cpp).
[[nodiscard]] cip::bytes parameter_object(state& s, const cip::request& q, const cip::object_address& a);
// Class 0x37, the EDS itself as instance 0xC8 (file_object.cpp).
[[nodiscard]] cip::bytes file_object(state& s, const cip::request& q, const cip::object_address& a);
// Closes listen-only connections whose owner is gone.
void close_orphans(state& s);
// A JSON line {"event": what, ...fields}; `fields` is the inside of an object, may be empty.
void log_event(state& s, const std::string& what, const std::string& fields);
[[nodiscard]] std::string hex(cip::byte_view b);

}  // namespace edsc::sim
