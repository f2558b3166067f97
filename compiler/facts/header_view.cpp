// Identity, DeviceNet I/O and [Capacity] facts for `edsc header`.
#include <filesystem>

#include <fmt/format.h>

#include "cip/encap.hpp"
#include "facts/header_parts.hpp"
#include "facts/header_view.hpp"
#include "facts/sha256.hpp"

namespace edsc::emit {

namespace {

using model::value;

// A required [Device] integer: reported (and 0) when absent, invalid or too big.
template <typename T>
T identity_number(const value& v, const char* keyword, std::uint64_t max, std::vector<header_issue>& issues) {
  if (v.is_integer() && !v.negative && v.magnitude <= max) return static_cast<T>(v.magnitude);
  issues.push_back({true, fmt::format("[Device] {} is {}; the header cannot state the Identity object without it",
                                      keyword, v.present() ? fmt::format("not a number up to {}", max) : "missing")});
  return 0;
}

std::optional<std::string> text_of(const value& v) {
  if (!v.ok() || v.kind != model::value_kind::string) return std::nullopt;
  return std::string(v.text);
}

identity_facts collect_identity(const model::device_info& d, std::vector<header_issue>& issues) {
  identity_facts id;
  id.vendor_id = identity_number<std::uint16_t>(d.vend_code, "VendCode", 0xFFFF, issues);
  id.device_type = identity_number<std::uint16_t>(d.prod_type, "ProdType", 0xFFFF, issues);
  id.product_code = identity_number<std::uint16_t>(d.prod_code, "ProdCode", 0xFFFF, issues);
  id.major_revision = identity_number<std::uint8_t>(d.maj_rev, "MajRev", 0xFF, issues);
  id.minor_revision = identity_number<std::uint8_t>(d.min_rev, "MinRev", 0xFF, issues);
  if (auto name = text_of(d.prod_name)) {
    id.product_name = std::move(*name);
  } else {
    issues.push_back({true, "[Device] ProdName is missing; the header cannot state the Identity object without it"});
  }
  // Identity attribute 7 holds at most 32 bytes; a scanner matches vendor,
  // type, code and major revision, so a shortened name is harmless. It ends
  // between two characters, so the device never shows half of one.
  if (id.product_name.size() > cip::max_product_name) {
    const auto kept = cip::held_product_name(id.product_name).size();
    issues.push_back({false, fmt::format("[Device] ProdName is {} bytes; the Identity object's Product Name holds at "
                                         "most {}, so the header carries its first {}{}",
                                         id.product_name.size(), cip::max_product_name, kept,
                                         kept < cip::max_product_name
                                             ? fmt::format(" ({} would cut a character in two)", cip::max_product_name)
                                             : "")});
    id.product_name.resize(kept);
  }
  id.catalog = text_of(d.catalog);
  id.vendor_name = text_of(d.vend_name);
  return id;
}

std::uint32_t data_size(const model::io_info& io, const value& ref_value, bool output) {
  const auto* r = ref_value.as_ref();
  if (r == nullptr || !r->resolved()) return 0;
  const auto& list = output ? io.outputs : io.inputs;
  if (r->target >= list.size()) return 0;
  const auto& size = list[r->target].size;
  return size.is_integer() ? static_cast<std::uint32_t>(size.as_uint()) : 0;
}

// A type exists when some InputN/OutputN may be used with it, or its xxxInfo
// names default data. The RightSight capture shows why an xxxInfo alone is
// not enough: `PollInfo = 0x0001, 0, 0;` and yet "object does not exist".
devicenet_facts collect_devicenet(const model::io_info& io, std::vector<header_issue>& issues) {
  devicenet_facts dn;
  std::uint64_t data_mask = 0;
  for (const auto* list : {&io.inputs, &io.outputs})
    for (const auto& d : *list)
      if (d.mask.is_integer()) data_mask |= d.mask.as_uint();
  constexpr std::uint8_t choice_bits[4] = {0x02, 0x04, 0x10, 0x20};
  for (std::size_t t = 0; t < dn.types.size(); ++t) {
    auto& f = dn.types[t];
    const model::io_connection_info* info = nullptr;
    for (const auto& c : io.connections)
      if (static_cast<std::size_t>(c.type) == t && info == nullptr) info = &c;
    bool names_data = false;
    if (info != nullptr) {
      for (const auto* v : {&info->default_input, &info->default_output}) {
        const auto* r = v->as_ref();
        if (r == nullptr) continue;
        if (r->resolved()) {
          names_data = true;
        } else {
          issues.push_back(
              {false, fmt::format("[IO_Info] {}Info names {}{}, which does not exist; its size is taken as 0", f.name,
                                  v == &info->default_input ? "Input" : "Output", r->number)});
        }
      }
      f.produced_size = data_size(io, info->default_input, false);
      f.consumed_size = data_size(io, info->default_output, true);
    }
    f.supported = (data_mask & (1u << t)) != 0 || names_data;
    if (f.supported) dn.allocation_choice_mask |= choice_bits[t];
  }
  if (io.default_mask.is_integer()) dn.default_connections = static_cast<std::uint16_t>(io.default_mask.as_uint());
  return dn;
}

// The counts of [Capacity] (EDS_FORMAT.md §3.13); ConnOverhead is a factor, not a count.
std::vector<capacity_fact> collect_capacity(const model::capacity& cap) {
  std::vector<capacity_fact> out;
  for (const auto& s : cap.settings) {
    const auto* v = s.first();
    if (s.canonical.substr(0, 3) != "Max" || v == nullptr || !v->is_integer() || v->negative) continue;
    auto name = upper_snake(s.canonical);
    bool seen = false;
    for (const auto& c : out) seen = seen || c.name == name;
    if (!seen) out.push_back({std::move(name), v->as_uint()});
  }
  return out;
}

}  // namespace

header_facts collect_facts(const model::device& dev, const source_file& src, std::vector<header_issue>& issues) {
  header_facts f;
  f.source_name = std::filesystem::path(src.path()).filename().string();
  f.source_sha256 = sha256_hex(src.text());
  f.identity = collect_identity(dev.identity, issues);
  if ((dev.classes.networks & model::net_devicenet) != 0 || dev.io.section != model::none)
    f.devicenet = collect_devicenet(dev.io, issues);
  f.ethernetip = (dev.classes.networks & model::net_ethernetip) != 0 || !dev.connections.empty();
  if (f.ethernetip) {
    f.connections = collect_connections(dev, issues);
    f.capacity = collect_capacity(dev.cap);
  }
  f.params = collect_params(dev);
  return f;
}

}  // namespace edsc::emit
