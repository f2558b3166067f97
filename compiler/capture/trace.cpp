#include "capture/trace.hpp"

#include <fmt/format.h>

#include "cip/codes.hpp"
#include "cip/io_frame.hpp"
#include "cip/message.hpp"
#include "cip/request.hpp"

namespace edsc::capture {

namespace {

constexpr std::size_t header = cip::encap_header_size;

bool is(std::uint8_t s, cip::service want) { return s == cip::code(want); }

std::uint32_t le32(cip::byte_view b) {
  return std::uint32_t{b[0]} | (std::uint32_t{b[1]} << 8) | (std::uint32_t{b[2]} << 16) | (std::uint32_t{b[3]} << 24);
}

// The connection a Forward_Close names: its triad, the latest opened first.
connection_seen* by_triad(std::vector<connection_seen>& cs, const cip::forward_close_request& fc) {
  for (auto it = cs.rbegin(); it != cs.rend(); ++it) {
    const auto& q = it->request;
    if (q.connection_serial == fc.connection_serial && q.originator_vendor == fc.originator_vendor &&
        q.originator_serial == fc.originator_serial)
      return &*it;
  }
  return nullptr;
}

// What the judge reads of an explicit request: an Identity Get_Attributes_All
// or a write, with the object it addresses.
enum class judged : std::uint8_t { none, identity, write };
struct judged_target {
  judged what = judged::none;
  cip::object_address where;
};
judged_target judged_request(const cip::request& q, std::size_t base) {
  const auto s = cip::code(q.service);
  auto path = cip::decode_path(q.path, base + 2);
  const auto where = path ? cip::address_of(*path) : std::nullopt;
  if (!where) return {};
  if (is(s, cip::service::get_attributes_all) && where->class_id == cip::code(cip::class_id::identity) &&
      where->instance == 1)
    return {judged::identity, *where};
  if (is(s, cip::service::set_attribute_single) || is(s, cip::service::set_attributes_all))
    return {judged::write, *where};
  return {};
}

}  // namespace

std::uint64_t connection_seen::timeout_us(bool originator_to_target) const {
  const std::uint64_t multiplier = std::uint64_t{4} << std::min<unsigned>(request.timeout_multiplier, 7);
  return multiplier * (originator_to_target ? request.ot_rpi_us : request.to_rpi_us);
}

void tracker::add(const message& m) {
  const bool io_port = m.source.port == cip::io_port || m.destination.port == cip::io_port;
  if (m.via == transport::udp && io_port)
    io(m);
  else
    encapsulation(m);
}

void tracker::problem(const message& m, std::string what) {
  if (problems_.size() < limits_.max_undecodable)
    problems_.push_back({m.frame, std::move(what)});
  else
    ++over_limits_;
}

// Scanners ask ListIdentity again and again: past a limit the answers are
// counted, not kept, so a long capture's memory stays bounded.
void tracker::identity(const message& m, cip::identity id) {
  if (identities_.size() >= limits_.max_identities) return void(++over_limits_);
  identities_.push_back({m.source.address, std::move(id), m.frame});
}

void tracker::encapsulation(const message& m) {
  const cip::byte_view b = m.payload;
  auto h = cip::decode_encap_header(b);
  if (!h) return problem(m, fmt::format("encapsulation header: {}", h.error().what));
  const auto data = b.subspan(header);
  if (data.size() != h->length)
    return problem(m, fmt::format("encapsulation length {} but {} bytes follow the header", h->length, data.size()));
  const auto cmd = static_cast<cip::command>(h->command);
  if (cmd == cip::command::list_identity && !data.empty()) {
    auto ids = cip::decode_list_identity(data, header);
    if (!ids) return problem(m, fmt::format("ListIdentity reply: {}", ids.error().what));
    for (auto& id : *ids) identity(m, std::move(id));
    return;
  }
  if (cmd != cip::command::send_rr_data) return;  // sessions, ListServices: nothing to judge
  auto cip = cip::decode_send_rr_data(data, header);
  if (!cip) return problem(m, fmt::format("SendRRData: {}", cip.error().what));
  if (cip->empty()) return problem(m, "SendRRData without a CIP message");
  if (((*cip)[0] & 0x80) != 0)
    reply(m, *h, *cip);
  else
    request(m, *h, *cip);
}

void tracker::request(const message& m, const cip::encap_header& h, cip::byte_view cip) {
  const auto base = static_cast<std::size_t>(cip.data() - m.payload.data());
  auto q = cip::decode_request(cip, base);
  if (!q) return problem(m, fmt::format("CIP request: {}", q.error().what));
  const auto s = cip::code(q->service);
  const auto key = key_of(m.source, m.destination, h);
  const auto data_base = static_cast<std::size_t>(q->data.data() - m.payload.data());
  if (pending_.size() >= limits_.max_pending_requests) {
    ++over_limits_;  // replies that never came: the oldest waits are forgotten
    pending_.erase(pending_.begin());
  }
  if (is(s, cip::service::forward_open) || is(s, cip::service::large_forward_open)) {
    const bool large = is(s, cip::service::large_forward_open);
    auto fo = cip::decode_forward_open(q->data, large, data_base);
    if (!fo) return problem(m, fmt::format("{}: {}", large ? "Large_Forward_Open" : "Forward_Open", fo.error().what));
    if (connections_.size() >= limits_.max_connections) return void(++over_limits_);
    connection_seen c;
    c.originator = m.source;
    c.target = m.destination;
    c.request_frame = m.frame;
    c.request_ns = m.time.total_ns();
    c.large = large;
    c.request = std::move(*fo);
    connections_.push_back(std::move(c));
    pending_[key] = {pending::kind::forward_open, connections_.size() - 1};
    return;
  }
  if (is(s, cip::service::forward_close)) {
    auto fc = cip::decode_forward_close_request(q->data, data_base);
    if (!fc) return problem(m, fmt::format("Forward_Close: {}", fc.error().what));
    if (auto* c = by_triad(connections_, *fc); c != nullptr && c->close_frame == 0) {
      c->close_frame = m.frame;
      c->close_ns = m.time.total_ns();
    }
    return;
  }
  if (is(s, cip::service::unconnected_send)) return unconnected(m, key, *q, base);
  explicit_request(m, key, *q, base);
}

// Service 0x52 is Unconnected_Send only at the Connection Manager; to other
// objects it is their own service (a Logix tag's Read Tag Fragmented).
void tracker::unconnected(const message& m, const request_key& key, const cip::request& q, std::size_t base) {
  auto path = cip::decode_path(q.path, base + 2);
  const auto where = path ? cip::address_of(*path) : std::nullopt;
  if (!where || where->class_id != cip::code(cip::class_id::connection_manager) || where->instance != 1) return;
  const auto data_base = static_cast<std::size_t>(q.data.data() - m.payload.data());
  auto us = cip::decode_unconnected_send(q.data, data_base);
  if (!us) return problem(m, fmt::format("Unconnected_Send: {}", us.error().what));
  const auto inner_base = static_cast<std::size_t>(us->message.data() - m.payload.data());
  auto inner = cip::decode_request(us->message, inner_base);
  if (!inner) return problem(m, fmt::format("request inside an Unconnected_Send: {}", inner.error().what));
  // Only an empty route leaves the request with the device at the capture's
  // address. Any port segment sends it on: to another node, or on the
  // backplane to the module in a slot, which is generally not the adapter
  // whose EDS its address matched. Such a request is counted, not judged.
  if (!us->route.empty()) {
    if (judged_request(*inner, inner_base).what != judged::none) ++routed_;
    return;
  }
  explicit_request(m, key, *inner, inner_base);
}

void tracker::explicit_request(const message& m, const request_key& key, const cip::request& q, std::size_t base) {
  const auto t = judged_request(q, base);
  if (t.what == judged::identity) {
    pending_[key] = {pending::kind::identity, 0};
    return;
  }
  if (t.what != judged::write) return;
  if (writes_.size() >= limits_.max_writes) return void(++over_limits_);
  writes_.push_back({m.source, m.destination, m.frame, cip::code(q.service), t.where.class_id, t.where.instance,
                     t.where.attribute, std::vector<std::uint8_t>(q.data.begin(), q.data.end()), std::nullopt});
  pending_[key] = {pending::kind::write, writes_.size() - 1};
}

// Paired by key, whatever the reply's service: an Unconnected_Send's reply
// is the embedded service's own, or 0xD2 with the error when routing failed.
void tracker::reply(const message& m, const cip::encap_header& h, cip::byte_view cip) {
  const auto it = pending_.find(key_of(m.destination, m.source, h));
  if (it == pending_.end()) return;  // a reply to a request before the capture began, or to one not tracked
  const auto p = it->second;
  pending_.erase(it);
  const auto base = static_cast<std::size_t>(cip.data() - m.payload.data());
  auto r = cip::decode_reply(cip, base);
  if (!r) return problem(m, fmt::format("CIP reply: {}", r.error().what));
  switch (p.what) {
    case pending::kind::forward_open: return forward_open_reply(connections_[p.index], m, *r);
    case pending::kind::write: writes_[p.index].reply_general = r->general; return;
    case pending::kind::identity: {
      if (r->general != 0) return;
      auto id = cip::decode_identity_all(r->data, base + 4 + 2 * r->additional.size());
      if (!id) return problem(m, fmt::format("Identity Get_Attributes_All reply: {}", id.error().what));
      identity(m, std::move(*id));
      return;
    }
  }
}

void tracker::forward_open_reply(connection_seen& c, const message& m, const cip::reply& r) {
  c.reply_frame = m.frame;
  c.reply_ns = m.time.total_ns();
  c.general = r.general;
  c.additional = r.additional;
  if (r.general != 0) return;
  auto ok = cip::decode_forward_open_ok(r.data, 0);
  if (!ok) return problem(m, fmt::format("Forward_Open reply: {}", ok.error().what));
  const auto index = static_cast<std::size_t>(&c - connections_.data());
  by_id_[{ok->ot_connection_id, c.originator.address}] = {index, true};
  by_id_[{ok->to_connection_id, c.target.address}] = {index, false};
  c.granted = std::move(*ok);
}

void tracker::io(const message& m) {
  auto f = cip::decode_io_frame(m.payload, false);
  if (!f) return problem(m, fmt::format("class 0/1 frame: {}", f.error().what));
  const auto it = by_id_.find({f->connection_id, m.source.address});
  if (it == by_id_.end()) {
    if (orphans_.size() < limits_.max_connections || orphans_.count(f->connection_id) != 0)
      ++orphans_[f->connection_id];
    else
      ++over_limits_;
    return;
  }
  auto& c = connections_[it->second.first];
  const bool ot = it->second.second;
  auto& d = ot ? c.ot : c.to;
  // The connected data item: the sequence count and all after it.
  const auto size = static_cast<std::uint32_t>(2 + f->data.size());
  const auto asked = ot ? c.request.ot.size : c.request.to.size;
  if (size != asked && d.size_mismatch_frame == 0) d.size_mismatch_frame = m.frame;
  const auto now = m.time.total_ns();
  if (d.frames == 0) {
    d.first_frame = m.frame;
    d.first_ns = now;
    d.min_size = d.max_size = size;
  } else {
    const auto us = static_cast<std::uint64_t>(std::max<std::int64_t>(now - d.last_ns, 0) / 1000);
    d.intervals.add(us, m.frame);
    const auto limit = c.timeout_us(ot);
    if (limit > 0 && us > limit && c.close_frame == 0 && c.timeout_after_frame == 0) {
      c.timeout_after_frame = d.last_frame;
      c.timeout_ot = ot;
    }
    const std::uint32_t step = f->encap_sequence - d.last_sequence;  // modulo 2^32
    if (step >= 0x80000000u)
      ++d.out_of_order;
    else if (step > 1)
      d.lost += step - 1;
    d.min_size = std::min(d.min_size, size);
    d.max_size = std::max(d.max_size, size);
  }
  ++d.frames;
  d.last_frame = m.frame;
  d.last_ns = now;
  d.last_sequence = f->encap_sequence;
  if (f->data.size() >= 4) mode(d, (le32(f->data) & 1) != 0, m.frame);
}

void tracker::mode(io_direction& d, bool run, std::uint64_t frame) {
  if (!d.run_now) {
    d.run_now = run;
    return;
  }
  if (*d.run_now == run) return;
  d.run_now = run;
  ++d.change_count;
  if (d.changes.size() < limits_.max_mode_changes) d.changes.push_back({frame, run});
}

// A direction silent for longer than its timeout before its Forward_Close
// (the device died and the scanner closed after) or before the capture's
// end timed out; a silence after the close is the close's doing.
void tracker::finish(std::int64_t end_ns) {
  for (auto& c : connections_) {
    if (!c.granted || c.timeout_after_frame != 0) continue;
    const auto until_ns = c.close_frame != 0 ? c.close_ns : end_ns;
    for (const bool ot : {true, false}) {
      const auto& d = ot ? c.ot : c.to;
      const auto type = ot ? c.request.ot.type : c.request.to.type;
      if (type == cip::conn_type::null) continue;
      const auto since_ns = d.frames > 0 ? d.last_ns : c.reply_ns;
      const auto silent_us = static_cast<std::uint64_t>(std::max<std::int64_t>(until_ns - since_ns, 0) / 1000);
      if (silent_us > c.timeout_us(ot)) {
        c.timeout_after_frame = d.frames > 0 ? d.last_frame : c.reply_frame;
        c.timeout_ot = ot;
        break;
      }
    }
  }
}

}  // namespace edsc::capture
