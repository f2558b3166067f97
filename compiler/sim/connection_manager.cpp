// The Connection Manager of the simulated device: Forward_Open and
// Large_Forward_Open accepted when the request is what the EDS's ConnectionN
// describes, refused otherwise with the extended status a device sends
// (ETHERNETIP_LIVE.md §4, checked against OpENer's answers on the same
// requests); Forward_Close.
#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cip/device_reply.hpp"
#include "sim/object_table.hpp"
#include "sim/objects.hpp"
#include "sim/refusal.hpp"

namespace edsc::sim {

namespace {

using cip::bytes;

// The refusal sent, and a "refused" line saying why (the status, the
// connection it was held against, the reason in words).
bytes refuse(state& s, const cip::request& q, const cip::forward_open_request& fo, const refusal& r,
             std::uint32_t connection = 0) {
  const auto status = r.bad_config_element ? general::invalid_attribute_value : general::connection_failure;
  std::vector<std::uint16_t> add{r.bad_config_element ? *r.bad_config_element : cip::code(r.status)};
  if (r.size_accepted) add.push_back(*r.size_accepted);
  log_event(s, "refused",
            fmt::format("\"serial\":{},\"originator_vendor\":{},\"originator_serial\":{},\"connection\":{},"
                        "\"status\":\"0x{:02X}\",\"extended\":\"0x{:04X}\",\"why\":{}",
                        fo.connection_serial, fo.originator_vendor, fo.originator_serial, connection, cip::code(status),
                        add.front(), nlohmann::json(r.why).dump()));
  // One status word and at most one after it: always fits.
  return cip::encode_reply_with_status(
             q.service, status, add,
             cip::connection_triple_data(fo.connection_serial, fo.originator_vendor, fo.originator_serial))
      .value();
}

std::string triple(const cip::forward_open_request& fo) {
  return fmt::format("\"serial\":{},\"originator_vendor\":{},\"originator_serial\":{}", fo.connection_serial,
                     fo.originator_vendor, fo.originator_serial);
}

using split_path = connections::connection_path_parts;

// A Forward_Open's connection path split, its key checked first.
std::optional<refusal> split(const state& s, const cip::forward_open_request& fo, split_path& out) {
  auto parts = connections::split_connection_path(fo);
  if (!parts) return refusal{ext::invalid_segment_in_path, {}, "the connection path: " + parts.error().what};
  out = std::move(*parts);
  if (out.key)
    if (auto r = check_key(s.dev.id, *out.key)) return r;
  return std::nullopt;
}

clock::duration timeout_of(const cip::forward_open_request& fo, std::uint32_t rpi) {
  return std::chrono::duration_cast<clock::duration>(std::chrono::microseconds(
      static_cast<std::uint64_t>(rpi) * (4u << std::min<unsigned>(fo.timeout_multiplier, 7))));
}

// Explicit messaging: a class 3 connection to the Message Router.
std::optional<refusal> open_explicit(state& s, const cip::forward_open_request& fo, const split_path& sp,
                                     open_connection& oc, clock::time_point now) {
  cip::path_segment router_class, router_instance;
  router_class.value = 2;  // type is class_id by default
  router_instance.type = cip::segment_type::instance;
  router_instance.value = 1;
  const std::vector<cip::path_segment> router{router_class, router_instance};
  if (sp.app != router)
    return refusal{
        ext::inconsistent_path_combination,
        {},
        "a class 3 connection goes to the Message Router (class 2, instance 1), not to " + path_words(sp.app)};
  if (s.connections.size() >= s.max_connections)
    return refusal{ext::out_of_connections,
                   {},
                   fmt::format("{} connections are open, the most the simulator holds", s.connections.size())};
  oc.ot_id = s.next_connection_id++;
  oc.to_id = fo.to_connection_id != 0 ? fo.to_connection_id : s.next_connection_id++;
  oc.timeout = timeout_of(fo, std::max<std::uint32_t>(fo.ot_rpi_us, 1000));
  oc.expires = now + oc.timeout;
  return std::nullopt;
}

// The configuration a Forward_Open carries, written into the point's configuration assembly.
void take_config(state& s, const connection_point& p, std::optional<cip::byte_view> config) {
  if (!config || p.plan.facts.config_instance == 0) return;
  auto* a = s.dev.assembly(p.plan.facts.config_instance);
  if (a == nullptr) return;
  a->data.assign(config->begin(),
                 config->begin() + static_cast<std::ptrdiff_t>(std::min(config->size(), a->data.size())));
  a->data.resize(p.plan.facts.config_size, 0);
  log_event(s, "config",
            fmt::format("\"instance\":{},\"by\":\"Forward_Open\",\"data\":\"{}\"", a->instance, hex(a->data)));
}

// Class 1 I/O: the first ConnectionN of the same application path that
// accepts the request; else the refusal of the first that had the path.
// `refused_number` is the ConnectionN a refusal was held against.
std::optional<refusal> open_io(state& s, const cip::forward_open_request& fo, const split_path& sp, open_connection& oc,
                               clock::time_point now, std::uint32_t& refused_number) {
  std::optional<refusal> first;
  std::optional<std::size_t> chosen;
  for (std::size_t i = 0; i < s.dev.points.size() && !chosen; ++i) {
    const auto& p = s.dev.points[i];
    if (p.segments.empty() || p.segments != sp.app) continue;
    if (auto r = check_point(s, p, fo, sp.config)) {
      if (!first) first = std::move(r), refused_number = p.number;
    } else {
      chosen = i;
    }
  }
  if (!chosen)
    return first ? first
                 : refusal{ext::inconsistent_path_combination,
                           {},
                           "no ConnectionN has the application path " + path_words(sp.app)};
  oc.point = chosen;
  oc.consumes = fo.ot.type != cip::conn_type::null;
  oc.produces = fo.to.type != cip::conn_type::null;
  oc.ot_id = s.next_connection_id++;
  oc.to_id = fo.to.type == cip::conn_type::point_to_point && fo.to_connection_id != 0 ? fo.to_connection_id
                                                                                      : s.next_connection_id++;
  oc.timeout = timeout_of(fo, oc.consumes ? fo.ot_rpi_us : fo.to_rpi_us);
  oc.expires = now + oc.timeout;
  oc.next_produce = now;
  take_config(s, s.dev.points[*chosen], sp.config);
  return std::nullopt;
}

// The connection opened: logged, kept, and the success reply.
bytes accept(state& s, const cip::request& q, const cip::forward_open_request& fo, const open_connection& oc) {
  log_event(
      s, "open",
      fmt::format("{},\"connection\":{},\"class\":{},\"ot_rpi_us\":{},\"to_rpi_us\":{}", triple(fo),
                  oc.point ? s.dev.points[*oc.point].number : 0, fo.transport & 0x0F, fo.ot_rpi_us, fo.to_rpi_us));
  s.connections.push_back(oc);
  const auto rep = cip::granted(fo, oc.ot_id, oc.to_id);
  return cip::encode_reply(q.service, general::success,
                           cip::forward_open_ok_data(rep).value());  // no application reply: fits
}

bytes forward_open(state& s, const link& l, const cip::request& q, clock::time_point now) {
  const bool large = q.service == cip::service::large_forward_open;
  auto parsed = cip::decode_forward_open(q.data, large, 0);
  if (!parsed) {
    log_event(s, "refused",
              fmt::format("\"status\":\"0x{:02X}\",\"why\":{}", cip::code(general::not_enough_data),
                          nlohmann::json("the Forward_Open cannot be read: " + parsed.error().what).dump()));
    return cip::encode_reply(q.service, general::not_enough_data);
  }
  const auto& fo = parsed.value();
  for (const auto& o : s.connections)
    if (o.serial == fo.connection_serial && o.vendor == fo.originator_vendor &&
        o.originator_serial == fo.originator_serial)
      return refuse(s, q, fo,
                    {ext::connection_in_use,
                     {},
                     fmt::format("a connection of serial {}, originator vendor {} and serial {} is already open",
                                 fo.connection_serial, fo.originator_vendor, fo.originator_serial)});
  split_path sp;
  if (auto r = split(s, fo, sp)) return refuse(s, q, fo, *r);
  const unsigned transport_class = fo.transport & 0x0F;
  if (transport_class != 1 && transport_class != 3)
    return refuse(s, q, fo,
                  {ext::transport_class_not_supported,
                   {},
                   fmt::format("transport class {} asked; the simulator serves classes 1 and 3", transport_class)});
  open_connection oc;
  oc.serial = fo.connection_serial;
  oc.vendor = fo.originator_vendor;
  oc.originator_serial = fo.originator_serial;
  oc.originator_ip = l.peer_ip;
  oc.ot_rpi_us = fo.ot_rpi_us;
  oc.to_rpi_us = fo.to_rpi_us;
  std::uint32_t refused_number = 0;
  auto r = transport_class == 3 ? open_explicit(s, fo, sp, oc, now) : open_io(s, fo, sp, oc, now, refused_number);
  if (r) return refuse(s, q, fo, *r, refused_number);
  return accept(s, q, fo, oc);
}

bytes forward_close(state& s, const cip::request& q) {
  auto parsed = cip::decode_forward_close_request(q.data, 0);
  if (!parsed) return cip::encode_reply(q.service, general::not_enough_data);
  const auto& fc = parsed.value();
  const auto it = std::find_if(s.connections.begin(), s.connections.end(), [&](const open_connection& o) {
    return o.serial == fc.connection_serial && o.vendor == fc.originator_vendor &&
           o.originator_serial == fc.originator_serial;
  });
  if (it == s.connections.end()) {
    const std::uint16_t add[] = {cip::code(ext::connection_not_found)};
    return cip::encode_reply_with_status(
               q.service, general::connection_failure, add,
               cip::connection_triple_data(fc.connection_serial, fc.originator_vendor, fc.originator_serial))
        .value();  // one word: always fits
  }
  log_event(
      s, "close",
      fmt::format("\"serial\":{},\"originator_vendor\":{},\"originator_serial\":{},\"produced\":{},\"consumed\":{}",
                  fc.connection_serial, fc.originator_vendor, fc.originator_serial, it->produced, it->consumed));
  s.connections.erase(it);
  close_orphans(s);
  return cip::encode_reply(
      q.service, general::success,
      cip::connection_triple_data(fc.connection_serial, fc.originator_vendor, fc.originator_serial));
}

}  // namespace

object_table connection_manager_table() {
  object_table t;
  t.class_id = cip::code(cip::class_id::connection_manager);
  t.exists = [](const state&, std::uint32_t i) { return i == 1; };
  t.attribute_paths = false;
  const auto open = [](object_call& c) { return forward_open(c.s, c.l, c.q, c.now); };
  t.services = {{cip::service::forward_open, open},
                {cip::service::large_forward_open, open},
                {cip::service::forward_close, [](object_call& c) { return forward_close(c.s, c.q); }}};
  return t;
}

}  // namespace edsc::sim
