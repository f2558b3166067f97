#include "network/read_enip.hpp"

#include <cmath>

namespace edsc::network {

namespace {

class enip_reader : public toml_reader {
 public:
  using toml_reader::toml_reader;

  enip_read run(const toml::table& root, span net_where, const located<std::string>& kind) {
    enip_file f;
    f.where = net_where;
    f.kind = kind;
    expect_keys(root, {"network", "scanner", "adapter"});
    if (const auto* header = root.get_as<toml::table>("network")) {
      expect_keys(*header, {"kind", "name"}, "[network]");
      read_string(*header, "name", f.name, false);
    }
    read_scanner(root, f);
    read_adapters(root, f);
    return {std::move(f), std::move(diags_)};
  }

 private:
  // "a.b.c.d", each part 0-255 written without leading zeros.
  static bool ipv4(std::string_view s) {
    int parts = 0;
    std::size_t i = 0;
    while (i <= s.size()) {
      const auto dot = s.find('.', i);
      const auto part = s.substr(i, dot == std::string_view::npos ? std::string_view::npos : dot - i);
      if (part.empty() || part.size() > 3 || (part.size() > 1 && part[0] == '0')) return false;
      int v = 0;
      for (const char c : part) {
        if (c < '0' || c > '9') return false;
        v = v * 10 + (c - '0');
      }
      if (v > 255) return false;
      ++parts;
      if (dot == std::string_view::npos) break;
      i = dot + 1;
    }
    return parts == 4;
  }

  void read_address(const toml::table& t, located<std::string>& out, std::string_view in) {
    read_string(t, "address", out, true, in);
    if (out.given && !ipv4(out.value)) {
      add(diag_id::net_address_invalid, out.where,
          fmt::format("address \"{}\" is not an IPv4 address (four numbers 0-255: \"192.168.1.20\")", out.value));
      out.given = false;
    }
  }

  // A time in milliseconds ("rpi_ms = 10", "2.5"), kept in microseconds.
  void read_ms(const toml::table& t, std::string_view key, located<std::uint32_t>& out) {
    span k;
    const auto* n = find(t, key, k);
    if (n == nullptr) return;
    double v = -1;
    if (const auto* i = n->as_integer()) v = static_cast<double>(i->get());
    if (const auto* d = n->as_floating_point()) v = d->get();
    const double us = std::round(v * 1000.0);
    if (!(us >= 1 && us <= 4294967295.0))
      return add(diag_id::net_key_type, region(n->source()),
                 fmt::format("'{}' must be a time in milliseconds, more than 0 and at most 4294967", key));
    out = {static_cast<std::uint32_t>(us), region(n->source()), true};
  }

  void read_scanner(const toml::table& root, enip_file& f) {
    const auto* t = root.get_as<toml::table>("scanner");
    if (t == nullptr) {
      if (const auto* n = root.get("scanner"); n != nullptr)
        add(diag_id::net_key_type, region(n->source()), "scanner must be a table: [scanner]");
      else
        add(diag_id::net_key_missing, f.where, "the file has no [scanner] table (address, eds)");
      return;
    }
    auto& s = f.scan;
    s.where = region(t->source());
    expect_keys(*t, {"name", "address", "eds", "max_connections", "max_pps"}, "[scanner]");
    read_string(*t, "name", s.name, false, "[scanner]");
    read_address(*t, s.address, "[scanner]");
    read_string(*t, "eds", s.eds, false, "[scanner]");
    read_uint(*t, "max_connections", s.max_connections, 0xFFFF);
    read_uint(*t, "max_pps", s.max_pps, 100000000);
  }

  void read_connection(const toml::node& n, enip_adapter& a) {
    enip_connection c;
    c.where = region(n.source());
    if (const auto* i = n.as_integer()) {
      if (i->get() < 1 || i->get() > 0xFFFF)
        return add(diag_id::net_key_type, c.where, "a connection number is 1 or more (ConnectionN of the EDS)");
      c.number = {static_cast<std::uint32_t>(i->get()), c.where, true};
      a.connections.push_back(std::move(c));
      return;
    }
    if (const auto* s = n.as_string()) {
      c.name = {s->get(), c.where, true};
      a.connections.push_back(std::move(c));
      return;
    }
    const auto* t = n.as_table();
    if (t == nullptr)
      return add(diag_id::net_key_type, c.where,
                 "a connection is the number of a ConnectionN (1), its name (\"Exclusive Owner\"), or a table "
                 "({ connection = 1, rpi_ms = 10 })");
    expect_keys(*t, {"connection", "rpi_ms", "ot_rpi_ms", "to_rpi_ms", "multicast", "set"}, "a connection");
    span k;
    const auto* which = find(*t, "connection", k);
    if (which == nullptr) return missing(*t, "connection", "a connection table");
    if (which->as_integer() == nullptr && which->as_string() == nullptr)
      return add(diag_id::net_key_type, region(which->source()),
                 "'connection' is the number of a ConnectionN or its name");
    const auto before = a.connections.size();
    read_connection(*which, a);
    if (a.connections.size() == before) return;
    auto& r = a.connections.back();
    r.where = c.where;
    read_ms(*t, "rpi_ms", r.rpi_us);
    read_ms(*t, "ot_rpi_ms", r.ot_rpi_us);
    read_ms(*t, "to_rpi_ms", r.to_rpi_us);
    if (const auto* m = find(*t, "multicast", k)) {
      if (const auto* b = m->as_boolean())
        r.multicast = {b->get(), region(m->source()), true};
      else
        add(diag_id::net_key_type, region(m->source()), "'multicast' must be true or false");
    }
    if (const auto* sets = find(*t, "set", k)) read_sets(*sets, r);
  }

  // set = ["Param3=5", "Speed=Fast"], each as the connection command's --set.
  void read_sets(const toml::node& n, enip_connection& c) {
    const auto* a = n.as_array();
    if (a == nullptr)
      return add(diag_id::net_key_type, region(n.source()),
                 "'set' is a list of \"NAME=VALUE\" strings, as --set takes them: set = [\"Param3=5\"]");
    for (const auto& e : *a) {
      const auto* s = e.as_string();
      if (s == nullptr || s->get().find('=') == std::string::npos) {
        add(diag_id::net_key_type, region(e.source()), "each 'set' entry is \"NAME=VALUE\"");
        continue;
      }
      c.sets.push_back({s->get(), region(e.source()), true});
    }
  }

  void read_adapter(const toml::table& t, std::size_t index, enip_file& f) {
    enip_adapter a;
    a.where = region(t.source());
    expect_keys(t, {"name", "address", "eds", "connections"}, "[[adapter]]");
    read_string(t, "name", a.name, true, "[[adapter]]");
    if (!a.name.given) a.name.value = fmt::format("[[adapter]] {}", index + 1);
    read_address(t, a.address, "[[adapter]]");
    read_string(t, "eds", a.eds, true, "[[adapter]]");
    span k;
    if (const auto* c = find(t, "connections", k)) {
      a.connections_where = region(c->source());
      if (const auto* arr = c->as_array()) {
        for (const auto& e : *arr) read_connection(e, a);
      } else {
        read_connection(*c, a);  // one connection written without brackets
      }
    } else {
      missing(t, "connections", "[[adapter]]");
    }
    f.adapters.push_back(std::move(a));
  }

  void read_adapters(const toml::table& root, enip_file& f) {
    const auto* n = root.get("adapter");
    if (n == nullptr) return;
    const auto* a = n->as_array();
    if (a == nullptr)
      return add(diag_id::net_key_type, region(n->source()), "adapters are an array of tables: [[adapter]]");
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (const auto* t = (*a)[i].as_table())
        read_adapter(*t, i, f);
      else
        add(diag_id::net_key_type, region((*a)[i].source()), "each adapter is a table: [[adapter]]");
    }
  }
};

}  // namespace

enip_read read_enip(const source_file& src, const toml::table& root, span net_where, const located<std::string>& kind) {
  return enip_reader(src).run(root, net_where, kind);
}

}  // namespace edsc::network
