#include "network/plan.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "facts/header_view.hpp"
#include "io/read_file.hpp"
#include "network/enip_check.hpp"
#include "network/layout.hpp"
#include "network/read_network.hpp"

namespace edsc::network {

namespace {

// What one EDS file offers a scanner, read once however many nodes use it.
struct eds_offer {
  std::unique_ptr<analysis> a;
  std::optional<std::string> io_error;
  std::size_t report = SIZE_MAX;  // index into eds_reports, when it has findings
  bool devicenet = false;
  emit::devicenet_facts dn;
  identity_values id;
  bool id_ok = false;
  std::string product;
  std::array<std::set<std::uint32_t>, conn_type_count> inputs, outputs;  // allowed sizes
};

void collect_sizes(const model::io_info& io, eds_offer& o) {
  for (const auto* list : {&io.inputs, &io.outputs})
    for (const auto& d : *list) {
      if (!d.mask.is_integer() || !d.size.is_integer()) continue;
      for (std::size_t t = 0; t < conn_type_count; ++t)
        if ((d.mask.as_uint() & (1u << t)) != 0)
          (d.output ? o.outputs : o.inputs)[t].insert(
              static_cast<std::uint32_t>(std::min<std::uint64_t>(d.size.as_uint(), 0xFFFFFFFFu)));
    }
}

std::string size_list(const std::set<std::uint32_t>& s) {
  std::string out;
  std::size_t i = 0;
  for (const auto v : s) {
    out += i == 0 ? "" : (i + 1 == s.size() ? " or " : ", ");
    out += std::to_string(v);
    ++i;
  }
  return out;
}

class checker {
 public:
  checker(checked_network& out, const check_options& options, const eds_reader& read)
      : out_(out), options_(options), read_(read) {}

  void run() {
    auto read = read_network(*out_.source);
    out_.diags = std::move(read.diags);
    if (read.enip) {
      out_.enip = std::move(read.enip);
      return check_enip(*out_.enip, out_, options_, read_);
    }
    if (!read.net) return;
    out_.file = std::move(read.net);
    const auto& net = *out_.file;
    plan p;
    p.name = net.name.given ? net.name.value : std::filesystem::path(out_.source->path()).stem().string();
    bool plannable = true;
    if (net.scan.profile.given) {
      p.profile = find_profile(net.scan.profile.value);
      if (p.profile == nullptr) {
        add(diag_id::net_profile_unknown, net.scan.profile.where,
            fmt::format("scanner profile \"{}\" is not known; edsc knows {}", net.scan.profile.value,
                        known_profiles()));
      }
    }
    plannable = p.profile != nullptr && net.scan.mac.given;
    p.scanner_mac = net.scan.mac.value;
    p.slot = net.scan.slot.given ? net.scan.slot.value : (p.profile ? p.profile->default_slot : 0);
    p.align = net.scan.align.value;
    p.input_start = net.scan.input_start.value;
    p.output_start = net.scan.output_start.value;
    lengths(net);
    for (std::size_t i = 0; i < net.nodes.size(); ++i) {
      auto planned = plan_node(net.nodes[i], i);
      if (planned)
        p.nodes.push_back(std::move(*planned));
      else
        plannable = false;
    }
    macs(net);
    std::stable_sort(p.nodes.begin(), p.nodes.end(),
                     [](const planned_node& a, const planned_node& b) { return a.mac < b.mac; });
    identities(p);
    // The nodes left out only ever make room: the overlaps and overflows
    // found among the others are there whatever the rest of the file says.
    if (p.profile != nullptr) placements(p);
    if (plannable) out_.result = std::move(p);
  }

 private:
  void add(diag_id id, span where, std::string message) {
    out_.diags.push_back(make_diagnostic(id, where, std::move(message)));
  }

  void lengths(const network_file& net) {
    if (!net.baud.given) return;
    const auto l = limits_for(net.baud.value, net.cable_type.value);
    if (!l) return;
    const auto cable = net.cable_type.given ? fmt::format("{} cable", name_of(net.cable_type.value)) : "any cable";
    if (net.trunk_length.given && net.trunk_length.value > l->trunk)
      add(diag_id::net_length_over_limit, net.trunk_length.where,
          fmt::format("trunk length {} m is over the {} m a {} kbit/s network allows with {}", net.trunk_length.value,
                      l->trunk, net.baud.value, cable));
    if (net.drop_length.given && net.drop_length.value > l->all_drops)
      add(diag_id::net_length_over_limit, net.drop_length.where,
          fmt::format("drops adding up to {} m are over the {} m a {} kbit/s network allows", net.drop_length.value,
                      l->all_drops, net.baud.value));
    if (net.longest_drop.given && net.longest_drop.value > l->one_drop)
      add(diag_id::net_length_over_limit, net.longest_drop.where,
          fmt::format("a drop of {} m is over the {} m any one drop may be", net.longest_drop.value, l->one_drop));
  }

  eds_offer& load(const std::string& path) {
    if (auto it = offers_.find(path); it != offers_.end()) return it->second;
    auto& o = offers_[path];
    auto r = read_ ? read_(path) : io::read_source(path);
    if (!r) {
      o.io_error = r.error().message;
      return o;
    }
    o.a = analyze(std::move(r.value()), options_);
    if (!o.a->diags.empty()) {
      o.report = out_.eds_reports.size();
      out_.eds_reports.push_back(
          {std::make_unique<source_file>(o.a->source->path(), std::string(o.a->text())), o.a->diags});
    }
    std::vector<emit::header_issue> issues;
    const auto facts = emit::collect_facts(o.a->dev, *o.a->source, issues);
    o.id_ok = std::none_of(issues.begin(), issues.end(), [](const auto& i) { return i.error; });
    o.id = {facts.identity.vendor_id, facts.identity.device_type, facts.identity.product_code,
            facts.identity.major_revision, facts.identity.minor_revision};
    o.product = facts.identity.product_name;
    o.devicenet = facts.devicenet.has_value();
    if (facts.devicenet) o.dn = *facts.devicenet;
    collect_sizes(o.a->dev.io, o);
    collect_sizes(o.a->dev.variant_io, o);
    return o;
  }

  // A node without a usable MAC ID or name is still checked (its EDS, its
  // connections) but not planned.
  std::optional<planned_node> plan_node(const network::node& n, std::size_t index) {
    planned_node pn;
    pn.mac = n.mac.value;
    pn.name = n.name.given ? n.name.value : fmt::format("[[node]] {}", index + 1);
    pn.key = n.key.value;
    pn.where = n.where;
    if (n.input_dword.given) pn.input_dword = n.input_dword.value, pn.input_dword_where = n.input_dword.where;
    if (n.output_dword.given) pn.output_dword = n.output_dword.value, pn.output_dword_where = n.output_dword.where;
    const eds_offer* offer = nullptr;
    if (n.eds.given) {
      pn.eds = n.eds.value;
      pn.has_eds = true;
      const auto dir = std::filesystem::path(out_.source->path()).parent_path();
      const auto path = (dir / n.eds.value).lexically_normal().string();
      const auto& o = load(path);
      if (o.io_error) {
        add(diag_id::net_eds_unreadable, n.eds.where, fmt::format("node '{}': {}", pn.name, *o.io_error));
        return std::nullopt;
      }
      if (o.a->errors() > 0) {
        add(diag_id::net_eds_errors, n.eds.where,
            fmt::format("node '{}': {} has {}; a scanner tool will not register it", pn.name, path,
                        plural(o.a->errors(), "error")));
      }
      if (!o.devicenet) {
        add(diag_id::net_connection_not_offered, n.eds.where,
            fmt::format("node '{}': {} describes no DeviceNet I/O ([IO_Info])", pn.name, path));
        return std::nullopt;
      }
      offer = &o;
      pn.product = o.product;
      if (o.id_ok) pn.identity = o.id;
    } else {
      add(diag_id::net_node_without_eds, n.name.where,
          fmt::format("node '{}' has no EDS: its identity and sizes are taken as written", pn.name));
      const auto& id = n.identity;
      pn.product = id.product.value;
      if (id.vendor.given && id.device_type.given && id.product_code.given)
        pn.identity = identity_values{id.vendor.value, id.device_type.value, id.product_code.value, id.major.value,
                                      id.minor.value};
    }
    if (!connections(n, offer, pn) || !n.mac.given || !n.name.given) return std::nullopt;
    return pn;
  }

  bool connections(const network::node& n, const eds_offer* offer, planned_node& pn) {
    std::vector<connection_plan> list = n.connections;
    if (list.empty() && n.connections_where.empty()) {
      const std::uint32_t mask = offer != nullptr ? offer->dn.default_connections : 0;
      for (std::size_t t = 0; t < conn_type_count; ++t)
        if ((mask & (1u << t)) != 0) list.push_back({static_cast<conn_type>(t), n.where, {}, {}});
      if (list.empty()) {
        add(diag_id::net_key_missing, n.where,
            fmt::format("node '{}' needs 'connections': {}", pn.name,
                        offer != nullptr ? "its EDS names no Default connection" : "it has no EDS to take them from"));
        return false;
      }
    }
    std::array<const connection_plan*, conn_type_count> seen{};
    bool ok = true;
    for (const auto& c : list) {
      const auto t = static_cast<std::size_t>(c.type);
      if (seen[t] != nullptr) {
        add(diag_id::net_connection_conflict, c.where,
            fmt::format("node '{}' lists the {} connection twice", pn.name, name_of(c.type)));
        continue;
      }
      seen[t] = &c;
      const auto other = c.type == conn_type::cos ? conn_type::cyclic : conn_type::cos;
      if ((c.type == conn_type::cos || c.type == conn_type::cyclic) && seen[static_cast<std::size_t>(other)]) {
        add(diag_id::net_connection_conflict, c.where,
            fmt::format("node '{}' lists both COS and cyclic; they share connection instance 4, so use one", pn.name));
        continue;
      }
      planned_connection pc{c.type, 0, 0};
      const auto& in = c.input.given ? c.input : n.input;
      const auto& out = c.output.given ? c.output : n.output;
      if (offer == nullptr) {
        if (!in.given && !out.given) {
          add(diag_id::net_key_missing, c.where,
              fmt::format("node '{}' has no EDS, so its {} connection needs 'input' and 'output' sizes", pn.name,
                          name_of(c.type)));
          ok = false;
          continue;
        }
        pc.input = in.value;
        pc.output = out.value;
      } else {
        const auto& f = offer->dn.types[t];
        if (!f.supported) {
          add(diag_id::net_connection_not_offered, c.where,
              fmt::format("node '{}': its EDS offers no {} connection (no InputN/OutputN mask or {}Info allows it)",
                          pn.name, name_of(c.type), label_of(c.type)));
          ok = false;
          continue;
        }
        pc.input = size(pn, c.type, true, in, f.produced_size, offer->inputs[t]);
        pc.output = size(pn, c.type, false, out, f.consumed_size, offer->outputs[t]);
      }
      pn.connections.push_back(pc);
    }
    return ok;
  }

  std::uint32_t size(const planned_node& pn, conn_type t, bool input, const located<std::uint32_t>& asked,
                     std::uint32_t fallback, std::set<std::uint32_t> allowed) {
    allowed.insert(fallback);  // the xxxInfo default is always a choice
    if (!asked.given) return fallback;
    if (allowed.count(asked.value) == 0) {
      add(diag_id::net_size_not_allowed, asked.where,
          fmt::format("node '{}': {} {} of {}; its EDS allows {} for {} ([IO_Info] / [Variant_IO_Info])", pn.name,
                      name_of(t), input ? "input" : "output", plural(asked.value, "byte"), size_list(allowed),
                      label_of(t)));
      return fallback;
    }
    return asked.value;
  }

  void macs(const network_file& net) {
    std::map<std::uint32_t, std::pair<span, std::string>> used;
    if (net.scan.mac.given) used[net.scan.mac.value] = {net.scan.mac.where, "the scanner"};
    for (const auto& n : net.nodes) {
      if (!n.mac.given) continue;
      const auto who = fmt::format("node '{}'", n.name.value);
      auto [it, fresh] = used.try_emplace(n.mac.value, n.mac.where, who);
      if (fresh) continue;
      auto d = make_diagnostic(diag_id::net_mac_duplicate, n.mac.where,
                               fmt::format("MAC ID {} of {} is already used by {}; the second device fails the "
                                           "duplicate MAC ID check and stays off line",
                                           n.mac.value, who, it->second.second));
      d.notes.push_back({it->second.first, fmt::format("{} has MAC ID {} here", it->second.second, n.mac.value)});
      out_.diags.push_back(std::move(d));
    }
  }

  void identities(const plan& p) {
    for (std::size_t i = 0; i < p.nodes.size(); ++i) {
      const auto& a = p.nodes[i];
      if (!a.identity || !a.has_eds) continue;
      for (std::size_t j = 0; j < i; ++j) {
        const auto& b = p.nodes[j];
        if (!b.identity || !b.has_eds) continue;
        const auto& x = *a.identity;
        const auto& y = *b.identity;
        if (x.vendor != y.vendor || x.device_type != y.device_type || x.product_code != y.product_code ||
            x.major != y.major)
          continue;
        auto d = make_diagnostic(
            diag_id::net_identity_duplicate, a.where,
            fmt::format("nodes '{}' (MAC {}) and '{}' (MAC {}) have the same identity (vendor {}, device type {}, "
                        "product code {}, revision {}); keying cannot tell them apart",
                        a.name, a.mac, b.name, b.mac, x.vendor, x.device_type, x.product_code, x.major));
        d.notes.push_back({b.where, fmt::format("node '{}' is declared here", b.name)});
        out_.diags.push_back(std::move(d));
        break;
      }
    }
  }

  void placements(const plan& p) {
    const auto l = automap(p);
    for (const auto& pr : l.problems) {
      const auto& n = p.nodes[pr.node];
      const auto& fixed_where = pr.input ? n.input_dword_where : n.output_dword_where;
      const span where = fixed_where.empty() ? n.where : fixed_where;
      const char* dir = pr.input ? "input" : "output";
      const auto& image = pr.input ? p.profile->input : p.profile->output;
      if (pr.overlap) {
        const auto& o = p.nodes[pr.other];
        auto d = make_diagnostic(diag_id::net_placement_overlap, where,
                                 fmt::format("node '{}' {} bytes {}-{} overlap node '{}' in the {} image", n.name, dir,
                                             pr.offset, pr.offset + pr.size - 1, o.name, dir));
        const auto& ow = pr.input ? o.input_dword_where : o.output_dword_where;
        d.notes.push_back({ow.empty() ? o.where : ow, fmt::format("node '{}' is placed here", o.name)});
        out_.diags.push_back(std::move(d));
      } else {
        add(diag_id::net_image_overflow, where,
            fmt::format("node '{}' needs {} {} {} at byte {}, past the {} (DWords 0-{}) of the {} {} slave "
                        "data area",
                        n.name, pr.size, dir, noun(pr.size, "byte", "bytes"), pr.offset,
                        plural(image.slave_bytes(), "byte"), image.slave_bytes() / 4 - 1, p.profile->name, dir));
      }
    }
  }

  checked_network& out_;
  const check_options& options_;
  const eds_reader& read_;
  std::map<std::string, eds_offer> offers_;
};

}  // namespace

checked_network check_network(std::unique_ptr<source_file> source, const check_options& options,
                              const eds_reader& read) {
  checked_network out;
  out.source = std::move(source);
  checker(out, options, read).run();
  std::stable_sort(out.diags.begin(), out.diags.end(),
                   [](const diagnostic& a, const diagnostic& b) { return a.where.begin < b.where.begin; });
  options.policy.apply(out.diags);
  out.totals.files = 1 + out.eds_reports.size();
  out.totals.add(out.diags);
  for (const auto& r : out.eds_reports) out.totals.add(r.diags);
  return out;
}

std::vector<file_report> take_reports(checked_network& c) {
  std::vector<file_report> reports;
  reports.push_back({std::move(c.source), std::move(c.diags)});
  for (auto& r : c.eds_reports) reports.push_back(std::move(r));
  c.eds_reports.clear();
  return reports;
}

}  // namespace edsc::network
