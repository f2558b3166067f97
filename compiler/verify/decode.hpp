#pragma once
// The Predefined Master/Slave Connection Set traffic of a capture, decoded
// (DEVICENET_FIRMWARE.md §2-3): who sent each frame, explicit requests paired
// with their answers, and I/O frames with the connection they belong to.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "verify/can_log.hpp"

namespace edsc::verify {

// Same order as emit::devicenet_facts::types.
enum class conn_type : std::uint8_t { poll, strobe, cos, cyclic };

// Allocation choice bits (request byte 4).
inline constexpr std::uint8_t choice_explicit = 0x01, choice_poll = 0x02, choice_strobe = 0x04, choice_multicast = 0x08,
                              choice_cos = 0x10, choice_cyclic = 0x20;

struct decoded_frame {
  std::size_t frame = 0;  // index into can_log::frames
  char dir = '?';         // 'M' master, 'S' slave, '?' unknown
  int group = 0;          // 1-4, 0 when not DeviceNet (29-bit, remote)
  unsigned message = 0;   // message id within the group
  unsigned mac = 0;       // the MAC the identifier carries
  std::string label;      // "G2 msg 4: explicit request"
  std::string meaning;    // plain words for --decode
  bool undecodable = false;
  std::string why;  // when undecodable
};

// One explicit request and the answer it got (if any).
struct exchange {
  unsigned mac = 0;
  std::size_t request = 0;            // index into can_log::frames
  std::optional<std::size_t> answer;  // index into can_log::frames (last fragment)
  std::uint8_t service = 0, cls = 0, inst = 0, attr = 0;
  bool has_attr = false;
  std::vector<std::uint8_t> value;  // request data after the path
  std::uint8_t allocated = 0;       // the node's allocation when asked
  bool error = false;
  std::uint8_t general = 0, additional = 0xFF;
  std::vector<std::uint8_t> data;  // success answer data after the service byte
};

struct io_event {
  std::size_t frame = 0;
  unsigned mac = 0;
  bool produced = true;  // slave -> master
  conn_type type = conn_type::cos;
  std::uint8_t allocated = 0;  // the node's allocation when sent
  std::size_t length = 0;
};

struct conversation {
  std::vector<decoded_frame> frames;  // one per can_log frame
  std::vector<exchange> exchanges;
  std::vector<io_event> io;
  std::vector<unsigned> nodes;  // slave MACs heard, ascending
};

[[nodiscard]] conversation decode(const can_log& log);

// "Get_Attribute_Single", "Allocate_Master/Slave_Connection_Set"...
[[nodiscard]] std::string service_name(std::uint8_t service, std::uint8_t cls);
// "Identity revision", "Connection 4 produced_connection_size"...
[[nodiscard]] std::string attribute_name(std::uint8_t cls, std::uint8_t inst, std::uint8_t attr);
[[nodiscard]] std::string status_name(std::uint8_t general);
[[nodiscard]] std::string choice_names(std::uint8_t choice);
[[nodiscard]] std::string hex_bytes(const std::vector<std::uint8_t>& data);

// `edsc verify --decode`: one row per frame (time, direction, id, group/message, meaning).
[[nodiscard]] std::string render_table(const can_log& log, const conversation& conv);

}  // namespace edsc::verify
