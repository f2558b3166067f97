#pragma once
// One announced connection opened by EIPScanner on `edsc sim` of the same
// file: Forward_Open (Large_Forward_Open when announced) with parameters
// from the JSON only, a listen-only one beside the owner the JSON names, I/O
// until frames went both ways, Forward_Close; then the frames EIPScanner
// received and the simulator's log of what it consumed are held to the
// announced sizes. The calling thread must be in the scanner's namespace.
#include <cstddef>
#include <string>

#include "announced.hpp"

namespace edsc::scanner_test {

struct open_outcome {
  std::string failure;                 // empty: opened, frames both ways of the announced sizes, closed
  std::size_t received = 0, sent = 0;  // T->O frames EIPScanner took, O->T frames it sent
};

// Opens `c` at `ip` (after `owner`, unless null) and checks it against the
// simulator's event log in the file `sim_log`; a device without one (OpENer)
// is given "", and only the T->O frames EIPScanner receives are checked.
open_outcome open_announced(const std::string& ip, const announced_connection& c, const announced_connection* owner,
                            const std::string& sim_log);

// What the simulator's event log in the file `sim_log` says of `c`, the last
// connection opened there, once it is closed: its O->T frames taken at the
// announced size, the data 0xA0, 0xA1, ... as sent; "" when all is so.
std::string simulator_took(const std::string& sim_log, const announced_connection& c);

}  // namespace edsc::scanner_test
