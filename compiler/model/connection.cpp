#include "model/connection.hpp"

namespace edsc::model {

namespace {
constexpr bool bit(std::uint32_t v, unsigned n) { return ((v >> n) & 1u) != 0; }
}  // namespace

trigger_transport decode_trigger(std::uint32_t v) {
  trigger_transport t;
  t.transport_classes = static_cast<std::uint16_t>(v & 0xFFFF);
  t.trigger_cyclic = bit(v, 16);
  t.trigger_cos = bit(v, 17);
  t.trigger_application = bit(v, 18);
  t.listen_only = bit(v, 24);
  t.input_only = bit(v, 25);
  t.exclusive_owner = bit(v, 26);
  t.redundant_owner = bit(v, 27);
  t.server = bit(v, 31);
  t.reserved = v & 0x70F80000u;  // bits 19-23 and 28-30
  return t;
}

app_kind classify(const trigger_transport& tt, bool configured) {
  app_kind k;
  k.named = (tt.exclusive_owner ? 1u : 0u) + (tt.input_only ? 1u : 0u) + (tt.listen_only ? 1u : 0u);
  k.type = tt.exclusive_owner ? app_type::exclusive_owner
           : tt.input_only    ? app_type::input_only
           : tt.listen_only   ? app_type::listen_only
                              : app_type::exclusive_owner;
  k.configured = configured;
  return k;
}

connection_params decode_params(std::uint32_t v) {
  connection_params p;
  // O->T uses the lower bit of each pair/nibble, T->O the upper one.
  p.ot.fixed = bit(v, 0);
  p.ot.variable = bit(v, 1);
  p.to.fixed = bit(v, 2);
  p.to.variable = bit(v, 3);
  p.ot.real_time_format = static_cast<std::uint8_t>((v >> 8) & 7);
  p.to.real_time_format = static_cast<std::uint8_t>((v >> 12) & 7);
  auto types = [&](direction_params& d, unsigned base) {
    d.type_null = bit(v, base);
    d.type_multicast = bit(v, base + 1);
    d.type_p2p = bit(v, base + 2);
    d.type_reserved = bit(v, base + 3);
  };
  types(p.ot, 16);
  types(p.to, 20);
  auto prios = [&](direction_params& d, unsigned base) {
    d.prio_low = bit(v, base);
    d.prio_high = bit(v, base + 1);
    d.prio_scheduled = bit(v, base + 2);
    d.prio_reserved = bit(v, base + 3);
  };
  prios(p.ot, 24);
  prios(p.to, 28);
  p.reserved = v & 0x000088F0u;  // bits 4-7 (obsolete), 11, 15
  return p;
}

}  // namespace edsc::model
