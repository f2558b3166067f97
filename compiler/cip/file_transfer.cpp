#include "cip/file_transfer.hpp"

namespace edsc::cip {

std::uint16_t file_checksum(byte_view content) {
  std::uint16_t sum = 0;
  for (const auto c : content) sum = static_cast<std::uint16_t>(sum + c);
  return static_cast<std::uint16_t>(0x10000 - sum);
}

bytes encode_upload_offer(const upload_offer& o) {
  bytes d;
  put_u32(d, o.file_size);
  put_u8(d, o.transfer_size);
  return d;
}

decoded<upload_offer> decode_upload_offer(byte_view data, std::size_t base) {
  reader r(data, base);
  upload_offer o;
  o.file_size = r.u32("file size");
  o.transfer_size = r.u8("transfer size");
  if (!r.ok()) return r.error();
  return o;
}

bool ends_file(packet_type t) { return t == packet_type::last || t == packet_type::first_and_last; }

bytes encode_upload_packet(std::uint8_t number, packet_type type, byte_view data,
                           std::optional<std::uint16_t> checksum) {
  bytes d;
  put_u8(d, number);
  put_u8(d, static_cast<std::uint8_t>(type));
  put_bytes(d, data);
  if (checksum) put_u16(d, *checksum);
  return d;
}

decoded<upload_packet> decode_upload_packet(byte_view data, std::size_t base) {
  reader r(data, base);
  upload_packet p;
  p.number = r.u8("transfer number");
  p.type = static_cast<packet_type>(r.u8("packet type"));
  if (!r.ok()) return r.error();
  auto rest = r.rest();
  if (ends_file(p.type)) {
    if (rest.size() < 2) return decode_error{base + 2, "the last packet has no checksum"};
    p.checksum = static_cast<std::uint16_t>(rest[rest.size() - 2] | rest[rest.size() - 1] << 8);
    rest = rest.first(rest.size() - 2);
  }
  p.data = rest;
  return p;
}

}  // namespace edsc::cip
