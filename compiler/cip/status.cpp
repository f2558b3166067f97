#include "cip/status.hpp"

#include <fmt/format.h>

namespace edsc::cip {

namespace {

template <class Code>
struct entry {
  Code code;
  std::string_view text;
};

template <class Code, std::size_t N>
std::string_view look_up(const entry<Code> (&table)[N], Code code) {
  for (const auto& e : table)
    if (e.code == code) return e.text;
  return {};
}

// OpENer enet_encap/encap.h.
constexpr entry<std::uint32_t> encap_statuses[] = {
    {0x0000, "success"},
    {0x0001, "invalid or unsupported command"},
    {0x0002, "insufficient memory in the target"},
    {0x0003, "incorrect data"},
    {0x0064, "invalid session handle"},
    {0x0065, "invalid length"},
    {0x0069, "unsupported encapsulation protocol revision"},
};

// OpENer cip/ciperror.h.
constexpr entry<std::uint8_t> general_statuses[] = {
    {0x00, "success"},
    {0x01, "connection failure"},
    {0x02, "resource unavailable"},
    {0x03, "invalid parameter value"},
    {0x04, "path segment error"},
    {0x05, "path destination unknown"},
    {0x06, "partial transfer"},
    {0x07, "connection lost"},
    {0x08, "service not supported"},
    {0x09, "invalid attribute value"},
    {0x0A, "attribute list error"},
    {0x0B, "already in requested mode/state"},
    {0x0C, "object state conflict"},
    {0x0D, "object already exists"},
    {0x0E, "attribute not settable"},
    {0x0F, "privilege violation"},
    {0x10, "device state conflict"},
    {0x11, "reply data too large"},
    {0x12, "fragmentation of a primitive value"},
    {0x13, "not enough data"},
    {0x14, "attribute not supported"},
    {0x15, "too much data"},
    {0x16, "object does not exist"},
    {0x17, "service fragmentation sequence not in progress"},
    {0x18, "no stored attribute data"},
    {0x19, "store operation failure"},
    {0x1A, "routing failure, request packet too large"},
    {0x1B, "routing failure, response packet too large"},
    {0x1C, "missing attribute list entry data"},
    {0x1D, "invalid attribute value list"},
    {0x1E, "embedded service error"},
    {0x1F, "vendor specific error"},
    {0x20, "invalid parameter"},
    {0x21, "write-once value or medium already written"},
    {0x22, "invalid reply received"},
    {0x25, "key failure in path"},
    {0x26, "path size invalid"},
    {0x27, "unexpected attribute in list"},
    {0x28, "invalid member id"},
    {0x29, "member not settable"},
};

// OpENer cip/cipconnectionmanager.h (extended status with general 0x01).
constexpr entry<std::uint16_t> extended_statuses[] = {
    {0x0100, "connection in use or duplicate Forward_Open"},
    {0x0103, "transport class and trigger combination not supported"},
    {0x0106, "ownership conflict"},
    {0x0107, "target connection not found"},
    {0x0108, "invalid network connection parameter"},
    {0x0109, "invalid connection size"},
    {0x0110, "target for connection not configured"},
    {0x0111, "RPI not supported"},
    {0x0112, "RPI value not acceptable"},
    {0x0113, "out of connections"},
    {0x0114, "vendor id or product code mismatch"},
    {0x0115, "device type mismatch"},
    {0x0116, "revision mismatch"},
    {0x0117, "invalid produced or consumed application path"},
    {0x0118, "invalid or inconsistent configuration application path"},
    {0x0119, "non-listen-only connection not opened"},
    {0x011A, "target object out of connections"},
    {0x011B, "RPI smaller than the production inhibit time"},
    {0x011C, "transport class not supported"},
    {0x011D, "production trigger not supported"},
    {0x011E, "direction not supported"},
    {0x011F, "invalid O->T fixed/variable flag"},
    {0x0120, "invalid T->O fixed/variable flag"},
    {0x0121, "invalid O->T priority"},
    {0x0122, "invalid T->O priority"},
    {0x0123, "invalid O->T connection type"},
    {0x0124, "invalid T->O connection type"},
    {0x0125, "invalid O->T redundant owner flag"},
    {0x0126, "invalid configuration size"},
    {0x0127, "invalid O->T size"},
    {0x0128, "invalid T->O size"},
    {0x0129, "invalid configuration application path"},
    {0x012A, "invalid consuming application path"},
    {0x012B, "invalid producing application path"},
    {0x012C, "configuration symbol does not exist"},
    {0x012D, "consuming symbol does not exist"},
    {0x012E, "producing symbol does not exist"},
    {0x012F, "inconsistent application path combination"},
    {0x0130, "inconsistent consume data format"},
    {0x0131, "inconsistent produce data format"},
    {0x0132, "null Forward_Open not supported"},
    {0x0133, "connection timeout multiplier not acceptable"},
    {0x0203, "connection timed out"},
    {0x0204, "unconnected request timed out"},
    {0x0205, "parameter error in unconnected request"},
    {0x0206, "message too large for unconnected send"},
    {0x0207, "unconnected acknowledge without reply"},
    {0x0301, "no buffer memory available"},
    {0x0302, "network bandwidth not available"},
    {0x0303, "no consumed connection id filter available"},
    {0x0304, "not configured to send scheduled priority data"},
    {0x0305, "schedule signature mismatch"},
    {0x0306, "schedule signature validation not possible"},
    {0x0311, "port not available"},
    {0x0312, "link address not valid"},
    {0x0315, "invalid segment in connection path"},
    {0x0316, "error in Forward_Close service connection path"},
    {0x0317, "scheduling not specified"},
    {0x0318, "link address to self invalid"},
    {0x0319, "secondary resources unavailable"},
    {0x031A, "rack connection already established"},
    {0x031B, "module connection already established"},
    {0x031C, "miscellaneous"},
    {0x031D, "redundant connection mismatch"},
    {0x031E, "no more user-configurable link consumer resources"},
    {0x031F, "no user-configurable link consumer resources configured"},
    {0x0800, "network link offline"},
    {0x0810, "no target application data available"},
    {0x0811, "no originator application data available"},
    {0x0812, "node address changed since the network was scheduled"},
    {0x0813, "not configured for off-subnet multicast"},
};

std::string code_and_text(std::string_view hex, std::string_view text) {
  return text.empty() ? fmt::format("{} (unknown code)", hex) : fmt::format("{} {}", hex, text);
}

}  // namespace

std::string_view encap_status_text(std::uint32_t status) { return look_up(encap_statuses, status); }
std::string_view general_status_text(std::uint8_t status) { return look_up(general_statuses, status); }
std::string_view extended_status_text(std::uint16_t status) { return look_up(extended_statuses, status); }

std::string describe_status(std::uint8_t general, std::span<const std::uint16_t> additional) {
  auto out = code_and_text(fmt::format("0x{:02X}", general), general_status_text(general));
  if (additional.empty()) return out;
  // The extended status is the first additional word only under general
  // 0x01; elsewhere the words are object-specific and shown as numbers.
  std::size_t i = 0;
  if (general == 0x01) {
    out += ", extended " + code_and_text(fmt::format("0x{:04X}", additional[0]), extended_status_text(additional[0]));
    i = 1;
  }
  if (i < additional.size()) {
    out += " (additional";
    for (; i < additional.size(); ++i) out += fmt::format(" 0x{:04X}", additional[i]);
    out += ")";
  }
  return out;
}

std::string describe_identity_status(std::uint16_t status) {
  // CIP Vol 1 5-2.2.1.5, as OpENer's cipidentity.h names the bits.
  static constexpr entry<std::uint16_t> bits[] = {
      {0x0001, "owned"},
      {0x0004, "configured"},
      {0x0100, "minor recoverable fault"},
      {0x0200, "minor unrecoverable fault"},
      {0x0400, "major recoverable fault"},
      {0x0800, "major unrecoverable fault"},
  };
  static constexpr std::string_view states[] = {
      "self-testing or unknown", "firmware update in progress", "at least one faulted I/O connection",
      "no I/O connections established", "non-volatile configuration bad", "major fault",
      "at least one I/O connection in run mode", "at least one I/O connection established, all in idle mode",
  };
  std::string out = fmt::format("0x{:04X}", status);
  std::string words;
  for (const auto& b : bits)
    if (status & b.code) words += fmt::format("{}{}", words.empty() ? "" : ", ", b.text);
  const unsigned state = (status >> 4) & 0x0F;
  if (state < std::size(states)) words += fmt::format("{}{}", words.empty() ? "" : ", ", states[state]);
  return words.empty() ? out : fmt::format("{} ({})", out, words);
}

}  // namespace edsc::cip
