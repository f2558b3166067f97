#pragma once
// The EtherNet/IP encapsulation layer (TCP and UDP port 44818) and the Common
// Packet Format items it carries (ETHERNETIP_LIVE.md §3).
#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "cip/bytes.hpp"
#include "cip/codes.hpp"

namespace edsc::cip {

inline constexpr std::uint16_t enip_port = 44818;
inline constexpr std::uint16_t io_port = 2222;
inline constexpr std::size_t encap_header_size = 24;

using sender_context = std::array<std::uint8_t, 8>;

struct encap_header {
  std::uint16_t command = 0;
  std::uint16_t length = 0;  // bytes after the header
  std::uint32_t session = 0;
  std::uint32_t status = 0;
  sender_context context{};
  std::uint32_t options = 0;
};

// The header (its length set from `data`; `status` 0 in requests) followed by
// `data`; refused when `data` is longer than the 16-bit length says.
[[nodiscard]] encoded encode_encap(command cmd, std::uint32_t session, const sender_context& context, byte_view data,
                                   encap_status status = encap_status::success);
// The first 24 bytes of `b`, which must hold at least that many.
[[nodiscard]] decoded<encap_header> decode_encap_header(byte_view b);

// One CPF item; `data` views the decoded buffer, `offset` is where it starts.
struct cpf_item {
  std::uint16_t type = 0;
  byte_view data;
  std::size_t offset = 0;
};
struct cpf_item_out {
  item type;
  byte_view data;
};
// Refused when an item's data is longer than its 16-bit length says.
[[nodiscard]] encoded encode_cpf(std::initializer_list<cpf_item_out> items);
// Every item of a CPF list; the lengths must fill `b` exactly.
[[nodiscard]] decoded<std::vector<cpf_item>> decode_cpf(byte_view b, std::size_t base);

// RegisterSession data: protocol version 1, options 0.
[[nodiscard]] bytes register_session_data();
// RegisterSession data, request or reply: protocol version and options, 4
// bytes and no more.
struct register_session {
  std::uint16_t version = 0, options = 0;
};
[[nodiscard]] decoded<register_session> decode_register_session(byte_view data, std::size_t base);

// SendRRData and SendUnitData data: interface handle, timeout, then the CPF
// items (returned).
[[nodiscard]] decoded<std::vector<cpf_item>> decode_command_items(byte_view data, std::size_t base);
// The first item of `type`, or null.
[[nodiscard]] const cpf_item* find_item(const std::vector<cpf_item>& items, item type);

// SendRRData data (interface handle 0, timeout, null address item,
// unconnected data item) around a CIP request.
[[nodiscard]] encoded send_rr_data(byte_view cip_request, std::uint16_t timeout_s);
// The unconnected data item of a SendRRData reply's data.
[[nodiscard]] decoded<byte_view> decode_send_rr_data(byte_view data, std::size_t base);
// SendUnitData data (class 3): connected address item, connected data item
// holding the 16-bit sequence count then the CIP message.
[[nodiscard]] encoded send_unit_data(std::uint32_t connection_id, std::uint16_t sequence, byte_view cip);
struct unit_data {
  std::uint32_t connection_id = 0;
  std::uint16_t sequence = 0;
  byte_view cip;
};
[[nodiscard]] decoded<unit_data> decode_send_unit_data(byte_view data, std::size_t base);

// A ListIdentity reply item (also what Identity Get_Attributes_All gives,
// without the socket address and the encapsulation version).
// Identity attribute 7, Product Name: a SHORT_STRING of at most 32 bytes
// (its length is one USINT of bytes; a byte is a character of the device's
// 8-bit string, so UTF-8 text takes more than one per character).
inline constexpr std::size_t max_product_name = 32;
// The Product Name a device holds for a ProdName: its first 32 bytes, cut
// between two characters. The header, the OpENer stack and the simulator
// serve it, and verify --live compares with it.
[[nodiscard]] std::string_view held_product_name(std::string_view prod_name);

struct identity {
  std::uint16_t encap_version = 0;
  std::uint16_t sin_family = 0, sin_port = 0;
  std::array<std::uint8_t, 4> sin_addr{};
  std::uint16_t vendor = 0, device_type = 0, product_code = 0;
  std::uint8_t major = 0, minor = 0;
  std::uint16_t status = 0;
  std::uint32_t serial = 0;
  std::string product_name;
  std::uint8_t state = 0xFF;  // 0xFF: not given
};
// Identity attributes 1-7 in their wire order (vendor id to product name),
// shared by the ListIdentity item and Get_Attributes_All.
void read_identity_fields(reader& r, identity& id);
// Every identity item of a ListIdentity reply's data (usually one).
[[nodiscard]] decoded<std::vector<identity>> decode_list_identity(byte_view data, std::size_t base);

// A ListServices reply item.
struct service_info {
  std::uint16_t version = 0, capability = 0;
  std::string name;
};
[[nodiscard]] decoded<std::vector<service_info>> decode_list_services(byte_view data, std::size_t base);

}  // namespace edsc::cip
