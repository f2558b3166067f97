#include "network/enip_check.hpp"

#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "connections/forward_open_fit.hpp"
#include "connections/overrides.hpp"
#include "connections/served_points.hpp"
#include "network/enip_capacity.hpp"

namespace edsc::network {

namespace {

using ext = cip::extended_status;

// One adapter's EDS, read and analysed once however many adapters use it.
struct adapter_eds {
  std::unique_ptr<analysis> a;
  std::optional<std::string> io_error;
  connections::served_points served;
};

class enip_checker {
 public:
  enip_checker(checked_network& out, const check_options& options, const eds_reader& read)
      : out_(out), options_(options), read_(read) {}

  void run(const enip_file& f) {
    addresses(f);
    for (const auto& a : f.adapters) adapter(a);
    check_scanner_capacity(f.scan, totals_, out_.diags);
  }

 private:
  void add(diag_id id, span where, std::string message) {
    out_.diags.push_back(make_diagnostic(id, where, std::move(message)));
  }

  void addresses(const enip_file& f) {
    std::map<std::string, std::pair<span, std::string>> seen;
    const auto use = [&](const located<std::string>& address, const std::string& who) {
      if (!address.given) return;
      const auto [it, fresh] = seen.try_emplace(address.value, address.where, who);
      if (fresh) return;
      auto d = make_diagnostic(diag_id::net_address_duplicate, address.where,
                               fmt::format("{} is at {}, the address of {}", who, address.value, it->second.second));
      d.notes.push_back({it->second.first, fmt::format("{} is given it here", it->second.second)});
      out_.diags.push_back(std::move(d));
    };
    use(f.scan.address, "the scanner");
    for (const auto& a : f.adapters) use(a.address, fmt::format("adapter '{}'", a.name.value));
  }

  adapter_eds& load(const std::string& path) {
    if (auto it = files_.find(path); it != files_.end()) return it->second;
    auto& e = files_[path];
    auto r = read_ ? read_(path) : io::read_source(path);
    if (!r) {
      e.io_error = r.error().message;
      return e;
    }
    e.a = analyze(std::move(r.value()), options_);
    if (!e.a->diags.empty())
      out_.eds_reports.push_back(
          {std::make_unique<source_file>(e.a->source->path(), std::string(e.a->text())), e.a->diags});
    if (e.a->errors() == 0) e.served = connections::serve_points(e.a->dev);
    return e;
  }

  void adapter(const enip_adapter& a) {
    if (!a.eds.given) return;
    const auto dir = std::filesystem::path(out_.source->path()).parent_path();
    const auto path = (dir / a.eds.value).lexically_normal().string();
    const auto& e = load(path);
    if (e.io_error)
      return add(diag_id::net_eds_unreadable, a.eds.where, fmt::format("adapter '{}': {}", a.name.value, *e.io_error));
    if (e.a->errors() > 0)
      return add(diag_id::net_eds_errors, a.eds.where,
                 fmt::format("adapter '{}': {} has {}; a scanner tool will not register it", a.name.value, path,
                             plural(e.a->errors(), "error")));
    std::vector<const connections::connection_point*> chosen;
    std::vector<planned_io> io;
    for (const auto& c : a.connections) {
      auto p = connection(a, e, c);
      chosen.push_back(p ? p->point : nullptr);
      if (p && p->fo) io.push_back({p->point, *p->fo});
    }
    listen_only_owners(a, chosen);
    check_adapter_capacity(a, e.a->dev, io, out_.diags, totals_);
  }

  // The served point a planned connection names, or none after saying why.
  const connections::connection_point* find_point(const enip_adapter& a, const adapter_eds& e,
                                                  const enip_connection& c) {
    for (const auto& p : e.served.points) {
      const auto& name = p.plan.facts.name;
      if ((c.number.given && p.number == c.number.value) || (c.name.given && name == c.name.value)) return &p;
    }
    for (const auto& s : e.served.skipped)
      if (c.number.given && s.number == c.number.value) {
        add(diag_id::net_connection_not_checked, c.where,
            fmt::format("adapter '{}': Connection{} is not checked: {}", a.name.value, s.number, s.why));
        return nullptr;
      }
    std::string offered;
    for (const auto& p : e.served.points)
      offered += fmt::format("{}Connection{} \"{}\"", offered.empty() ? "" : ", ", p.number, p.plan.facts.name);
    const auto asked = c.number.given ? fmt::format("Connection{}", c.number.value) : "\"" + c.name.value + "\"";
    add(diag_id::net_connection_unknown, c.where,
        fmt::format("adapter '{}': its EDS has no {}; it has {}", a.name.value, asked,
                    offered.empty() ? "no ConnectionN edsc can read" : offered));
    return nullptr;
  }

  // The point a planned connection names, and its Forward_Open with the
  // plan's choices in it where edsc can build one.
  struct chosen_point {
    const connections::connection_point* point = nullptr;
    std::optional<cip::forward_open_request> fo;
  };

  std::optional<chosen_point> connection(const enip_adapter& a, const adapter_eds& e, const enip_connection& c) {
    const auto* p = find_point(a, e, c);
    if (p == nullptr) return std::nullopt;
    if (!p->plan.not_openable.empty() && !p->plan.needs_owner) {
      add(diag_id::net_connection_not_checked, c.where,
          fmt::format("adapter '{}': Connection{} \"{}\" is not checked: {}", a.name.value, p->number,
                      p->plan.facts.name, p->plan.not_openable));
      return chosen_point{p, std::nullopt};
    }
    const model::device* dev = &e.a->dev;
    std::optional<connections::applied_sets> applied;
    if (!c.sets.empty()) {
      std::vector<connections::param_set> sets;
      for (const auto& s : c.sets)
        if (auto ps = connections::parse_set(s.value)) sets.push_back(*ps);
      auto r = connections::apply_sets(*dev, sets);
      if (!r) {
        for (const auto& why : r.error())
          add(diag_id::net_set_invalid, c.where, fmt::format("adapter '{}': {}", a.name.value, why.message));
        return chosen_point{p, std::nullopt};
      }
      applied = std::move(*r);
      dev = &applied->dev;
    }
    auto fo = p->plan.request;
    if (c.rpi_us.given) fo.ot_rpi_us = fo.to_rpi_us = c.rpi_us.value;
    if (c.ot_rpi_us.given) fo.ot_rpi_us = c.ot_rpi_us.value;
    if (c.to_rpi_us.given) fo.to_rpi_us = c.to_rpi_us.value;
    if (c.multicast.given && fo.to.type != cip::conn_type::null)
      fo.to.type = c.multicast.value ? cip::conn_type::multicast : cip::conn_type::point_to_point;
    std::optional<cip::byte_view> config;
    if (!p->plan.config_data.empty()) config = cip::byte_view(p->plan.config_data);
    if (auto r = connections::check_fit(dev, *p, fo, config)) refused(a, c, *p, *r);
    return chosen_point{p, fo};
  }

  void refused(const enip_adapter& a, const enip_connection& c, const connections::connection_point& p,
               const connections::refusal& r) {
    const auto id = r.status == ext::rpi_not_supported ? diag_id::net_rpi_range
                    : r.status == ext::invalid_to_type || r.status == ext::invalid_ot_type
                        ? diag_id::net_multicast_not_offered
                        : diag_id::net_set_invalid;
    span where = c.where;
    if (id == diag_id::net_rpi_range)
      for (const auto* f : {&c.rpi_us, &c.ot_rpi_us, &c.to_rpi_us})
        if (f->given) where = f->where;
    if (id == diag_id::net_multicast_not_offered && c.multicast.given) where = c.multicast.where;
    add(id, where,
        fmt::format("adapter '{}', Connection{} \"{}\": {}; the adapter refuses it (0x{:04X})", a.name.value, p.number,
                    p.plan.facts.name, r.why, cip::code(r.status)));
  }

  // A listen-only connection opens only beside a connection of the same
  // adapter that produces its T->O data (an exclusive owner or input only).
  void listen_only_owners(const enip_adapter& a, const std::vector<const connections::connection_point*>& chosen) {
    for (std::size_t i = 0; i < chosen.size(); ++i) {
      const auto* p = chosen[i];
      if (p == nullptr || p->plan.kind.type != model::app_type::listen_only) continue;
      bool owned = false;
      for (const auto* q : chosen)
        owned = owned || (q != nullptr && q->plan.kind.type != model::app_type::listen_only &&
                          q->plan.facts.input_instance == p->plan.facts.input_instance);
      if (!owned)
        add(diag_id::net_listen_only_without_owner, a.connections[i].where,
            fmt::format("adapter '{}': Connection{} \"{}\" is listen-only and no connection of this plan produces "
                        "its input (instance {}); the adapter refuses it (0x0119) unless another scanner owns it",
                        a.name.value, p->number, p->plan.facts.name, p->plan.facts.input_instance));
    }
  }

  checked_network& out_;
  const check_options& options_;
  const eds_reader& read_;
  std::map<std::string, adapter_eds> files_;
  plan_totals totals_;
};

}  // namespace

void check_enip(const enip_file& f, checked_network& out, const check_options& options, const eds_reader& read) {
  enip_checker(out, options, read).run(f);
}

}  // namespace edsc::network
