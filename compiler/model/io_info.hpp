#pragma once
#include <cstdint>
#include <vector>

#include "model/value.hpp"

namespace edsc::model {

// DeviceNet predefined connection types: the bits of every IO_Info mask.
enum io_bit : std::uint16_t {
  io_poll = 0x0001,
  io_strobe = 0x0002,
  io_cos = 0x0004,
  io_cyclic = 0x0008,
  io_multicast_poll = 0x0010,  // unconfirmed (EDS_FORMAT.md §3.4)
};

enum class io_connection : std::uint8_t { poll, strobe, cos, cyclic };

// PollInfo / StrobeInfo / COSInfo / CyclicInfo. `default_input` and
// `default_output` are number references resolved into io_info::inputs/outputs.
struct io_connection_info {
  io_connection type = io_connection::poll;
  origin from;
  value mask, default_input, default_output;
};

// InputN (produced by the device) / OutputN (consumed by it).
struct io_data {
  std::uint32_t number = 0;
  bool output = false;
  origin from;
  value size, significant_bits, mask, name, path_size, path, help;
  std::vector<value> extra;  // fields beyond the 7 of the layout
};

// [IO_Info], and [Variant_IO_Info] in the same layout (our reading, §3.5).
struct io_info {
  std::uint32_t section = none;
  origin default_from;
  value default_mask;
  std::vector<io_connection_info> connections;
  std::vector<io_data> inputs, outputs;  // in file order
  // InputExaN / OutputExaN (§3.18): same layout, path names an AssemExaN.
  std::vector<io_data> input_exas, output_exas;
};

}  // namespace edsc::model
