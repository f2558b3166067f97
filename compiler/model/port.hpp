#pragma once
#include <cstdint>
#include <vector>

#include "model/value.hpp"

namespace edsc::model {

// PortN (EDS_FORMAT.md §3.12); fields 5+ are unconfirmed and kept in `extra`.
struct port {
  std::uint32_t number = 0;
  origin from;
  value type, name, path, port_number;
  std::vector<value> extra;
};

}  // namespace edsc::model
