// Plain words for the decoded traffic: service, attribute and status names
// and the --decode table.
#include <fmt/format.h>

#include "cip/codes.hpp"
#include "verify/decode.hpp"

namespace edsc::verify {

std::string service_name(std::uint8_t service, std::uint8_t cls) {
  const auto name = cip::name_of(cip::service{service}, cip::class_id{cls});
  return name.empty() ? fmt::format("service 0x{:02X}", service) : std::string(name);
}

std::string attribute_name(std::uint8_t cls, std::uint8_t inst, std::uint8_t attr) {
  if (cls == 0x01) {
    static constexpr const char* names[] = {"",         "vendor ID", "device type",   "product code",
                                            "revision", "status",    "serial number", "product name"};
    return attr >= 1 && attr <= 7 ? fmt::format("Identity {}", names[attr])
                                  : fmt::format("Identity attribute {}", attr);
  }
  if (cls == 0x03) {
    return attr == 1   ? "DeviceNet MAC ID"
           : attr == 2 ? "DeviceNet baud rate"
                       : fmt::format("DeviceNet attribute {}", attr);
  }
  if (cls == 0x05) {
    static constexpr const char* conns[] = {"", "explicit", "polled", "bit-strobed", "COS/cyclic", "multicast poll"};
    const std::string conn = inst >= 1 && inst <= 5 ? conns[inst] : fmt::format("instance {}", inst);
    switch (attr) {
      case 7: return conn + " produced_connection_size";
      case 8: return conn + " consumed_connection_size";
      case 9: return conn + " expected_packet_rate";
      case 0x0C: return conn + " watchdog_timeout_action";
      case 0x11: return conn + " production_inhibit_time";
      default: return fmt::format("{} connection attribute {}", conn, attr);
    }
  }
  if (cls == 0x2B && attr == 1) return "acknowledge timer";
  return fmt::format("class 0x{:02X} attribute {}", cls, attr);
}

std::string status_name(std::uint8_t general) {
  const cip::general_status status{general};
  if (status == cip::general_status::success) return "success";
  const auto words = cip::words_of(status);
  return words.empty() ? fmt::format("general status 0x{:02X}", general) : fmt::format("{} (0x{:02X})", words, general);
}

std::string choice_names(std::uint8_t choice) {
  static constexpr const char* names[] = {"explicit", "poll",   "bit-strobe",      "multicast poll",
                                          "COS",      "cyclic", "ack suppression", "bit 7"};
  std::string out;
  for (int b = 0; b < 8; ++b) {
    if ((choice & (1u << b)) == 0) continue;
    if (!out.empty()) out += " + ";
    out += names[b];
  }
  return out.empty() ? "nothing" : out;
}

std::string hex_bytes(const std::vector<std::uint8_t>& data) {
  std::string out;
  for (const auto b : data) out += fmt::format("{}{:02X}", out.empty() ? "" : " ", b);
  return out.empty() ? "(no data)" : out;
}

std::string render_table(const can_log& log, const conversation& conv) {
  std::optional<double> t0;
  for (const auto& f : log.frames)
    if (f.time && !t0) t0 = f.time;
  std::string out =
      fmt::format("{:>11}  {:3}  {:5}  {:<34}  {}\n", t0 ? "time" : "line", "dir", "id", "group/message", "meaning");
  for (const auto& d : conv.frames) {
    const auto& f = log.frames[d.frame];
    const auto when = f.time && t0 ? fmt::format("{:+.6f}", *f.time - *t0) : fmt::format("{}", f.line);
    const auto id = f.extended ? fmt::format("{:08X}", f.id) : fmt::format("0x{:03X}", f.id);
    const auto meaning = d.undecodable ? fmt::format("? {} [{}]", d.why, hex_bytes(f.data)) : d.meaning;
    out += fmt::format("{:>11}  {:^3}  {:5}  {:<34}  {}\n", when, d.dir, id, d.label, meaning);
  }
  for (const auto& p : log.problems) out += fmt::format("{:>11}  unreadable line: {}\n", p.line, p.message);
  return out;
}

}  // namespace edsc::verify
