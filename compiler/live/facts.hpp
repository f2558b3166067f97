#pragma once
// `verify --live` in two halves: what the device answered, gathered over the
// wire into plain facts (gather_facts), and the comparison of those facts
// with the EDS (judge_facts), a pure function every verdict is tested
// through with facts made by hand and no device.
#include <cstdint>
#include <optional>
#include <vector>

#include "cip/encap.hpp"
#include "cip/message.hpp"
#include "live/error.hpp"
#include "live/io.hpp"
#include "live/verify_live.hpp"
#include "model/device.hpp"

namespace edsc::live {

// The reply to attribute 4 (size) of one assembly instance the EDS locates,
// and, when that reply says the instance is unknown, whether the device
// answers for the Assembly class itself (then the instance is surely absent).
struct assembly_fact {
  cip::reply size;
  std::optional<bool> class_answers;
};

// Each fact is there when its check was reached, in the order of the checks
// (identity, the assemblies of plan_assemblies, the connections of
// plan_connections); a check without its fact was not reached, or was under
// way when the run stopped.
struct live_facts {
  bool connected = false;  // false: nothing was asked (the failure says why)
  std::optional<cip::identity> identity;
  std::vector<assembly_fact> assemblies;
  // One per connection plan reached: the outcome of opening it, or nothing
  // for a plan edsc cannot open (its reason is the plan's).
  std::vector<std::optional<connection_outcome>> connections;
  // The device stopped answering (or a local failure); `during_check` when
  // it came while a check was under way (the next check without its fact),
  // false when after a connection's watch (its fact is there).
  std::optional<error> failure;
  bool during_check = true;
  int interrupted = 0;  // the signal that stopped the run, or 0
};

// Asks the device what the checks need, stopping at a failure or a signal.
[[nodiscard]] live_facts gather_facts(const net::endpoint& device, const model::device& dev, const live_options& opt);
// The report: a row per check, a diagnostic per disagreement, the failure.
[[nodiscard]] live_report judge_facts(const model::device& dev, const live_facts& facts, bool connections);

}  // namespace edsc::live
