#pragma once
// `edsc verify --network`: every node of a planned network judged from one
// CAN capture (docs/network.md, "Verifying a live network").
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "network/plan.hpp"
#include "verify/decode.hpp"

namespace edsc::network {

enum class node_state : std::uint8_t { match, mismatch, missing, not_seen, seen, unknown };
[[nodiscard]] const char* name_of(node_state s);

struct node_verdict {
  std::uint32_t mac = 0;
  std::string name;  // empty for Unknown nodes
  node_state state = node_state::not_seen;
  std::size_t io_frames = 0, io_wrong = 0;
  std::string detail;  // what the verdict rests on
};

struct network_verdict {
  diagnostics capture_diags;        // located in the capture
  diagnostics network_diags;        // located in the network file (nodes never heard)
  std::vector<node_verdict> nodes;  // the plan's nodes, then Unknown ones, by MAC
  bool startup = false;             // the capture holds explicit messages (a start-up)
  std::string proves;               // what the capture can and cannot prove
};

[[nodiscard]] network_verdict verify_network(const plan& p, const verify::can_log& log,
                                             const verify::conversation& conv);

// The per-node summary table of the text report.
[[nodiscard]] std::string render_verdict_table(const network_verdict& v);

}  // namespace edsc::network
