// The File object (class 0x37): the EDS itself as instance 0xC8, so a
// configuration tool's "upload EDS from device" gets the file the simulator
// was started with, byte for byte.
//
// Facts relied on (CIP Vol. 1, File object, as remembered; the service codes,
// instance 0xC8, the packet types and the 255-byte limit are also in
// ../shared/docs/ETHERNETIP_LIVE.md §4, which calls them unconfirmed; OpENer
// has no File object to compare with):
// - attributes 1 state (USINT: 2 file loaded, 3 upload initiated, 5 upload in
//   progress), 2 instance name (STRINGI), 3 instance format version (UINT),
//   4 file name (STRINGI), 5 file revision (USINT major, USINT minor), 6 file
//   size (UDINT), 7 file checksum (INT: the two's complement of the 16-bit sum
//   of the file's bytes), 10 file type (USINT, 1 read only), 11 file encoding
//   format (USINT, 0 binary);
// - Initiate_Upload (0x4B): the originator's maximum transfer size (USINT) in;
//   file size (UDINT) and the transfer size chosen (USINT) out;
// - Upload_Transfer (0x4F): a transfer number (USINT, from 0, +1 modulo 256)
//   in; the number, the packet type (0 first, 1 middle, 2 last, 4 first and
//   last) and up to transfer-size bytes of the file out, the last packet
//   followed by the checksum (INT). Asking the last number again sends the
//   same packet again (a reply that was lost).
// docs/sim.md lists which answers are the simulator's own choice.
// The transfer's bytes, both sides: cip/file_transfer.hpp.
#include <algorithm>

#include <fmt/format.h>

#include "cip/device_reply.hpp"
#include "cip/file_transfer.hpp"
#include "cip/message.hpp"
#include "sim/object_table.hpp"
#include "sim/objects.hpp"

namespace edsc::sim {

namespace {

using cip::bytes;

constexpr std::uint8_t state_loaded = 2, state_upload_initiated = 3, state_upload_in_progress = 5;

// STRINGI with one string: language "eng", SHORT_STRING (0xDA), character set 4 (ISO 8859-1).
void put_stringi(bytes& b, const std::string& text) {
  cip::put_u8(b, 1);
  b.insert(b.end(), {'e', 'n', 'g'});
  cip::put_u8(b, 0xDA);
  cip::put_u16(b, 4);
  const auto n = std::min<std::size_t>(text.size(), 255);
  cip::put_u8(b, static_cast<std::uint8_t>(n));
  b.insert(b.end(), text.begin(), text.begin() + static_cast<std::ptrdiff_t>(n));
}

std::uint8_t file_state(const state& s) {
  if (!s.upload.active || s.upload.done) return state_loaded;
  return s.upload.offset == 0 ? state_upload_initiated : state_upload_in_progress;
}

// An attribute of the one instance.
attribute file_attr(std::uint32_t number, void (*put)(const state&, bytes&)) {
  return {number, [put](const state& s, std::uint32_t, bytes& d) { put(s, d); }};
}

std::vector<attribute> instance_attributes() {
  return {
      file_attr(1, [](const state& s, bytes& d) { cip::put_u8(d, file_state(s)); }),
      file_attr(2, [](const state&, bytes& d) { put_stringi(d, "EDS and Icon Files"); }),
      file_attr(3, [](const state&, bytes& d) { cip::put_u16(d, 1); }),
      file_attr(4, [](const state& s, bytes& d) { put_stringi(d, s.dev.file.name); }),
      file_attr(5,
                [](const state& s, bytes& d) { cip::put_u8(d, s.dev.file.major), cip::put_u8(d, s.dev.file.minor); }),
      file_attr(
          6, [](const state& s, bytes& d) { cip::put_u32(d, static_cast<std::uint32_t>(s.dev.file.content.size())); }),
      file_attr(7, [](const state& s, bytes& d) { cip::put_u16(d, cip::file_checksum(s.dev.file.content)); }),
      file_attr(10, [](const state&, bytes& d) { cip::put_u8(d, 1); }),  // read only
      file_attr(11, [](const state&, bytes& d) { cip::put_u8(d, 0); }),  // binary, not compressed
  };
}

// The packet that starts at `from` under transfer number `number`.
bytes packet(const state& s, cip::service service, std::uint8_t number, std::size_t from) {
  const auto& content = s.dev.file.content;
  const auto n = std::min<std::size_t>(s.upload.transfer_size, content.size() - from);
  const bool is_first = from == 0, is_last = from + n == content.size();
  using type = cip::packet_type;
  const auto t = is_first && is_last ? type::first_and_last
                 : is_first          ? type::first
                 : is_last           ? type::last
                                     : type::middle;
  const auto d = cip::encode_upload_packet(number, t, cip::byte_view(content).subspan(from, n),
                                           is_last ? std::optional(cip::file_checksum(content)) : std::nullopt);
  return cip::encode_reply(service, general::success, d);
}

bytes transfer(state& s, const cip::request& q) {
  if (q.data.empty()) return cip::encode_reply(q.service, general::not_enough_data);
  if (q.data.size() > 1) return cip::encode_reply(q.service, general::too_much_data);
  auto& u = s.upload;
  if (!u.active) return cip::encode_reply(q.service, general::object_state_conflict);
  const auto number = q.data[0];
  if (u.offset > 0 && number == static_cast<std::uint8_t>(u.next - 1))
    return packet(s, q.service, number, u.last_offset);
  if (number != u.next || u.done) return cip::encode_reply(q.service, general::invalid_parameter);
  auto reply = packet(s, q.service, number, u.offset);
  u.last_offset = u.offset;
  u.offset = std::min(u.offset + u.transfer_size, s.dev.file.content.size());
  u.done = u.offset == s.dev.file.content.size();
  ++u.next;
  if (u.done) log_event(s, "uploaded", fmt::format("\"instance\":{},\"size\":{}", cip::eds_file_instance, u.offset));
  return reply;
}

bytes initiate(state& s, const cip::request& q) {
  if (q.data.empty()) return cip::encode_reply(q.service, general::not_enough_data);
  if (q.data.size() > 1) return cip::encode_reply(q.service, general::too_much_data);
  if (q.data[0] == 0) return cip::encode_reply(q.service, general::invalid_parameter);
  s.upload = file_upload{true, false, q.data[0], 0, 0, 0};  // a new upload restarts one left unfinished
  const auto d =
      cip::encode_upload_offer({static_cast<std::uint32_t>(s.dev.file.content.size()), s.upload.transfer_size});
  return cip::encode_reply(q.service, general::success, d);
}

}  // namespace

object_table file_table() {
  object_table t;
  t.class_id = cip::code(cip::class_id::file);
  t.present = [](const state& s) { return !s.dev.file.content.empty(); };
  // Revision 1, max instance, number of instances.
  t.class_level = attribute_level{{constant_u16(1, 1), constant_u16(2, cip::eds_file_instance), constant_u16(3, 1)}};
  t.exists = [](const state&, std::uint32_t i) { return i == cip::eds_file_instance; };
  t.missing = general::object_does_not_exist;
  t.instance_level = {instance_attributes(), false, true};  // every attribute read only
  t.services = {{cip::service::initiate_upload, [](object_call& c) { return initiate(c.s, c.q); }},
                {cip::service::upload_transfer, [](object_call& c) { return transfer(c.s, c.q); }}};
  return t;
}

}  // namespace edsc::sim
