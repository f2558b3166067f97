// The Connection Manager of the simulated device: Forward_Open and
// Large_Forward_Open accepted when the request is what the EDS's ConnectionN
// describes, refused otherwise with the extended status a device sends
// (ETHERNETIP_LIVE.md §4, checked against OpENer's answers on the same
// requests); Forward_Close.
#include <algorithm>

#include <fmt/format.h>

#include "cip/device_reply.hpp"
#include "sim/objects.hpp"

namespace edsc::sim {

namespace {

using cip::bytes;

namespace ext {
constexpr std::uint16_t in_use = 0x0100, transport_trigger = 0x0103, ownership = 0x0106, not_found = 0x0107,
                        fixed_variable = 0x0109, rpi = 0x0111, out_of_connections = 0x0113, vendor_code = 0x0114,
                        device_type = 0x0115, revision = 0x0116, no_owner = 0x0119, transport_class = 0x011C,
                        ot_type = 0x0123, to_type = 0x0124, ot_size = 0x0127, to_size = 0x0128,
                        config_path = 0x0129, inconsistent_path = 0x012F, bad_segment = 0x0315;
}

struct refusal {
  std::uint16_t status = 0;
  std::optional<std::uint16_t> additional;  // the size the device accepts (0x0127, 0x0128)
};

bytes refuse(const cip::request& q, const cip::forward_open_request& fo, refusal r) {
  std::vector<std::uint16_t> add{r.status};
  if (r.additional) add.push_back(*r.additional);
  return cip::encode_reply(q.service, general::connection_failure, add, cip::connection_triple_data(fo.connection_serial, fo.originator_vendor, fo.originator_serial));
}

// [Device] against the key: zero fields match anything; exact keying wants
// the same major and minor, compatible keying the same major and a minor the
// device reaches.
std::optional<refusal> check_key(const cip::identity& id, const cip::electronic_key& k) {
  if ((k.vendor != 0 && k.vendor != id.vendor) || (k.product_code != 0 && k.product_code != id.product_code))
    return refusal{ext::vendor_code, {}};
  if (k.device_type != 0 && k.device_type != id.device_type) return refusal{ext::device_type, {}};
  if (k.major != 0) {
    if (k.major != id.major) return refusal{ext::revision, {}};
    if (k.compatible ? (k.minor > id.minor) : (k.minor != 0 && k.minor != id.minor)) return refusal{ext::revision, {}};
  }
  return std::nullopt;
}

bool type_allowed(const model::direction_params& d, cip::conn_type t) {
  if (!d.type_null && !d.type_multicast && !d.type_p2p) return true;  // the EDS says nothing: take any
  switch (t) {
    case cip::conn_type::null: return d.type_null;
    case cip::conn_type::multicast: return d.type_multicast;
    case cip::conn_type::point_to_point: return d.type_p2p;
    default: return false;
  }
}

bool owner_producing(const state& s, std::uint32_t input_instance) {
  for (const auto& c : s.connections)
    if (c.point && s.dev.points[*c.point].kind != point_kind::listen_only &&
        s.dev.points[*c.point].plan.facts.input_instance == input_instance)
      return true;
  return false;
}

// Why `fo` cannot open `p`, in the order a device looks: transport, types,
// sizes, RPI, configuration, then who already holds what.
std::optional<refusal> check_point(const state& s, const connection_point& p, const cip::forward_open_request& fo,
                                   std::optional<cip::byte_view> config) {
  const auto& c = *p.plan.conn;
  const unsigned trigger = (fo.transport >> 4) & 0x07;
  const bool trigger_ok = (trigger == 0 && c.tt.trigger_cyclic) || (trigger == 1 && c.tt.trigger_cos) ||
                          (trigger == 2 && c.tt.trigger_application);
  if ((fo.transport & 0x0F) != 1 || !trigger_ok) return refusal{ext::transport_trigger, {}};
  if (!type_allowed(c.cp.ot, fo.ot.type)) return refusal{ext::ot_type, {}};
  if (!type_allowed(c.cp.to, fo.to.type)) return refusal{ext::to_type, {}};
  const auto& want = p.plan.request;
  const auto want_ot = live::network_size(p.plan.facts.output_size, p.plan.ot_run_idle);
  const auto want_to = live::network_size(p.plan.facts.input_size, p.plan.to_run_idle);
  if (fo.ot.type != cip::conn_type::null) {
    if (fo.ot.variable && !c.cp.ot.variable) return refusal{ext::fixed_variable, {}};
    if (fo.ot.variable ? fo.ot.size > want_ot : fo.ot.size != want_ot) return refusal{ext::ot_size, want_ot};
  }
  if (fo.to.type != cip::conn_type::null) {
    if (fo.to.variable && !c.cp.to.variable) return refusal{ext::fixed_variable, {}};
    if (fo.to.variable ? fo.to.size > want_to : fo.to.size != want_to) return refusal{ext::to_size, want_to};
  }
  (void)want;
  const auto within = [](const rpi_limits& r, std::uint32_t rpi) { return rpi >= r.min_us && rpi <= r.max_us; };
  if ((fo.ot.type != cip::conn_type::null && !within(p.ot_rpi, fo.ot_rpi_us)) ||
      (fo.to.type != cip::conn_type::null && !within(p.to_rpi, fo.to_rpi_us)))
    return refusal{ext::rpi, {}};
  if (config) {
    const auto want_cfg = p.plan.facts.config_size;
    // The data segment counts words: an odd configuration size arrives padded.
    if (config->size() != want_cfg && config->size() != want_cfg + (want_cfg % 2)) return refusal{ext::config_path, {}};
  }
  if (s.connections.size() >= s.max_connections) return refusal{ext::out_of_connections, {}};
  if (p.kind == point_kind::exclusive_owner)
    for (const auto& o : s.connections)
      if (o.point && s.dev.points[*o.point].kind == point_kind::exclusive_owner &&
          s.dev.points[*o.point].plan.facts.output_instance == p.plan.facts.output_instance)
        return refusal{ext::ownership, {}};
  if (p.kind == point_kind::listen_only && !owner_producing(s, p.plan.facts.input_instance))
    return refusal{ext::no_owner, {}};
  return std::nullopt;
}

std::string triple(const cip::forward_open_request& fo) {
  return fmt::format("\"serial\":{},\"originator_vendor\":{},\"originator_serial\":{}", fo.connection_serial,
                     fo.originator_vendor, fo.originator_serial);
}

bytes forward_open(state& s, const link& l, const cip::request& q, clock::time_point now) {
  const bool large = q.service == cip::service::large_forward_open;
  auto parsed = cip::decode_forward_open(q.data, large, 0);
  if (!parsed) return cip::encode_reply(q.service, general::not_enough_data);
  const auto& fo = parsed.value();
  for (const auto& o : s.connections)
    if (o.serial == fo.connection_serial && o.vendor == fo.originator_vendor &&
        o.originator_serial == fo.originator_serial)
      return refuse(q, fo, {ext::in_use, {}});
  auto segs = cip::decode_path(fo.path, 0);
  if (!segs) return refuse(q, fo, {ext::bad_segment, {}});
  std::vector<cip::path_segment> app;
  std::optional<cip::byte_view> config;
  for (const auto& sg : segs.value()) {
    if (sg.type == cip::segment_type::key) {
      if (auto r = check_key(s.dev.id, sg.key)) return refuse(q, fo, *r);
    } else if (sg.type == cip::segment_type::data) {
      config = sg.data;
    } else {
      app.push_back(sg);
    }
  }
  const unsigned transport_class = fo.transport & 0x0F;
  const auto new_id = [&s] { return s.next_connection_id++; };
  const auto timeout_of = [&](std::uint32_t rpi) {
    return std::chrono::duration_cast<clock::duration>(std::chrono::microseconds(
        static_cast<std::uint64_t>(rpi) * (4u << std::min<unsigned>(fo.timeout_multiplier, 7))));
  };
  open_connection oc;
  oc.serial = fo.connection_serial;
  oc.vendor = fo.originator_vendor;
  oc.originator_serial = fo.originator_serial;
  oc.originator_ip = l.peer_ip;
  oc.ot_rpi_us = fo.ot_rpi_us;
  oc.to_rpi_us = fo.to_rpi_us;
  if (transport_class == 3) {
    // Explicit messaging: a class 3 connection to the Message Router.
    cip::path_segment router_class, router_instance;
    router_class.value = 2;  // type is class_id by default
    router_instance.type = cip::segment_type::instance;
    router_instance.value = 1;
    const std::vector<cip::path_segment> router{router_class, router_instance};
    if (app != router) return refuse(q, fo, {ext::inconsistent_path, {}});
    if (s.connections.size() >= s.max_connections) return refuse(q, fo, {ext::out_of_connections, {}});
    oc.ot_id = new_id();
    oc.to_id = fo.to_connection_id != 0 ? fo.to_connection_id : new_id();
    oc.timeout = timeout_of(std::max<std::uint32_t>(fo.ot_rpi_us, 1000));
    oc.expires = now + oc.timeout;
  } else if (transport_class != 1) {
    return refuse(q, fo, {ext::transport_class, {}});
  } else {
    std::optional<refusal> first;
    std::optional<std::size_t> chosen;
    for (std::size_t i = 0; i < s.dev.points.size() && !chosen; ++i) {
      const auto& p = s.dev.points[i];
      if (p.segments.empty() || p.segments != app) continue;
      if (auto r = check_point(s, p, fo, config)) {
        if (!first) first = r;
      } else {
        chosen = i;
      }
    }
    if (!chosen) return refuse(q, fo, first.value_or(refusal{ext::inconsistent_path, {}}));
    const auto& p = s.dev.points[*chosen];
    oc.point = chosen;
    oc.consumes = fo.ot.type != cip::conn_type::null;
    oc.produces = fo.to.type != cip::conn_type::null;
    oc.ot_id = new_id();
    oc.to_id = fo.to.type == cip::conn_type::point_to_point && fo.to_connection_id != 0 ? fo.to_connection_id : new_id();
    oc.timeout = timeout_of(oc.consumes ? fo.ot_rpi_us : fo.to_rpi_us);
    oc.expires = now + oc.timeout;
    oc.next_produce = now;
    if (config && p.plan.facts.config_instance != 0)
      if (auto* a = s.dev.assembly(p.plan.facts.config_instance)) {
        a->data.assign(config->begin(), config->begin() + static_cast<std::ptrdiff_t>(std::min(config->size(), a->data.size())));
        a->data.resize(p.plan.facts.config_size, 0);
        log_event(s, "config", fmt::format("\"instance\":{},\"by\":\"Forward_Open\",\"data\":\"{}\"",
                                           a->instance, hex(a->data)));
      }
  }
  cip::forward_open_reply rep;
  rep.ot_connection_id = oc.ot_id;
  rep.to_connection_id = oc.to_id;
  rep.connection_serial = fo.connection_serial;
  rep.originator_vendor = fo.originator_vendor;
  rep.originator_serial = fo.originator_serial;
  rep.ot_api_us = fo.ot_rpi_us;
  rep.to_api_us = fo.to_rpi_us;
  log_event(s, "open",
            fmt::format("{},\"connection\":{},\"class\":{},\"ot_rpi_us\":{},\"to_rpi_us\":{}", triple(fo),
                        oc.point ? s.dev.points[*oc.point].number : 0, transport_class, fo.ot_rpi_us, fo.to_rpi_us));
  s.connections.push_back(oc);
  return cip::encode_reply(q.service, 0, {}, cip::forward_open_ok_data(rep));
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
    const std::uint16_t add[] = {ext::not_found};
    return cip::encode_reply(q.service, general::connection_failure, add,
                             cip::connection_triple_data(fc.connection_serial, fc.originator_vendor, fc.originator_serial));
  }
  log_event(s, "close", fmt::format("\"serial\":{},\"originator_vendor\":{},\"originator_serial\":{},\"produced\":{},\"consumed\":{}",
                                    fc.connection_serial, fc.originator_vendor, fc.originator_serial, it->produced,
                                    it->consumed));
  s.connections.erase(it);
  close_orphans(s);
  return cip::encode_reply(q.service, 0, {}, cip::connection_triple_data(fc.connection_serial, fc.originator_vendor, fc.originator_serial));
}

}  // namespace

bytes connection_manager(state& s, const link& l, const cip::request& q, const cip::object_address& a,
                         clock::time_point now) {
  if (a.instance != 1 || a.attribute) return cip::encode_reply(q.service, general::path_unknown);
  switch (q.service) {
    case cip::service::forward_open:
    case cip::service::large_forward_open: return forward_open(s, l, q, now);
    case cip::service::forward_close: return forward_close(s, q);
    default: return cip::encode_reply(q.service, general::not_supported);
  }
}

}  // namespace edsc::sim
