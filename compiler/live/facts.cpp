#include "live/facts.hpp"

#include <unistd.h>

#include <fmt/format.h>

#include "connections/plan.hpp"
#include "live/client.hpp"
#include "net/interrupt.hpp"

namespace edsc::live {

namespace {

struct gatherer {
  const model::device& dev;
  const live_options& opt;
  live_facts& f;
  std::optional<bool> assembly_class;

  void step(const std::string& what) const {
    if (opt.progress) opt.progress(what);
  }
  // True once the run stops: a failure, or a signal caught before this check.
  bool stopped() {
    if (f.failure || f.interrupted) return true;
    f.interrupted = net::interruption();
    return f.interrupted != 0;
  }
  void lost(const error& e, bool during_check) {
    f.failure = e;
    f.during_check = during_check;
  }

  void identity(client& s) {
    if (stopped()) return;
    step("reading the identity");
    auto id = read_identity(s);
    if (!id) return lost(id.error(), true);
    f.identity = std::move(*id);
  }

  // Whether the device answers for the Assembly class itself (its Max Instance).
  result<bool> assembly_class_answers(client& s) {
    if (!assembly_class) {
      auto r = s.request(cip::service::get_attribute_single, cip::logical_path(cip::class_id::assembly, 0, 2));
      if (!r) return r.error();
      assembly_class = r->is(cip::general_status::success);
    }
    return *assembly_class;
  }

  void assemblies(client& s) {
    const auto targets = plan_assemblies(dev);
    for (std::size_t i = 0; i < targets.size() && !stopped(); ++i) {
      step(fmt::format("reading the size of assembly instance {} ({} of {})", targets[i].instance, i + 1,
                       targets.size()));
      auto r = s.request(cip::service::get_attribute_single,
                         cip::logical_path(cip::class_id::assembly, targets[i].instance, 4));
      if (!r) return lost(r.error(), true);
      assembly_fact a{std::move(*r), std::nullopt};
      // Path destination unknown is OpENer's answer.
      if (a.size.is(cip::general_status::path_destination_unknown) ||
          a.size.is(cip::general_status::object_does_not_exist)) {
        auto known = assembly_class_answers(s);
        if (!known) return lost(known.error(), true);
        a.class_answers = *known;
      }
      f.assemblies.push_back(std::move(a));
    }
  }

  void connections(client& s) {
    auto serial = static_cast<std::uint16_t>(0x4500 + (::getpid() & 0xFF));
    const auto plans = plan_connections(dev);
    for (std::size_t i = 0; i < plans.size() && !stopped(); ++i) {
      const auto& p = plans[i];
      if (!p.not_openable.empty()) {
        f.connections.emplace_back();
        continue;
      }
      const auto window = io_window(opt, p.to_rpi_us);
      step(fmt::format("opening Connection{} ({} of {}) and watching its I/O for {:.1f} s", p.facts.number, i + 1,
                       plans.size(), window.count() / 1000.0));
      auto o = exercise_connection(s, p, ++serial, window);
      if (!o.opened && o.failure) return lost(*o.failure, true);
      f.connections.emplace_back(o);
      if (o.failure) return lost(*o.failure, false);
      if (o.interrupted) f.interrupted = net::interruption();
    }
  }
};

}  // namespace

live_facts gather_facts(const net::endpoint& device, const model::device& dev, const live_options& opt) {
  live_facts f;
  gatherer g{dev, opt, f, std::nullopt};
  g.step(fmt::format("connecting to {}", device.text));
  auto opened = client::open(device, opt.timeout);
  if (!opened) {
    f.failure = opened.error();
    return f;
  }
  f.connected = true;
  g.identity(*opened);
  g.assemblies(*opened);
  if (opt.connections) g.connections(*opened);
  opened->close();
  return f;
}

}  // namespace edsc::live
