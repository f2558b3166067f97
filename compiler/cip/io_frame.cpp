#include "cip/io_frame.hpp"

#include <fmt/format.h>

#include "cip/encap.hpp"

namespace edsc::cip {

encoded encode_io_frame(const io_frame& f) {
  bytes addr, payload;
  put_u32(addr, f.connection_id);
  put_u32(addr, f.encap_sequence);
  put_u16(payload, f.sequence_count);
  if (f.run_idle) put_u32(payload, *f.run_idle);
  put_bytes(payload, f.data);
  auto frame = encode_cpf({{item::sequenced_address, addr}, {item::connected_data, payload}});
  if (frame && frame->size() > max_io_frame_size)
    return fail(encode_error{"class 1 frame size", frame->size(), max_io_frame_size});
  return frame;
}

decoded<io_frame> decode_io_frame(byte_view b, bool run_idle) {
  auto items = decode_cpf(b, 0);
  if (!items) return items.error();
  const auto& it = items.value();
  if (it.size() < 2 || it[0].type != static_cast<std::uint16_t>(item::sequenced_address) ||
      it[1].type != static_cast<std::uint16_t>(item::connected_data))
    return decode_error{0,
                        "not a class 1 frame: expected a sequenced address item (0x8002) "
                        "then a connected data item (0x00B1)"};
  io_frame f;
  reader ra(it[0].data, it[0].offset);
  f.connection_id = ra.u32("connection id");
  f.encap_sequence = ra.u32("encapsulation sequence number");
  if (!ra.ok()) return ra.error();
  if (ra.remaining() != 0) return ra.fail("sequenced address item longer than 8 bytes");
  reader rd(it[1].data, it[1].offset);
  f.sequence_count = rd.u16("CIP sequence count");
  if (run_idle && rd.remaining() > 0) f.run_idle = rd.u32("run/idle header");
  if (!rd.ok()) return rd.error();
  const auto rest = rd.rest();
  f.data.assign(rest.begin(), rest.end());
  return f;
}

}  // namespace edsc::cip
