// The checks of a Forward_Open that depend on what the simulator holds now:
// how many connections are open, who owns an output, who produces an input.
// What the EDS alone decides is connections::check_fit.
#include <fmt/format.h>

#include "sim/refusal.hpp"

namespace edsc::sim {

namespace {

bool owner_producing(const state& s, std::uint32_t input_instance) {
  for (const auto& c : s.connections)
    if (c.point && s.dev.points[*c.point].kind != model::app_type::listen_only &&
        s.dev.points[*c.point].plan.facts.input_instance == input_instance)
      return true;
  return false;
}

}  // namespace

std::optional<refusal> check_point(const state& s, const connection_point& p, const cip::forward_open_request& fo,
                                   std::optional<cip::byte_view> config) {
  if (auto r = connections::check_fit(s.dev.eds, p, fo, config)) return r;
  const auto& f = p.plan.facts;
  if (s.connections.size() >= s.max_connections)
    return refusal{ext::out_of_connections,
                   {},
                   fmt::format("{} connections are open, the most the simulator holds", s.connections.size())};
  if (p.kind == model::app_type::exclusive_owner)
    for (const auto& o : s.connections)
      if (o.point && s.dev.points[*o.point].kind == model::app_type::exclusive_owner &&
          s.dev.points[*o.point].plan.facts.output_instance == f.output_instance)
        return refusal{ext::ownership_conflict,
                       {},
                       fmt::format("output assembly {} is owned by the connection of serial {}, originator vendor {} "
                                   "and serial {}",
                                   f.output_instance, o.serial, o.vendor, o.originator_serial)};
  if (p.kind == model::app_type::listen_only && !owner_producing(s, f.input_instance))
    return refusal{ext::non_listen_only_not_opened,
                   {},
                   fmt::format("Connection{} listens to input assembly {}, which no open connection produces", p.number,
                               f.input_instance)};
  return std::nullopt;
}

}  // namespace edsc::sim
