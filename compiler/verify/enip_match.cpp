// Which EDS file describes each device a capture shows: by the identity it
// gave (ListIdentity, the Identity object), else by the electronic key its
// Forward_Opens carry, else the one file given (said as an assumption).
#include <map>

#include <fmt/format.h>

#include "cip/request.hpp"
#include "connections/plan.hpp"
#include "verify/enip_capture.hpp"
#include "verify/enip_judge.hpp"

namespace edsc::verify {

std::string address_text(std::uint32_t a) {
  return fmt::format("{}.{}.{}.{}", a >> 24, (a >> 16) & 0xFF, (a >> 8) & 0xFF, a & 0xFF);
}

std::optional<cip::electronic_key> key_in(const cip::forward_open_request& fo) {
  auto segs = cip::decode_path(fo.path, 0);
  if (!segs) return std::nullopt;
  for (const auto& s : *segs)
    if (s.type == cip::segment_type::key) return s.key;
  return std::nullopt;
}

namespace {

bool describes(const cip::electronic_key& eds, const cip::identity& id) {
  return eds.vendor == id.vendor && eds.device_type == id.device_type && eds.product_code == id.product_code &&
         eds.major == id.major;
}

// A key names a product when it gives at least its vendor and product code;
// every field it gives must be the EDS's.
bool names(const cip::electronic_key& eds, const cip::electronic_key& k) {
  if (k.vendor == 0 || k.product_code == 0) return false;
  return k.vendor == eds.vendor && k.product_code == eds.product_code &&
         (k.device_type == 0 || k.device_type == eds.device_type) && (k.major == 0 || k.major == eds.major);
}

void match(capture_device& d, const capture::tracker& t, std::span<const std::optional<cip::electronic_key>> keys) {
  if (d.identity) {
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] && describes(*keys[i], *d.identity)) {
        d.eds = i;
        d.how = matched_by::identity;
        return;
      }
    return;  // the device said who it is, and no file describes it
  }
  for (const auto ci : d.connections) {
    const auto k = key_in(t.connections()[ci].request);
    if (!k) continue;
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] && names(*keys[i], *k)) {
        d.eds = i;
        d.how = matched_by::key;
        return;
      }
  }
  if (keys.size() == 1) {
    d.eds = 0;
    d.how = matched_by::only_file;
  }
}

}  // namespace

std::vector<capture_device> find_devices(const capture::tracker& t, std::span<const capture_eds> files) {
  std::map<std::uint32_t, capture_device> by_address;
  for (const auto& id : t.identities()) {
    auto& d = by_address[id.address];
    if (d.identity) continue;  // the first the capture shows
    d.address = id.address;
    d.identity = id.id;
    d.identity_frame = id.frame;
  }
  const auto& cs = t.connections();
  for (std::size_t i = 0; i < cs.size(); ++i) {
    auto& d = by_address[cs[i].target.address];
    d.address = cs[i].target.address;
    d.connections.push_back(i);
  }
  std::vector<std::optional<cip::electronic_key>> keys;
  for (const auto& f : files) keys.push_back(connections::key_from_device(*f.dev));
  std::vector<capture_device> out;
  for (auto& [address, d] : by_address) {
    match(d, t, keys);
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace edsc::verify
