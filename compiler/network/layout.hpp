#pragma once
// Automap: the scanner's input and output slave areas laid out from a plan
// (docs/network.md, "Layout"). Offsets are bytes from the first slave data
// byte of the image.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "network/plan.hpp"

namespace edsc::network {

struct block {
  std::size_t node = 0;  // index into plan::nodes
  conn_type type = conn_type::poll;
  std::uint32_t offset = 0, size = 0;  // bytes
  bool fixed = false;                  // placed by input_dword / output_dword
  [[nodiscard]] std::uint32_t end() const { return offset + size; }
};

struct image_layout {
  bool input = true;
  std::uint32_t capacity = 0;  // slave data bytes
  std::vector<block> blocks;   // ascending offset
  [[nodiscard]] std::uint32_t used() const;
};

struct layout_problem {
  bool input = true;
  std::size_t node = 0;
  bool overlap = false;   // else: past the end of the slave area
  std::size_t other = 0;  // the node overlapped (overlap only)
  std::uint32_t offset = 0, size = 0;
};

struct layout {
  image_layout input, output;
  std::vector<layout_problem> problems;
};

[[nodiscard]] layout automap(const plan& p);

}  // namespace edsc::network
