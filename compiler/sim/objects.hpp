#pragma once
// Internal to the simulator: the objects a request reaches after its path
// is read, and the JSON lines they log.
#include <cstdint>
#include <string>

#include "cip/request.hpp"
#include "sim/state.hpp"

namespace edsc::sim {

using general = cip::general_status;

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
