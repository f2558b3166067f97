#pragma once
// `edsc probe`: what a device says about itself (ListIdentity, Identity
// attributes) and the sizes of the assembly instances it lets us read.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "cip/encap.hpp"
#include "live/error.hpp"

namespace edsc::live {

struct assembly_size {
  std::uint32_t instance = 0;
  std::uint32_t size = 0;  // bytes (attribute 4)
};

struct probe_result {
  cip::identity identity;
  std::string identity_source;              // "Identity object", "ListIdentity (UDP)"
  std::vector<cip::service_info> services;  // ListServices
  std::vector<assembly_size> assemblies;
  std::string assemblies_note;  // why the list may be incomplete
};

struct probe_options {
  std::chrono::milliseconds timeout{3000};
  bool udp = false;                            // ListIdentity by UDP instead of TCP
  std::vector<std::uint32_t> extra_instances;  // assembly instances to read besides the scan
};

// Instances up to the Assembly class's Max Instance (attribute 2), at most
// this many, are asked for their size one request at a time.
inline constexpr std::uint32_t max_scanned_instances = 512;

[[nodiscard]] result<probe_result> probe(const net::endpoint& device, const probe_options& opt);

// What a scanner's electronic key from an EDS revision would say of the device.
enum class keying { exact, compatible, none };
[[nodiscard]] keying keying_verdict(unsigned eds_major, unsigned eds_minor, unsigned dev_major, unsigned dev_minor);
[[nodiscard]] const char* to_string(keying k);

}  // namespace edsc::live
