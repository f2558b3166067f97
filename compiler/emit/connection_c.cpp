// `edsc connection --format c`: a C header for an originator of one's own
// (a scanner on a microcontroller): per ConnectionN the whole Forward_Open
// request as bytes, the offsets of the fields the originator fills in, and a
// struct of the settings. Every text from the EDS goes through comment_text
// or c_string_literal (facts/c_text.hpp).
#include <fmt/format.h>

#include "connections/summary.hpp"
#include "emit/connection_render.hpp"
#include "facts/c_text.hpp"

namespace edsc::emit {

namespace {

using namespace connections;

std::string byte_rows(const cip::bytes& b) {
  std::string out;
  for (std::size_t i = 0; i < b.size(); ++i)
    out += fmt::format("{}0x{:02X},", i % 12 == 0 ? (i == 0 ? "    " : "\n    ") : " ", b[i]);
  return out;
}

std::string array(std::string_view name, const cip::bytes& b) {
  if (b.empty()) return fmt::format("/* {}: none */\n", name);
  return fmt::format("static const uint8_t {}[{}] = {{\n{}\n}};\n", name, b.size(), byte_rows(b));
}

std::string direction_fields(std::string_view dir, const direction_setting& d, bool large) {
  const std::uint32_t params = large ? d.word32 : d.word16.value_or(0);
  return fmt::format(
      "    .{0}_rpi_us = {1}u,\n"
      "    .{0}_data_size = {2}u,\n"
      "    .{0}_wire_size = {3}u, /* {4} */\n"
      "    .{0}_params = 0x{5:0{6}X}u, /* {7} network connection parameters */\n"
      "    .{0}_instance = {8}u,\n"
      "    .{0}_run_idle = {9}u,\n",
      dir, d.rpi.asked_us, d.data_size, d.asked.size,
      !d.used ? std::string("null connection")
              : fmt::format("data{}{}", d.sequence ? " + 2 sequence" : "", d.run_idle ? " + 4 run/idle" : ""),
      params, large ? 8 : 4, large ? "32-bit Large_Forward_Open" : "16-bit Forward_Open", d.instance,
      d.run_idle ? 1 : 0);
}

void one_c(std::string& out, const connection_setting& s, const source_file& src) {
  const auto n = s.number;
  const auto words = summarize(s);
  out += fmt::format("\n/* Connection{} \"{}\" (line {}): {}; {} */\n", n, comment_text(s.name),
                     src.position(s.at.begin).line, comment_text(words.kind), comment_text(words.transport));
  if (s.request.empty()) {
    out += fmt::format("/* no request: {} */\n", comment_text(s.cannot_express));
    return;
  }
  if (!words.owner_label.empty())
    out += fmt::format("/* {} {} */\n", comment_text(words.owner_label), comment_text(words.owners));
  out += array(fmt::format("edsc_connection{}_request", n), s.request);
  out += array(fmt::format("edsc_connection{}_path", n), s.connection_path);
  out += array(fmt::format("edsc_connection{}_config", n), s.config_data);
  out += fmt::format("static const struct edsc_connection edsc_connection{} = {{\n", n);
  out += fmt::format("    .number = {}u,\n    .name = {},\n    .large = {}u,\n    .transport = 0x{:02X}u,\n", n,
                     c_string_literal(s.name), s.large ? 1 : 0, s.transport);
  out += direction_fields("ot", s.ot, s.large);
  out += direction_fields("to", s.to, s.large);
  out += fmt::format("    .config_instance = {}u,\n", s.config_instance);
  const auto ptr = [&](std::string_view what, const cip::bytes& b) {
    return b.empty() ? std::string("0") : fmt::format("edsc_connection{}_{}", n, what);
  };
  out +=
      fmt::format("    .config = {},\n    .config_size = {}u,\n", ptr("config", s.config_data), s.config_data.size());
  out +=
      fmt::format("    .path = {},\n    .path_size = {}u,\n", ptr("path", s.connection_path), s.connection_path.size());
  out +=
      fmt::format("    .request = {},\n    .request_size = {}u,\n}};\n", ptr("request", s.request), s.request.size());
}

// The request as cip::encode_forward_open lays it out: service, path size,
// the path to the Connection Manager (20 06 24 01), then the request data
// (ETHERNETIP_LIVE.md §4): offsets from the first byte of the request.
constexpr std::string_view preamble = R"(#include <stdint.h>

/* The Forward_Open (service 0x54) or Large_Forward_Open (0x5B) request,
   addressed to the Connection Manager: send it in SendRRData (inside an
   Unconnected_Send when routed). The originator fills in, little-endian: */
#define EDSC_FO_OT_CONNECTION_ID 8 /* UDINT, 0: the target chooses */
#define EDSC_FO_TO_CONNECTION_ID 12 /* UDINT, the originator's choice */
#define EDSC_FO_CONNECTION_SERIAL 16 /* UINT, unique per originator */
#define EDSC_FO_ORIGINATOR_VENDOR 18 /* UINT, the originator's vendor id */
#define EDSC_FO_ORIGINATOR_SERIAL 20 /* UDINT, the originator's serial number */
#define EDSC_FO_TIMEOUT_MULTIPLIER 24 /* USINT, 2: 16 times the RPI */

struct edsc_connection {
    uint32_t number; /* N of ConnectionN */
    const char *name;
    uint8_t large; /* 1: Large_Forward_Open, the 32-bit parameter words */
    uint8_t transport; /* transport type/trigger byte */
    uint32_t ot_rpi_us;
    uint16_t ot_data_size;
    uint16_t ot_wire_size; /* the size in the parameters: data and headers */
    uint32_t ot_params;
    uint32_t ot_instance;
    uint8_t ot_run_idle; /* 1: O->T frames carry the 32-bit run/idle header */
    uint32_t to_rpi_us;
    uint16_t to_data_size;
    uint16_t to_wire_size;
    uint32_t to_params;
    uint32_t to_instance;
    uint8_t to_run_idle;
    uint32_t config_instance; /* 0: none */
    const uint8_t *config; /* the configuration data, also inside path */
    uint16_t config_size;
    const uint8_t *path; /* the request's connection path: key, application path, data */
    uint16_t path_size;
    const uint8_t *request;
    uint16_t request_size;
};
)";

}  // namespace

std::string render_connections_c(const std::vector<connection_setting>& all, const source_file& src) {
  const auto guard = "EDSC_CONNECTIONS_" + upper_snake(src.path().substr(src.path().find_last_of('/') + 1));
  std::string out = fmt::format(
      "/* The connections of {} as an originator sends them.\n"
      "   Generated by edsc connection --format c; regenerate rather than edit. */\n"
      "#ifndef {}\n#define {}\n\n",
      comment_text(src.path()), guard, guard);
  out += preamble;
  for (const auto& s : all) one_c(out, s, src);
  out += fmt::format("\n#endif /* {} */\n", guard);
  return out;
}

}  // namespace edsc::emit
