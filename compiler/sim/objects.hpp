#pragma once
// Internal to the simulator: the objects a request reaches after its path
// is read, and the JSON lines they log.
#include <cstdint>
#include <string>

#include "cip/request.hpp"
#include "sim/state.hpp"

namespace edsc::sim {

using general = cip::general_status;

struct object_table;
// Class 6, Forward_Open, Large_Forward_Open and Forward_Close (connection_manager.cpp).
[[nodiscard]] object_table connection_manager_table();
// Class 0x0F from [Params] (parameter_object.cpp).
[[nodiscard]] object_table parameter_table();
// Class 0x37, the EDS itself as instance 0xC8 (file_object.cpp).
[[nodiscard]] object_table file_table();
// Closes listen-only connections whose owner is gone.
void close_orphans(state& s);
// A JSON line {"event": what, ...fields}; `fields` is the inside of an object, may be empty.
void log_event(state& s, const std::string& what, const std::string& fields);
[[nodiscard]] std::string hex(cip::byte_view b);

}  // namespace edsc::sim
