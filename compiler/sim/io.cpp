// Class 1 I/O of the simulated device: O->T frames consumed and checked for
// size, T->O frames produced at the granted interval with sequence counts and
// the run/idle header the EDS's format asks for, and connections closed
// when their consumer timeout passes (multiplier x RPI without a frame).
#include <algorithm>

#include <fmt/format.h>

#include "cip/io_frame.hpp"
#include "sim/objects.hpp"
#include "sim/too_large.hpp"

namespace edsc::sim {

namespace {

// The counter pattern of input data: byte i of an input assembly is tick + i.
void advance_inputs(state& s) {
  ++s.input_tick;
  for (auto& a : s.dev.assemblies)
    if (a.role == assembly_role::input && !a.fixed)
      for (std::size_t i = 0; i < a.data.size(); ++i) a.data[i] = static_cast<std::uint8_t>(s.input_tick + i);
}

void expire(state& s, clock::time_point now) {
  bool removed = false;
  for (auto it = s.connections.begin(); it != s.connections.end();) {
    if (it->expires <= now) {
      log_event(s, "timeout",
                fmt::format("\"serial\":{},\"originator_vendor\":{},\"originator_serial\":{},"
                            "\"produced\":{},\"consumed\":{}",
                            it->serial, it->vendor, it->originator_serial, it->produced, it->consumed));
      it = s.connections.erase(it);
      removed = true;
    } else {
      ++it;
    }
  }
  if (removed) close_orphans(s);
}

// Closes the connections producing to `to_ids`, whose frames cannot be sent.
void close_unsendable(state& s, const std::vector<std::uint32_t>& to_ids) {
  std::erase_if(s.connections, [&](const open_connection& c) {
    if (std::find(to_ids.begin(), to_ids.end(), c.to_id) == to_ids.end()) return false;
    log_event(s, "close",
              fmt::format("\"serial\":{},\"originator_vendor\":{},\"originator_serial\":{},"
                          "\"why\":\"its frames do not fit a class 1 frame\"",
                          c.serial, c.vendor, c.originator_serial));
    return true;
  });
  close_orphans(s);
}

}  // namespace

void close_orphans(state& s) {
  auto has_owner = [&](std::uint32_t input) {
    for (const auto& c : s.connections)
      if (c.point && s.dev.points[*c.point].kind != model::app_type::listen_only &&
          s.dev.points[*c.point].plan.facts.input_instance == input)
        return true;
    return false;
  };
  std::erase_if(s.connections, [&](const open_connection& c) {
    if (!c.point || s.dev.points[*c.point].kind != model::app_type::listen_only) return false;
    if (has_owner(s.dev.points[*c.point].plan.facts.input_instance)) return false;
    log_event(s, "close",
              fmt::format("\"serial\":{},\"originator_vendor\":{},\"originator_serial\":{},"
                          "\"why\":\"its owner closed\"",
                          c.serial, c.vendor, c.originator_serial));
    return true;
  });
}

void consume_io(state& s, cip::byte_view frame, std::uint32_t from_ip, clock::time_point now) {
  auto head = cip::decode_io_frame(frame, false);
  if (!head) return;
  open_connection* c = nullptr;
  for (auto& o : s.connections)
    if (o.point && o.consumes && o.ot_id == head->connection_id && o.originator_ip == from_ip) c = &o;
  if (c == nullptr) return;  // not ours, or from someone else: ignored as a device does
  const auto& p = s.dev.points[*c->point];
  auto f = cip::decode_io_frame(frame, p.plan.ot_run_idle && p.plan.facts.output_size > 0);
  if (!f) return;
  if (f->data.size() != p.plan.facts.output_size) {
    if (c->wrong_size++ == 0)
      log_event(s, "wrong-size",
                fmt::format("\"connection\":{},\"bytes\":{},\"expected\":{}", p.number, f->data.size(),
                            p.plan.facts.output_size));
    return;  // a frame of the wrong size does not refresh the timeout
  }
  c->expires = now + c->timeout;
  ++c->consumed;
  const bool fresh = !c->consumed_any || f->sequence_count != c->last_consumed_sequence;
  c->consumed_any = true;
  c->last_consumed_sequence = f->sequence_count;
  const bool run = f->run_idle && (*f->run_idle & 1);
  const bool run_changed = run != c->run;  // a PLC going to program mode may keep its data
  c->run = run;
  if ((!fresh && !run_changed) || p.plan.facts.output_size == 0) return;
  auto* a = s.dev.assembly(p.plan.facts.output_instance);
  if (a == nullptr) return;
  if (a->data != f->data || c->consumed == 1 || run_changed) {
    a->data = f->data;
    log_event(s, "output",
              fmt::format("\"instance\":{},\"connection\":{},\"run\":{},\"sequence\":{},\"data\":\"{}\"", a->instance,
                          p.number, run, f->sequence_count, hex(a->data)));
  }
}

std::vector<outgoing> produce_io(state& s, clock::time_point now) {
  expire(s, now);
  std::vector<outgoing> out;
  std::vector<std::uint32_t> unsendable;  // T->O ids of frames too large to send
  bool ticked = false;
  for (auto& c : s.connections) {
    if (!c.point || !c.produces || c.next_produce > now) continue;
    if (!ticked) {
      advance_inputs(s);
      ticked = true;
    }
    const auto& p = s.dev.points[*c.point];
    cip::io_frame f;
    f.connection_id = c.to_id;
    f.encap_sequence = ++c.encap_sequence;
    f.sequence_count = ++c.sequence;
    if (p.plan.to_run_idle && p.plan.facts.input_size > 0) f.run_idle = 1;  // the simulated device runs
    if (const auto* a = s.dev.assembly(p.plan.facts.input_instance)) f.data = a->data;
    f.data.resize(p.plan.facts.input_size, 0);
    auto frame = cip::encode_io_frame(f);
    if (!frame) {
      log_too_large(s, "class 1 frame", frame.error());
      unsendable.push_back(c.to_id);
      continue;
    }
    out.push_back({c.originator_ip, std::move(frame).value()});
    ++c.produced;
    const auto period =
        std::chrono::duration_cast<clock::duration>(std::chrono::microseconds(std::max(c.to_rpi_us, 100u)));
    c.next_produce += period;
    if (c.next_produce <= now) {  // fell behind by a whole period: count it, do not burst
      ++c.late;
      c.next_produce = now + period;
    }
  }
  if (!unsendable.empty()) close_unsendable(s, unsendable);
  return out;
}

std::optional<clock::time_point> next_deadline(const state& s) {
  std::optional<clock::time_point> t;
  for (const auto& c : s.connections) {
    if (!t || c.expires < *t) t = c.expires;
    if (c.point && c.produces && c.next_produce < *t) t = c.next_produce;
  }
  return t;
}

}  // namespace edsc::sim
