#include "announced.hpp"

#include <nlohmann/json.hpp>

#include "cip/connectionManager/NetworkConnectionParams.h"

namespace edsc::scanner_test {

namespace {

using nlohmann::json;

// "20 04 24 97" as bytes; an empty string is no bytes.
bytes from_hex(const std::string& text) {
  bytes out;
  for (std::size_t i = 0; i + 1 < text.size();) {
    if (text[i] == ' ') {
      ++i;
      continue;
    }
    out.push_back(static_cast<std::uint8_t>(std::stoul(text.substr(i, 2), nullptr, 16)));
    i += 2;
  }
  return out;
}

bytes hex_or_empty(const json& j) { return j.is_string() ? from_hex(j.get<std::string>()) : bytes{}; }

announced_direction direction_of(const json& d) {
  announced_direction a;
  a.used = d.at("used").get<bool>();
  a.sequence = d.at("sequence_count").get<bool>();
  a.run_idle = d.at("run_idle").get<bool>();
  a.data_size = d.at("data_size").get<unsigned>();
  a.wire_size = d.at("wire_size").get<unsigned>();
  if (!d.at("network_parameters_16").is_null()) a.word16 = d.at("network_parameters_16").get<std::uint32_t>();
  a.word32 = d.at("network_parameters_32").get<std::uint32_t>();
  a.rpi_us = d.at("rpi").at("us").get<std::uint32_t>();
  a.type = d.at("type").get<std::string>();
  return a;
}

announced_connection connection_of(const json& c) {
  announced_connection a;
  a.number = c.at("number").get<unsigned>();
  a.name = c.at("name").get<std::string>();
  a.kind = c.at("kind").get<std::string>();
  a.classes = c.at("classes").get<std::vector<unsigned>>();
  a.owners = c.at("owners").get<std::vector<unsigned>>();
  a.expressible = c.at("expressible").get<bool>();
  if (c.at("why_not").is_string()) a.why_not = c.at("why_not").get<std::string>();
  a.path = hex_or_empty(c.at("path").at("hex"));
  if (c.at("key").is_object()) a.key = hex_or_empty(c.at("key").at("hex"));
  if (c.at("configuration").is_object()) a.config = hex_or_empty(c.at("configuration").at("data_hex"));
  a.request = hex_or_empty(c.at("forward_open_hex"));
  a.ot = direction_of(c.at("o_to_t"));
  a.to = direction_of(c.at("t_to_o"));
  a.transport = c.at("transport_byte").get<std::uint8_t>();
  a.large = c.at("large_forward_open").get<bool>();
  return a;
}

// The network connection parameters EIPScanner is given: the announced word
// less the header bytes it adds itself (2 for the sequence count of class
// 1 and 3, 4 for the run/idle header), or the reason it cannot.
std::string eipscanner_word(const announced_direction& d, bool large, bool sequenced, std::uint32_t& word) {
  if (!large && !d.word16) return "a size over 511 bytes has no Forward_Open word";
  word = large ? d.word32 : *d.word16;
  const std::uint32_t size_mask = large ? 0xFFFF : 0x1FF;
  if (sequenced && !d.sequence) return "EIPScanner adds a sequence count to every class 1 direction, this one has none";
  const std::uint32_t added = (sequenced ? 2 : 0) + (d.run_idle ? 4 : 0);
  if ((word & size_mask) < added) return "the announced size is smaller than the headers EIPScanner adds";
  word -= added;
  return {};
}

}  // namespace

std::vector<announced_connection> read_announced(const std::string& json_text, std::string& error) {
  std::vector<announced_connection> out;
  try {
    const auto doc = json::parse(json_text);
    for (const auto& c : doc.at("connections")) out.push_back(connection_of(c));
  } catch (const std::exception& e) {
    error = e.what();
    out.clear();
  }
  return out;
}

bytes scanner_path(const announced_connection& c) {
  bytes p = c.key;
  p.insert(p.end(), c.path.begin(), c.path.end());
  if (!c.config.empty()) {
    p.push_back(0x80);
    p.push_back(static_cast<std::uint8_t>((c.config.size() + 1) / 2));
    p.insert(p.end(), c.config.begin(), c.config.end());
    if (c.config.size() % 2 != 0) p.push_back(0);
  }
  return p;
}

scanner_settings scanner_parameters(const announced_connection& c) {
  using eipScanner::cip::connectionManager::NetworkConnectionParams;
  scanner_settings s;
  auto& p = s.params;
  p.connectionPath = scanner_path(c);
  p.originatorVendorId = 0x0457;
  p.originatorSerialNumber = 0x00EC5CA1;
  p.connectionTimeoutMultiplier = 3;  // x32: a busy machine's late frame closes nothing
  p.transportTypeTrigger = c.transport;
  p.o2tRPI = c.ot.rpi_us;
  p.t2oRPI = c.to.rpi_us;
  p.o2tRealTimeFormat = c.ot.run_idle;
  p.t2oRealTimeFormat = c.to.run_idle;
  // As EIPScanner's forwardOpen decides it adds the sequence count.
  const bool sequenced =
      (c.transport & NetworkConnectionParams::CLASS1) != 0 || (c.transport & NetworkConnectionParams::CLASS3) != 0;
  std::uint32_t ot = 0, to = 0;
  if (auto why = eipscanner_word(c.ot, c.large, sequenced, ot); !why.empty()) s.cannot = "O->T: " + why;
  if (auto why = eipscanner_word(c.to, c.large, sequenced, to); !why.empty()) s.cannot = "T->O: " + why;
  p.o2tNetworkConnectionParams = ot;
  p.t2oNetworkConnectionParams = to;
  return s;
}

}  // namespace edsc::scanner_test
