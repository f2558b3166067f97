#include "network/read_network.hpp"

#include <array>
#include <initializer_list>
#include <string_view>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "network/read_enip.hpp"
#include "network/toml_reader.hpp"

namespace edsc::network {

namespace {

using namespace std::string_view_literals;

class reader : public toml_reader {
 public:
  explicit reader(const source_file& src) : toml_reader(src) {}

  read_result run() {
    toml::table root;
    try {
      root = toml::parse(src_.text(), src_.path());
    } catch (const toml::parse_error& e) {
      const auto at = offset(e.source().begin);
      const std::uint32_t end = at < src_.size() ? at + 1 : at;
      add(diag_id::net_syntax, {at, end}, fmt::format("not TOML: {}", e.description()));
      return finish();
    }
    network_file net;
    // Without [network] or its kind, the rest is still read as the one kind
    // edsc plans, so its errors show in the same run.
    const auto* header = root.get_as<toml::table>("network");
    if (header == nullptr) {
      if (const auto* n = root.get("network"); n != nullptr)
        add(diag_id::net_key_type, region(n->source()), "network must be a table: [network]");
      else
        add(diag_id::net_key_missing, {0, 0}, "the file has no [network] table (kind, name, baud)");
    } else {
      net.where = region(header->source());
      read_string(*header, "kind", net.kind, true);
      if (net.kind.given && net.kind.value == "ethernetip") {
        auto e = read_enip(src_, root, region(header->source()), net.kind);
        for (auto& d : e.diags) diags_.push_back(std::move(d));
        out_.enip = std::move(e.file);
        return finish();
      }
      if (net.kind.given && net.kind.value != "devicenet") {
        add(diag_id::net_kind_unsupported, net.kind.where,
            fmt::format("network kind \"{}\" cannot be planned; edsc plans kind = \"devicenet\" and "
                        "kind = \"ethernetip\"",
                        net.kind.value));
        return finish();
      }
      read_network_table(*header, net);
    }
    expect_keys(root, {"network", "scanner", "node"});
    read_scanner(root, net);
    read_nodes(root, net);
    out_.net = std::move(net);
    return finish();
  }

 private:
  read_result finish() {
    out_.diags = std::move(diags_);
    return std::move(out_);
  }

  void read_mac(const toml::table& t, located<std::uint32_t>& out, std::string_view in) {
    span k;
    const auto* n = find(t, "mac", k);
    if (n == nullptr) return missing(t, "mac", in);
    const auto where = region(n->source());
    const auto* i = n->as_integer();
    if (i == nullptr) return add(diag_id::net_key_type, where, "'mac' must be an integer from 0 to 63");
    if (i->get() < 0 || i->get() > 63)
      return add(diag_id::net_mac_range, where,
                 fmt::format("MAC ID {} is outside 0-63; DeviceNet has 64 MAC IDs", i->get()));
    out = {static_cast<std::uint32_t>(i->get()), where, true};
  }

  void read_network_table(const toml::table& t, network_file& net) {
    expect_keys(t, {"kind", "name", "baud", "cable", "trunk_length", "drop_length", "longest_drop"}, "[network]");
    read_string(t, "name", net.name, false);
    if (read_uint(t, "baud", net.baud, 1000000, "[network]") && net.baud.value != 125 && net.baud.value != 250 &&
        net.baud.value != 500) {
      add(diag_id::net_key_type, net.baud.where,
          fmt::format("baud = {} is not a DeviceNet rate; use 125, 250 or 500 (kbit/s)", net.baud.value));
      net.baud.given = false;
    }
    static constexpr std::array<std::pair<std::string_view, cable>, 3> cables{
        {{"thick", cable::thick}, {"thin", cable::thin}, {"flat", cable::flat}}};
    read_word(t, "cable", cables, net.cable_type);
    read_length(t, "trunk_length", net.trunk_length);
    read_length(t, "drop_length", net.drop_length);
    read_length(t, "longest_drop", net.longest_drop);
  }

  void read_scanner(const toml::table& root, network_file& net) {
    const auto* t = root.get_as<toml::table>("scanner");
    if (t == nullptr) {
      if (const auto* n = root.get("scanner"); n != nullptr)
        add(diag_id::net_key_type, region(n->source()), "scanner must be a table: [scanner]");
      else
        add(diag_id::net_key_missing, net.where, "the file has no [scanner] table (profile, mac)");
      return;
    }
    auto& s = net.scan;
    s.where = region(t->source());
    expect_keys(*t, {"profile", "mac", "slot", "alignment", "input_start_dword", "output_start_dword"}, "[scanner]");
    read_string(*t, "profile", s.profile, true, "[scanner]");
    read_mac(*t, s.mac, "[scanner]");
    read_uint(*t, "slot", s.slot, 255);
    static constexpr std::array<std::pair<std::string_view, alignment>, 3> aligns{
        {{"byte", alignment::byte}, {"word", alignment::word}, {"dword", alignment::dword}}};
    read_word(*t, "alignment", aligns, s.align);
    read_uint(*t, "input_start_dword", s.input_start, 0xFFFF);
    read_uint(*t, "output_start_dword", s.output_start, 0xFFFF);
  }

  void read_connection(const toml::node& n, node& nd) {
    static constexpr std::array<std::pair<std::string_view, conn_type>, 4> types{{{"poll", conn_type::poll},
                                                                                  {"strobe", conn_type::strobe},
                                                                                  {"cos", conn_type::cos},
                                                                                  {"cyclic", conn_type::cyclic}}};
    connection_plan c;
    c.where = region(n.source());
    if (const auto* s = n.as_string()) {
      for (const auto& [w, e] : types)
        if (s->get() == w) {
          c.type = e;
          nd.connections.push_back(c);
          return;
        }
      return add(diag_id::net_key_type, c.where,
                 fmt::format("connection \"{}\" is not one of \"poll\", \"strobe\", \"cos\", \"cyclic\"", s->get()));
    }
    const auto* t = n.as_table();
    if (t == nullptr)
      return add(diag_id::net_key_type, c.where,
                 "a connection is a type name (\"cos\") or a table ({ type = \"poll\", input = 4, output = 2 })");
    expect_keys(*t, {"type", "input", "output"}, "a connection");
    located<conn_type> type;
    span k;
    if (find(*t, "type", k) == nullptr) return missing(*t, "type", "a connection table");
    read_word(*t, "type", types, type);
    if (!type.given) return;
    c.type = type.value;
    read_uint(*t, "input", c.input, 0xFFFF);
    read_uint(*t, "output", c.output, 0xFFFF);
    nd.connections.push_back(c);
  }

  void read_identity(const toml::node& n, node& nd) {
    const auto* t = n.as_table();
    if (t == nullptr)
      return add(
          diag_id::net_key_type, region(n.source()),
          "'identity' must be a table: { vendor = 1, device_type = 24, product_code = 5, major = 1, minor = 1 }");
    expect_keys(*t, {"vendor", "device_type", "product_code", "major", "minor", "product"}, "identity");
    auto& id = nd.identity;
    read_uint(*t, "vendor", id.vendor, 0xFFFF);
    read_uint(*t, "device_type", id.device_type, 0xFFFF);
    read_uint(*t, "product_code", id.product_code, 0xFFFF);
    read_uint(*t, "major", id.major, 0x7F);
    read_uint(*t, "minor", id.minor, 0xFF);
    read_string(*t, "product", id.product, false, "identity");
  }

  void read_node(const toml::table& t) {
    node nd;
    nd.where = region(t.source());
    expect_keys(
        t,
        {"mac", "name", "eds", "connections", "input", "output", "keying", "input_dword", "output_dword", "identity"},
        "[[node]]");
    read_mac(t, nd.mac, "[[node]]");
    read_string(t, "name", nd.name, true, "[[node]]");
    read_string(t, "eds", nd.eds, false);
    read_uint(t, "input", nd.input, 0xFFFF);
    read_uint(t, "output", nd.output, 0xFFFF);
    static constexpr std::array<std::pair<std::string_view, keying>, 3> keys{
        {{"exact", keying::exact}, {"compatible", keying::compatible}, {"none", keying::none}}};
    read_word(t, "keying", keys, nd.key);
    read_uint(t, "input_dword", nd.input_dword, 0xFFFF);
    read_uint(t, "output_dword", nd.output_dword, 0xFFFF);
    span k;
    if (const auto* c = find(t, "connections", k)) {
      nd.connections_where = region(c->source());
      if (const auto* a = c->as_array()) {
        for (const auto& e : *a) read_connection(e, nd);
      } else {
        read_connection(*c, nd);  // one connection written without brackets
      }
    }
    if (const auto* id = find(t, "identity", k)) {
      if (nd.eds.given)
        add(diag_id::net_key_unknown, k, "'identity' is ignored: the node's EDS states its identity");
      else
        read_identity(*id, nd);
    }
    nodes_->push_back(std::move(nd));
  }

  void read_nodes(const toml::table& root, network_file& net) {
    nodes_ = &net.nodes;
    const auto* n = root.get("node");
    if (n == nullptr) return;
    const auto* a = n->as_array();
    if (a == nullptr) return add(diag_id::net_key_type, region(n->source()), "nodes are an array of tables: [[node]]");
    for (const auto& e : *a) {
      if (const auto* t = e.as_table())
        read_node(*t);
      else
        add(diag_id::net_key_type, region(e.source()), "each node is a table: [[node]]");
    }
  }

  read_result out_;
  std::vector<node>* nodes_ = nullptr;
};

}  // namespace

read_result read_network(const source_file& src) {
  try {
    return reader(src).run();
  } catch (const std::exception& e) {
    // toml++ may throw for resource exhaustion; that is still bad input, not a crash.
    read_result r;
    r.diags.push_back(make_diagnostic(diag_id::net_syntax, {0, 0}, fmt::format("not readable as TOML: {}", e.what())));
    return r;
  }
}

}  // namespace edsc::network
