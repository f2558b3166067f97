#include "network/verify_network.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "base/plural.hpp"

namespace edsc::network {

namespace {

using verify::conn_type;

// The planned size for a frame's connection; cos and cyclic share instance 4.
const planned_connection* planned_for(const planned_node& n, conn_type t) {
  for (const auto& c : n.connections)
    if (static_cast<int>(c.type) == static_cast<int>(t)) return &c;
  if (t == conn_type::cos || t == conn_type::cyclic)
    for (const auto& c : n.connections)
      if (c.type == network::conn_type::cos || c.type == network::conn_type::cyclic) return &c;
  return nullptr;
}

class verifier {
 public:
  verifier(const plan& p, const verify::can_log& log, const verify::conversation& conv)
      : p_(p), log_(log), conv_(conv) {}

  network_verdict run() {
    v_.startup = !conv_.exchanges.empty();
    for (const auto& p : log_.problems)
      v_.capture_diags.push_back(make_diagnostic(diag_id::verify_log_line, p.where,
                                                 fmt::format("capture line {} skipped: {}", p.line, p.message)));
    const std::set<unsigned> heard(conv_.nodes.begin(), conv_.nodes.end());
    std::set<unsigned> planned;
    for (const auto& n : p_.nodes) {
      planned.insert(n.mac);
      judge(n, heard.contains(n.mac));
    }
    for (const auto mac : heard) {
      if (planned.contains(mac) || mac == p_.scanner_mac) continue;
      node_verdict nv{mac, {}, node_state::unknown, 0, 0, "heard on the bus, not in the network file"};
      for (const auto& d : conv_.frames)
        if (d.dir == 'S' && d.group != 0 && d.mac == mac) {
          v_.capture_diags.push_back(make_diagnostic(
              diag_id::verify_net_unknown, log_.frames[d.frame].where,
              fmt::format("MAC {} speaks on the bus but the network does not list it; a configuration tool shows it "
                          "as Unknown and the scanner maps none of its data",
                          mac)));
          break;
        }
      v_.nodes.push_back(std::move(nv));
    }
    std::stable_sort(v_.nodes.begin(), v_.nodes.end(),
                     [](const node_verdict& a, const node_verdict& b) { return a.mac < b.mac; });
    std::stable_sort(v_.capture_diags.begin(), v_.capture_diags.end(),
                     [](const diagnostic& a, const diagnostic& b) { return a.where.begin < b.where.begin; });
    v_.proves = v_.startup
                    ? "The capture holds explicit messages (a start-up): a node never heard is Missing, identities "
                      "read are judged by each node's keying."
                    : "The capture holds no explicit messages (no start-up): it proves the I/O lengths of the nodes "
                      "it shows, not their identities (Match needs the Identity reads), and a node without traffic "
                      "is only not seen, not Missing.";
    return std::move(v_);
  }

 private:
  void judge(const planned_node& n, bool heard) {
    node_verdict nv{n.mac, n.name, node_state::not_seen, 0, 0, {}};
    if (!heard) {
      nv.state = v_.startup ? node_state::missing : node_state::not_seen;
      nv.detail = "no frame from this MAC";
      auto d = make_diagnostic(
          diag_id::verify_net_missing, n.where,
          fmt::format("node '{}' (MAC {}) never speaks in the capture{}", n.name, n.mac,
                      v_.startup ? "; the scanner will show it as Missing"
                                 : "; the capture holds no start-up, so this proves nothing about the node"));
      if (!v_.startup) d.level = severity::note;
      v_.network_diags.push_back(std::move(d));
      v_.nodes.push_back(std::move(nv));
      return;
    }
    const bool identity_read = identity(n, nv);
    io(n, nv);
    if (nv.state != node_state::mismatch) nv.state = identity_read ? node_state::match : node_state::seen;
    if (nv.detail.empty())
      nv.detail = identity_read ? fmt::format("identity matches ({} keying)", name_of(n.key)) : "identity not read";
    v_.nodes.push_back(std::move(nv));
  }

  // Identity attributes 1-4 as answered, against the plan, per keying.
  bool identity(const planned_node& n, node_verdict& nv) {
    bool read = false;
    for (const auto& x : conv_.exchanges) {
      if (x.mac != n.mac || !x.answer || x.error || x.cls != 0x01 || x.inst != 1 || x.service != 0x0E) continue;
      if (x.attr < 1 || x.attr > 4 || x.data.size() < 2) continue;
      read = true;
      if (!n.identity || n.key == keying::none) continue;
      const auto& id = *n.identity;
      const unsigned got = x.data[0] | (x.data[1] << 8);
      std::string what;
      switch (x.attr) {
        case 1:
          if (got != id.vendor) what = fmt::format("vendor ID {} where the network expects {}", got, id.vendor);
          break;
        case 2:
          if (got != id.device_type)
            what = fmt::format("device type {} where the network expects {}", got, id.device_type);
          break;
        case 3:
          if (got != id.product_code)
            what = fmt::format("product code {} where the network expects {}", got, id.product_code);
          break;
        case 4:
          if (x.data[0] != id.major || (n.key == keying::exact && x.data[1] != id.minor))
            what =
                fmt::format("revision {}.{} where the network expects {}.{}", x.data[0], x.data[1], id.major, id.minor);
          break;
        default: break;
      }
      if (what.empty()) continue;
      nv.state = node_state::mismatch;
      nv.detail = what;
      v_.capture_diags.push_back(
          make_diagnostic(diag_id::verify_net_identity, log_.frames[*x.answer].where,
                          fmt::format("node '{}' (MAC {}) answers {}; with {} keying the scanner shows it as Mismatch",
                                      n.name, n.mac, what, name_of(n.key))));
    }
    return read;
  }

  void io(const planned_node& n, node_verdict& nv) {
    std::map<std::pair<int, bool>, std::size_t> reported;  // first diagnostic per connection and direction
    for (const auto& e : conv_.io) {
      if (e.mac != n.mac) continue;
      ++nv.io_frames;
      const auto* c = planned_for(n, e.type);
      if (c == nullptr) continue;
      const auto expected = e.produced ? c->input : c->output;
      // Longer data travels fragmented; fragments are not reassembled.
      if (expected > 8 || e.length == expected) continue;
      ++nv.io_wrong;
      const auto key = std::make_pair(static_cast<int>(e.type), e.produced);
      if (reported.contains(key)) continue;
      reported[key] = v_.capture_diags.size();
      v_.capture_diags.push_back(make_diagnostic(
          diag_id::verify_net_io_length, log_.frames[e.frame].where,
          fmt::format("{} I/O frame {} node '{}' (MAC {}) carries {} where the network plans {} ({} {})",
                      label_of(c->type), e.produced ? "from" : "to", n.name, n.mac, plural(e.length, "byte"), expected,
                      label_of(c->type), e.produced ? "input" : "output")));
    }
  }

  const plan& p_;
  const verify::can_log& log_;
  const verify::conversation& conv_;
  network_verdict v_;
};

}  // namespace

const char* name_of(node_state s) {
  switch (s) {
    case node_state::match: return "Match";
    case node_state::mismatch: return "Mismatch";
    case node_state::missing: return "Missing";
    case node_state::not_seen: return "not seen";
    case node_state::seen: return "seen";
    case node_state::unknown: return "Unknown";
  }
  return "?";
}

network_verdict verify_network(const plan& p, const verify::can_log& log, const verify::conversation& conv) {
  return verifier(p, log, conv).run();
}

std::string render_verdict_table(const network_verdict& v) {
  std::size_t w = 4;
  for (const auto& n : v.nodes) w = std::max(w, n.name.size());
  std::string out = fmt::format("  {:>3}  {:<{}}  {:<9}  {:<22}  {}\n", "MAC", "node", w, "state", "I/O frames", "why");
  for (const auto& n : v.nodes) {
    const auto io = n.io_frames == 0  ? std::string("none")
                    : n.io_wrong == 0 ? fmt::format("{}, lengths agree", n.io_frames)
                                      : fmt::format("{}, {} of wrong length", n.io_frames, n.io_wrong);
    out += fmt::format("  {:>3}  {:<{}}  {:<9}  {:<22}  {}\n", n.mac, n.name.empty() ? "?" : n.name, w,
                       name_of(n.state), io, n.detail);
  }
  return out + v.proves + "\n";
}

}  // namespace edsc::network
