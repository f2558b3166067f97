#include "live/upload.hpp"

#include <fmt/format.h>

#include "cip/status.hpp"

namespace edsc::live {

namespace {

using cip::packet_type;

error refused(const char* what, const cip::reply& r) {
  return {net::error_id::refused, fmt::format("{} refused: {}", what, cip::describe_status(r.general, r.additional))};
}

// Whether a packet of `type` may come as transfer `n`: first (or first and
// last) exactly at 0, never an abort or a type the File object lacks.
bool in_turn(packet_type type, std::uint32_t n) {
  const bool opens = type == packet_type::first || type == packet_type::first_and_last;
  return type <= packet_type::first_and_last && type != packet_type::abort && opens == (n == 0);
}

}  // namespace

result<cip::bytes> upload_file(client& s, std::uint32_t instance) {
  const auto path = cip::logical_path(cip::class_id::file, instance);
  const std::uint8_t max_transfer = 0xFF;
  auto init = s.request(cip::service::initiate_upload, path, cip::byte_view(&max_transfer, 1));
  if (!init) return init.error();
  const auto& ir = *init;
  if (ir.general != 0) return refused("Initiate_Upload of the File object", ir);
  const auto offer = cip::decode_upload_offer(ir.data, 0);
  if (!offer || offer->transfer_size == 0)
    return error{net::error_id::unexpected, "Initiate_Upload answered without a file size and transfer size"};
  const auto size = offer->file_size;
  cip::bytes file;
  // A packet carries at least one byte, so the file's size bounds the packets.
  for (std::uint32_t n = 0; n <= size; ++n) {
    const auto number = static_cast<std::uint8_t>(n);
    auto t = s.request(cip::service::upload_transfer, path, cip::byte_view(&number, 1));
    if (!t) return t.error();
    const auto& r = *t;
    if (r.general != 0) return refused(fmt::format("Upload_Transfer {}", n).c_str(), r);
    if (r.data.size() < 2 || r.data[0] != number)
      return error{net::error_id::unexpected, fmt::format("Upload_Transfer {} answered another transfer", n)};
    if (!in_turn(packet_type{r.data[1]}, n))
      return error{net::error_id::unexpected,
                   fmt::format("Upload_Transfer {}: packet type {} out of turn", n, r.data[1])};
    const auto p = cip::decode_upload_packet(r.data, 0);
    if (!p) return malformed(fmt::format("Upload_Transfer {} reply", n), p.error());
    file.insert(file.end(), p->data.begin(), p->data.end());
    if (!p->checksum) continue;
    if (const auto expected = cip::file_checksum(file); *p->checksum != expected)
      return error{net::error_id::unexpected,
                   fmt::format("the file's checksum 0x{:04X} does not match its bytes (0x{:04X} expected)",
                               *p->checksum, expected)};
    if (file.size() != size)
      return error{net::error_id::unexpected,
                   fmt::format("the device announced {} bytes and sent {}", size, file.size())};
    return file;
  }
  return error{net::error_id::unexpected, fmt::format("no last packet after {} bytes announced", size)};
}

}  // namespace edsc::live
