#include "live/probe.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "cip/message.hpp"
#include "cip/status.hpp"
#include "live/client.hpp"

namespace edsc::live {

keying keying_verdict(unsigned eds_major, unsigned eds_minor, unsigned dev_major, unsigned dev_minor) {
  if (eds_major != dev_major) return keying::none;
  if (eds_minor == dev_minor) return keying::exact;
  // Compatible keying: a device of a newer minor revision emulates the older one.
  return dev_minor > eds_minor ? keying::compatible : keying::none;
}

const char* to_string(keying k) {
  switch (k) {
    case keying::exact: return "exact";
    case keying::compatible: return "compatible";
    case keying::none: return "none";
  }
  return "none";
}

result<probe_result> probe(const net::endpoint& device, const probe_options& opt) {
  probe_result out;
  if (opt.udp) {
    auto ids = list_identity_udp(device, opt.timeout);
    if (!ids) return ids.error();
    out.identity = ids->front();
    out.identity_source = "ListIdentity (UDP)";
  }
  auto opened = client::open(device, opt.timeout);
  if (!opened) return opened.error();
  auto& s = *opened;
  if (!opt.udp) {
    auto id = read_identity(s);
    if (!id) return id.error();
    out.identity = *id;
    out.identity_source = "Identity object";
  }
  auto services = s.list_services();
  if (!services) return services.error();
  out.services = *services;
  // Assembly class attribute 2, Max Instance, bounds the scan.
  auto max = s.request(cip::service::get_attribute_single, cip::logical_path(cip::class_id::assembly, 0, 2));
  if (!max) return max.error();
  std::vector<std::uint32_t> instances = opt.extra_instances;
  if (const auto& rep = *max; rep.general == 0 && rep.data.size() >= 2) {
    const std::uint32_t n = rep.data[0] | (rep.data[1] << 8);
    for (std::uint32_t i = 1; i <= std::min(n, max_scanned_instances); ++i) instances.push_back(i);
    if (n > max_scanned_instances)
      out.assemblies_note = fmt::format("only instances 1-{} of {} read", max_scanned_instances, n);
  } else {
    out.assemblies_note = fmt::format(
        "the Assembly class's Max Instance is not readable ({}); only instances "
        "named by the library's EDS files were tried",
        rep.general ? cip::describe_status(rep.general, rep.additional) : "no data");
  }
  std::sort(instances.begin(), instances.end());
  instances.erase(std::unique(instances.begin(), instances.end()), instances.end());
  for (const auto i : instances) {
    auto r = s.request(cip::service::get_attribute_single, cip::logical_path(cip::class_id::assembly, i, 4));
    if (!r) return r.error();
    const auto& rep = *r;
    if (rep.general == 0 && rep.data.size() >= 2)
      out.assemblies.push_back({i, static_cast<std::uint32_t>(rep.data[0] | (rep.data[1] << 8))});
  }
  s.close();
  return out;
}

}  // namespace edsc::live
