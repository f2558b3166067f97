#include "cip/encap.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "base/utf8.hpp"

namespace edsc::cip {

std::string_view held_product_name(std::string_view prod_name) { return utf8::cut(prod_name, max_product_name); }

void read_identity_fields(reader& r, identity& id) {
  id.vendor = r.u16("vendor id");
  id.device_type = r.u16("device type");
  id.product_code = r.u16("product code");
  id.major = r.u8("major revision");
  id.minor = r.u8("minor revision");
  id.status = r.u16("status");
  id.serial = r.u32("serial number");
  const auto len = r.u8("product name length");
  const auto name = r.take(len, "product name");
  id.product_name.assign(name.begin(), name.end());
}

encoded encode_encap(command cmd, std::uint32_t session, const sender_context& context, byte_view data,
                     encap_status status) {
  const auto length = fit<std::uint16_t>(data.size(), 0xFFFF, "encapsulation length");
  if (!length) return fail(length.error());
  bytes b;
  b.reserve(encap_header_size + data.size());
  put_u16(b, code(cmd));
  put_u16(b, *length);
  put_u32(b, session);
  put_u32(b, code(status));
  put_bytes(b, context);
  put_u32(b, 0);  // options: 0
  put_bytes(b, data);
  return b;
}

decoded<encap_header> decode_encap_header(byte_view b) {
  reader r(b);
  encap_header h;
  h.command = r.u16("encapsulation command");
  h.length = r.u16("encapsulation length");
  h.session = r.u32("session handle");
  h.status = r.u32("encapsulation status");
  const auto ctx = r.take(8, "sender context");
  h.options = r.u32("encapsulation options");
  if (!r.ok()) return r.error();
  std::copy(ctx.begin(), ctx.end(), h.context.begin());
  return h;
}

encoded encode_cpf(std::initializer_list<cpf_item_out> items) {
  bytes b;
  put_u16(b, static_cast<std::uint16_t>(items.size()));  // a list written out in the source: a handful
  for (const auto& it : items) {
    const auto length = fit<std::uint16_t>(it.data.size(), 0xFFFF, "CPF item length");
    if (!length) return fail(length.error());
    put_u16(b, code(it.type));
    put_u16(b, *length);
    put_bytes(b, it.data);
  }
  return b;
}

decoded<std::vector<cpf_item>> decode_cpf(byte_view b, std::size_t base) {
  reader r(b, base);
  const auto count = r.u16("CPF item count");
  std::vector<cpf_item> items;
  for (unsigned i = 0; i < count && r.ok(); ++i) {
    cpf_item it;
    it.type = r.u16("CPF item type");
    const auto len = r.u16("CPF item length");
    it.offset = r.offset();
    it.data = r.take(len, "CPF item data");
    items.push_back(it);
  }
  if (!r.ok()) return r.error();
  if (r.remaining() != 0) return r.fail(plural(r.remaining(), "byte") + " after the last CPF item");
  return items;
}

bytes register_session_data() {
  bytes b;
  put_u16(b, 1);  // protocol version
  put_u16(b, 0);  // options
  return b;
}

decoded<register_session> decode_register_session(byte_view data, std::size_t base) {
  reader r(data, base);
  register_session reg;
  reg.version = r.u16("RegisterSession protocol version");
  reg.options = r.u16("RegisterSession options");
  if (!r.ok()) return r.error();
  if (r.remaining() != 0) return r.fail(plural(r.remaining(), "byte") + " after the RegisterSession options");
  return reg;
}

namespace {

// SendRRData and SendUnitData data: interface handle 0 (CIP), the timeout,
// then the CPF items.
encoded command_data(std::uint16_t timeout_s, std::initializer_list<cpf_item_out> items) {
  auto cpf = encode_cpf(items);
  if (!cpf) return cpf;
  bytes b;
  put_u32(b, 0);
  put_u16(b, timeout_s);
  put_bytes(b, *cpf);
  return b;
}

}  // namespace

encoded send_rr_data(byte_view cip_request, std::uint16_t timeout_s) {
  return command_data(timeout_s, {{item::null_address, {}}, {item::unconnected_data, cip_request}});
}

const cpf_item* find_item(const std::vector<cpf_item>& items, item type) {
  for (const auto& it : items)
    if (it.type == code(type)) return &it;
  return nullptr;
}

decoded<std::vector<cpf_item>> decode_command_items(byte_view data, std::size_t base) {
  reader r(data, base);
  r.u32("interface handle");
  r.u16("timeout");
  if (!r.ok()) return r.error();
  const auto at = r.offset();
  return decode_cpf(r.rest(), at);
}

decoded<byte_view> decode_send_rr_data(byte_view data, std::size_t base) {
  auto items = decode_command_items(data, base);
  if (!items) return items.error();
  const auto* d = find_item(items.value(), item::unconnected_data);
  if (!d) return decode_error{base + 6, "SendRRData reply without an unconnected data item (0x00B2)"};
  return d->data;
}

encoded send_unit_data(std::uint32_t connection_id, std::uint16_t sequence, byte_view cip) {
  bytes addr, payload;
  put_u32(addr, connection_id);
  put_u16(payload, sequence);
  put_bytes(payload, cip);
  // Timeout 0 for connected messages.
  return command_data(0, {{item::connected_address, addr}, {item::connected_data, payload}});
}

decoded<unit_data> decode_send_unit_data(byte_view data, std::size_t base) {
  auto items = decode_command_items(data, base);
  if (!items) return items.error();
  const auto* a = find_item(items.value(), item::connected_address);
  const auto* d = find_item(items.value(), item::connected_data);
  if (!a || !d) return decode_error{base + 6, "SendUnitData without a connected address and a connected data item"};
  if (a->data.size() != 4)
    return decode_error{a->offset,
                        fmt::format("a connected address item of {}; 4 expected", plural(a->data.size(), "byte"))};
  unit_data u;
  reader ra(a->data, a->offset);
  u.connection_id = ra.u32("connection id");
  if (!ra.ok()) return ra.error();
  reader rd(d->data, d->offset);
  u.sequence = rd.u16("sequence count");
  u.cip = rd.rest();
  if (!rd.ok()) return rd.error();
  return u;
}

decoded<std::vector<identity>> decode_list_identity(byte_view data, std::size_t base) {
  auto items = decode_cpf(data, base);
  if (!items) return items.error();
  std::vector<identity> out;
  for (const auto& it : items.value()) {
    if (it.type != static_cast<std::uint16_t>(item::list_identity)) continue;
    reader r(it.data, it.offset);
    identity id;
    id.encap_version = r.u16("encapsulation version");
    id.sin_family = r.be16("socket address family");
    id.sin_port = r.be16("socket address port");
    const auto addr = r.take(4, "socket address");
    r.take(8, "socket address zero bytes");
    read_identity_fields(r, id);
    id.state = r.u8("state");
    if (!r.ok()) return r.error();
    std::copy(addr.begin(), addr.end(), id.sin_addr.begin());
    out.push_back(std::move(id));
  }
  if (out.empty()) return decode_error{base, "ListIdentity reply without an identity item (0x000C)"};
  return out;
}

decoded<std::vector<service_info>> decode_list_services(byte_view data, std::size_t base) {
  auto items = decode_cpf(data, base);
  if (!items) return items.error();
  std::vector<service_info> out;
  for (const auto& it : items.value()) {
    if (it.type != static_cast<std::uint16_t>(item::list_services)) continue;
    reader r(it.data, it.offset);
    service_info s;
    s.version = r.u16("service version");
    s.capability = r.u16("capability flags");
    const auto name = r.take(16, "service name");
    if (!r.ok()) return r.error();
    for (const auto c : name) {
      if (c == 0) break;
      s.name.push_back(static_cast<char>(c));
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace edsc::cip
