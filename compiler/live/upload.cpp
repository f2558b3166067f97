#include "live/upload.hpp"

#include <fmt/format.h>

#include "cip/status.hpp"

namespace edsc::live {

namespace {

constexpr std::uint8_t first = 0, middle = 1, last = 2, first_and_last = 4;

net_error refused(const char* what, const cip::reply& r) {
  return {fmt::format("{} refused: {}", what, cip::describe_status(r.general, r.additional))};
}

}  // namespace

result<cip::bytes> upload_file(session& s, std::uint32_t instance) {
  const auto path = cip::logical_path(cip::class_id::file, instance);
  const std::uint8_t max_transfer = 0xFF;
  auto init = s.request(cip::service::initiate_upload, path, cip::byte_view(&max_transfer, 1));
  if (auto* e = failed(init)) return *e;
  const auto& ir = std::get<cip::reply>(init);
  if (ir.general != 0) return refused("Initiate_Upload of the File object", ir);
  if (ir.data.size() < 5 || ir.data[4] == 0) return net_error{"Initiate_Upload answered without a file size and transfer size"};
  const std::uint32_t size = ir.data[0] | ir.data[1] << 8 | ir.data[2] << 16 | static_cast<std::uint32_t>(ir.data[3]) << 24;
  cip::bytes file;
  std::uint16_t sum = 0;
  // A packet carries at least one byte, so the file's size bounds the packets.
  for (std::uint32_t n = 0; n <= size; ++n) {
    const auto number = static_cast<std::uint8_t>(n);
    auto t = s.request(cip::service::upload_transfer, path, cip::byte_view(&number, 1));
    if (auto* e = failed(t)) return *e;
    const auto& r = std::get<cip::reply>(t);
    if (r.general != 0) return refused(fmt::format("Upload_Transfer {}", n).c_str(), r);
    if (r.data.size() < 2 || r.data[0] != number) return net_error{fmt::format("Upload_Transfer {} answered another transfer", n)};
    const auto type = r.data[1];
    const bool ends = type == last || type == first_and_last;
    if (type > first_and_last || type == 3 || ((type == first || type == first_and_last) != (n == 0)))
      return net_error{fmt::format("Upload_Transfer {}: packet type {} out of turn", n, type)};
    const auto data_end = r.data.size() - (ends ? 2 : 0);
    if (data_end < 2) return net_error{fmt::format("Upload_Transfer {}: the last packet has no checksum", n)};
    for (auto i = r.data.begin() + 2; i != r.data.begin() + static_cast<std::ptrdiff_t>(data_end); ++i) {
      file.push_back(*i);
      sum = static_cast<std::uint16_t>(sum + *i);
    }
    if (!ends) continue;
    const std::uint16_t checksum = r.data[data_end] | r.data[data_end + 1] << 8;
    if (static_cast<std::uint16_t>(sum + checksum) != 0)
      return net_error{fmt::format("the file's checksum 0x{:04X} does not match its bytes (0x{:04X} expected)", checksum,
                                   static_cast<std::uint16_t>(0x10000 - sum))};
    if (file.size() != size)
      return net_error{fmt::format("the device announced {} bytes and sent {}", size, file.size())};
    return file;
  }
  return net_error{fmt::format("no last packet after {} bytes announced", size)};
}

}  // namespace edsc::live
