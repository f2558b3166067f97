#include "connections/capacity.hpp"

#include <cctype>
#include <string_view>

namespace edsc::connections {
namespace {

bool same_word(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// A field that is a non-negative integer: anything else is the checker's to
// report and no limit here. The schema's UINT/UDINT already refuse a sign;
// the test of `negative` keeps a schema change from making one a count.
std::optional<std::uint64_t> count_of(const model::value* v) {
  if (v == nullptr || !v->is_integer() || v->negative) return std::nullopt;
  return v->as_uint();
}

std::optional<stated_count> count_setting(const model::capacity& cap, std::string_view keyword) {
  const auto* s = cap.find(keyword);
  if (s == nullptr) return std::nullopt;
  const auto n = count_of(s->first());
  if (!n) return std::nullopt;
  return stated_count{*n, s->first()->from.where};
}

std::optional<stated_factor> factor_setting(const model::capacity& cap, std::string_view keyword) {
  const auto* s = cap.find(keyword);
  if (s == nullptr) return std::nullopt;
  const auto* v = s->first();
  if (v == nullptr || !v->ok() || (v->kind != model::value_kind::real && v->kind != model::value_kind::integer))
    return std::nullopt;
  const double x = v->as_real();
  if (!(x >= 0)) return std::nullopt;  // negative, or NaN
  return stated_factor{x, v->from.where};
}

std::optional<tspec_direction> direction_of(const model::value& v) {
  if (!v.ok() || v.kind != model::value_kind::keyword) return std::nullopt;
  if (same_word(v.text, "Tx")) return tspec_direction::tx;
  if (same_word(v.text, "Rx")) return tspec_direction::rx;
  if (same_word(v.text, "TxRx")) return tspec_direction::txrx;
  return std::nullopt;
}

bool applies(tspec_direction t, io_direction d) {
  if (t == tspec_direction::txrx) return true;
  return (t == tspec_direction::tx) == (d == io_direction::tx);
}

// `a` decides before `b` for a connection of `size` bytes: it covers the
// size and is smaller; or both cover it at one size and a is slower; or
// neither covers it and a is larger, or as large and slower.
bool decides_before(const tspec_limit& a, const tspec_limit& b, std::uint64_t size) {
  const bool a_covers = a.size >= size, b_covers = b.size >= size;
  if (a_covers != b_covers) return a_covers;
  if (a.size != b.size) return a_covers ? a.size < b.size : a.size > b.size;
  return a.pps < b.pps;
}

}  // namespace

capacity_limits limits_of(const model::device& dev) {
  const auto& cap = dev.cap;
  capacity_limits out;
  out.max_cip_connections = count_setting(cap, "MaxCIPConnections");
  out.max_io_connections = count_setting(cap, "MaxIOConnections");
  out.max_msg_connections = count_setting(cap, "MaxMsgConnections");
  out.max_io_producers = count_setting(cap, "MaxIOProducers");
  out.max_io_consumers = count_setting(cap, "MaxIOConsumers");
  out.max_io_produce_consume = count_setting(cap, "MaxIOProduceConsume");
  out.max_io_mcast_producers = count_setting(cap, "MaxIOMcastProducers");
  out.max_io_mcast_consumers = count_setting(cap, "MaxIOMcastConsumers");
  out.max_consumers_per_mcast = count_setting(cap, "MaxConsumersPerMcast");
  out.conn_overhead = factor_setting(cap, "ConnOverhead");
  for (const auto& t : cap.tspecs) {
    const auto dir = direction_of(t.direction);
    const auto size = count_of(&t.size), pps = count_of(&t.rate);
    if (!dir || !size || !pps) continue;
    out.tspecs.push_back({t.number, *dir, *size, *pps, t.from.where, t.rate.from.where});
  }
  return out;
}

std::optional<pps_bound> pps_limit(const capacity_limits& limits, io_direction dir, std::uint64_t size) {
  const tspec_limit* best = nullptr;
  for (const auto& t : limits.tspecs)
    if (applies(t.direction, dir) && (best == nullptr || decides_before(t, *best, size))) best = &t;
  if (best == nullptr) return std::nullopt;
  pps_bound b;
  b.pps = best->pps;
  b.tspec = best->number;
  b.at = best->at;
  b.rate_at = best->rate_at;
  b.extrapolated = best->size < size;
  b.both_directions = best->direction == tspec_direction::txrx;
  return b;
}

}  // namespace edsc::connections
