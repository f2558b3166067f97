// What OpENer must be told to serve an EDS: its assemblies and connection
// points from the EtherNet/IP connection facts `edsc header` already computes
// (header_eip.cpp), and a located diagnostic for each thing OpENer cannot do.
#include "emit/opener_plan.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "facts/header_parts.hpp"

namespace edsc::emit {

namespace {

const model::connection* model_connection(const model::device& dev, std::uint32_t number) {
  for (const auto& c : dev.connections)
    if (c.kind == model::connection_kind::connection && c.number == number) return &c;
  return nullptr;
}

// Where a finding about a connection points: its path field, else the entry.
span where_of(const model::connection& c, const model::value& field) {
  return field.present() ? field.from.where : c.from.where;
}

// Why OpENer cannot read the path's connection points, or empty. After the
// configuration instance it reads one per direction the Forward_Open opens
// (O->T, then T->O; a null direction has none): with fewer it reads past
// the path and refuses the connection with 0x0315 (measured on a generated
// device, tests/eipscanner). The directions are those a scanner configured
// from the EDS opens (connections/plan.cpp: any type but null offered).
std::string points_problem(const model::connection& c, const model::epath& p) {
  const auto opened = [](const model::direction_params& d) { return d.type_p2p || d.type_multicast; };
  const auto needed = (opened(c.cp.ot) ? 1 : 0) + (opened(c.cp.to) ? 1 : 0);
  const auto points = std::count_if(p.segments.begin(), p.segments.end(),
                                    [](const auto& s) { return s.kind == model::segment_kind::connection_point; });
  if (points >= needed) return {};
  return fmt::format(
      "its path gives {} connection point{} (0x2C) where OpENer reads {}, one per direction the connection opens "
      "(O->T, then T->O); OpENer refuses it with 0x0315",
      points, points == 1 ? "" : "s", needed);
}

// Why OpENer cannot serve this path, or empty: its connection points join
// assembly instances that the EDS states as numbers.
std::string path_problem(const model::device& dev, const model::connection& c, const eip_connection_facts& f) {
  const auto* p = dev.path_of(c.path);
  if (p == nullptr) return "it has no path OpENer could match a Forward_Open against";
  bool instance_seen = false;
  for (const auto& s : p->segments) {
    // OpENer reads one instance (configuration) and then connection points
    // (0x2C); a second instance segment it refuses (0x0315, measured).
    if (s.kind == model::segment_kind::instance) {
      if (instance_seen)
        return fmt::format(
            "its path names instance {} with a 0x24 segment where OpENer expects a connection point "
            "(0x2C); OpENer refuses it with 0x0315",
            s.value);
      instance_seen = true;
    }
    switch (s.kind) {
      case model::segment_kind::class_id:
        if (s.value_known() && s.value != 0x04)
          return fmt::format("its path names class 0x{:02X}; OpENer connects to assemblies (class 0x04) only", s.value);
        break;
      case model::segment_kind::port: return "its path routes through a port; OpENer serves its own assemblies only";
      case model::segment_kind::instance:
      case model::segment_kind::connection_point:
        if (!s.placeholder.empty()) return "its path holds a placeholder the tool fills in, not an instance";
        if (s.value_known() && s.value > 0xFFFF)
          return fmt::format("its path names instance {}; OpENer numbers assembly instances in 16 bits", s.value);
        break;
      case model::segment_kind::placeholder: return "its path holds a placeholder the tool fills in, not an instance";
      case model::segment_kind::symbol:
      case model::segment_kind::unknown: return "its path holds a segment OpENer does not match connection points by";
      default: break;
    }
  }
  if (f.output_size > 0 && f.output_instance == 0) return "its O->T data has no assembly instance in the path";
  if (f.input_size > 0 && f.input_instance == 0) return "its T->O data has no assembly instance in the path";
  if (f.input_instance == 0)
    return "its path names no input (T->O) instance, which every OpENer connection point needs";
  return points_problem(c, *p);
}

class planner {
 public:
  planner(const model::device& dev, diagnostics& diags) : dev_(dev), diags_(diags) {}

  void add(const eip_connection_facts& f) {
    const auto* c = model_connection(dev_, f.number);
    if (c == nullptr) return;  // a proxy entry: not an I/O connection of this device
    const auto tt = model::decode_trigger(f.trigger_transport);
    const auto kind = model::classify(tt, f.config_size > 0 && f.config_instance != 0);
    if (!c->decoded || !kind.unambiguous()) {
      report(diag_id::opener_connection_kind, where_of(*c, c->trigger),
             fmt::format(
                 "Connection{}: {}", f.number,
                 !c->decoded ? "its trigger/transport is not a number OpENer's kinds can be read from"
                 : kind.named == 0
                     ? (tt.redundant_owner ? "redundant owner has no OpENer connection point"
                                           : "it names no transport type (exclusive owner, input only, listen only)")
                     : "it names more than one transport type; OpENer configures one kind per point"));
      return;
    }
    if (const auto why = path_problem(dev_, *c, f); !why.empty()) {
      report(diag_id::opener_connection_path, where_of(*c, c->path), fmt::format("Connection{}: {}", f.number, why));
      return;
    }
    if (!assembly(*c, f.input_instance, f.input_size, "input", c->to_size, c->to_format) ||
        !assembly(*c, f.output_instance, f.output_size, "output", c->ot_size, c->ot_format) ||
        !assembly(*c, f.config_instance, f.config_size, "configuration", c->target_config_size,
                  c->target_config_format))
      return;
    opener_point p;
    p.kind = kind.type;
    auto& count = p.kind == model::app_type::exclusive_owner ? plan.exclusive_owner
                  : p.kind == model::app_type::input_only    ? plan.input_only
                                                             : plan.listen_only;
    p.index = count++;
    p.connection = f.number;
    p.name = f.name;
    p.output_instance = f.output_instance;
    p.input_instance = f.input_instance;
    p.config_instance = f.config_instance;
    plan.points.push_back(std::move(p));
    // Run/idle is one build option per direction; only the owner's O->T
    // carries data (input and listen only send heartbeats).
    if (kind.type == model::app_type::exclusive_owner) direction(*c, f.output_run_idle, consumed_, "O->T");
    direction(*c, f.input_run_idle, produced_, "T->O");
  }

  void finish() {
    std::sort(plan.assemblies.begin(), plan.assemblies.end(),
              [](const auto& a, const auto& b) { return a.instance < b.instance; });
    if (consumed_.seen) plan.consumed_run_idle = consumed_.run_idle;
    if (produced_.seen) plan.produced_run_idle = produced_.run_idle;
    for (const auto& a : plan.assemblies) {
      const bool configuration = std::any_of(plan.points.begin(), plan.points.end(),
                                             [&](const opener_point& p) { return p.config_instance == a.instance; });
      const auto needed = a.size + (configuration ? opener_forward_open_headroom : opener_buffer_headroom);
      // The 16-bit encapsulation length bounds every message.
      plan.ethernet_buffer_bytes = std::max(plan.ethernet_buffer_bytes, std::min<std::uint32_t>(needed, 65535));
    }
  }

  opener_plan plan;

 private:
  struct run_idle_choice {
    bool seen = false, run_idle = false;
    std::uint32_t connection = 0;
  };

  void report(diag_id id, span where, std::string message) {
    diags_.push_back(make_diagnostic(id, where, std::move(message)));
  }

  // One buffer per instance: the first connection giving it data fixes its size.
  bool assembly(const model::connection& c, std::uint32_t instance, std::uint32_t size, const char* role,
                const model::value& size_field, const model::value& format) {
    if (instance == 0) return true;
    // The Assembly object reports the [Assembly] entry's size (attribute 4)
    // and OpENer holds one buffer: the two sizes must agree.
    if (const auto* a = assembly_of(dev_, format); a != nullptr && size > 0) {
      const auto declared = assembly_size(dev_, a);
      if (declared > 0 && declared != size) {
        report(diag_id::opener_assembly_size, where_of(c, size_field),
               fmt::format("Connection{}: the {} has {} bytes but the assembly it names has {}; OpENer holds one "
                           "buffer per instance",
                           c.number, role, size, declared));
        return false;
      }
    }
    if (size > opener_max_assembly_bytes) {
      report(diag_id::opener_assembly_size, where_of(c, size_field),
             fmt::format("Connection{}: the {} assembly {} has {} bytes; an OpENer message holds at most {}", c.number,
                         role, instance, size, opener_max_assembly_bytes));
      return false;
    }
    for (auto& a : plan.assemblies)
      if (a.instance == instance) {
        // 0 bytes is a connection that sends none (a configuration left
        // out, a heartbeat), not a size: the instance keeps its data size.
        if (a.size == size || size == 0) return true;
        if (a.size == 0) {
          a.size = size;
          return true;
        }
        report(diag_id::opener_assembly_size, where_of(c, size_field),
               fmt::format("Connection{}: assembly {} has {} bytes here but {} as the {} of an earlier connection; "
                           "OpENer holds one buffer per instance",
                           c.number, instance, size, a.size, a.role));
        return false;
      }
    plan.assemblies.push_back({instance, size, role});
    return true;
  }

  void direction(const model::connection& c, bool run_idle, run_idle_choice& choice, const char* dir) {
    if (!choice.seen) {
      choice = {true, run_idle, c.number};
      return;
    }
    if (choice.run_idle != run_idle)
      report(diag_id::opener_run_idle, where_of(c, c.params),
             fmt::format("Connection{}: its {} data {} run/idle header but Connection{}'s {}", c.number, dir,
                         run_idle ? "has a" : "has no", choice.connection, run_idle ? "has none" : "has one"));
  }

  const model::device& dev_;
  diagnostics& diags_;
  run_idle_choice consumed_, produced_;
};

}  // namespace

opener_plan plan_opener(const model::device& dev, const source_file& src, diagnostics& diags,
                        std::vector<header_issue>& issues) {
  const auto facts = collect_facts(dev, src, issues);
  planner p(dev, diags);
  for (const auto& f : facts.connections) p.add(f);
  p.finish();
  p.plan.identity = facts.identity;
  p.plan.source_name = facts.source_name;
  p.plan.source_sha256 = facts.source_sha256;
  bool any_connection = false;
  for (const auto& c : dev.connections) any_connection = any_connection || c.kind == model::connection_kind::connection;
  if (!any_connection)
    diags.push_back(
        make_diagnostic(diag_id::opener_no_connection, span{},
                        "no ConnectionN in [Connection Manager]: OpENer would have no I/O connection to serve"));
  return std::move(p.plan);
}

}  // namespace edsc::emit
