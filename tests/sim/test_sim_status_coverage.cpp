// Every status edsc names — the encapsulation, general and extended
// statuses of compiler/cip/codes.def — has a row here: either a
// request written by hand that makes `edsc sim` (on OpENer's EDS) answer
// exactly that status, or the reason the simulator never sends it. A status
// the simulator's sources name must have a request; a status a row says is
// never sent must not appear in them. So a branch that produces a status
// cannot fall out of the suite unnoticed, and a new status in the table or
// in the simulator fails here until it has its row.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "netns/raw_forward_open.hpp"
#include "sim_wire.hpp"

namespace edsc::sim_test {
namespace {

namespace fs = std::filesystem;
using raw::bytes;
using raw::hex;

enum class layer { encap, general, extended };
const char* layer_name(layer l) {
  return l == layer::encap ? "encapsulation" : l == layer::general ? "general" : "extended";
}

// What the device answered at the layer a row is about; nullopt: no answer.
using scenario = std::function<std::optional<unsigned>(const std::string& ip)>;

struct row {
  layer kind;
  unsigned code;
  scenario produce;  // empty: never sent, for `reason`
  const char* reason = "";
};

// --- requests -------------------------------------------------------------

std::optional<unsigned> encap_status(const std::string& ip, const bytes& message, bool register_first = true) {
  auto t = raw::tcp::connect(ip);
  if (!t) return std::nullopt;
  std::uint32_t handle = 0;
  if (register_first) {
    const auto r = t->exchange(raw::register_session());
    if (!r) return std::nullopt;
    handle = raw::le32(*r, 4);
  }
  auto m = message;
  if (register_first && m.size() >= 8 && raw::le32(m, 4) == 0xFFFFFFFF) {  // "the session": filled in here
    m[4] = handle & 0xFF, m[5] = handle >> 8 & 0xFF, m[6] = handle >> 16 & 0xFF, m[7] = handle >> 24;
  }
  const auto r = t->exchange(m);
  if (!r) return std::nullopt;
  return raw::le32(*r, 8);
}

std::optional<raw::cip_reply> ask(const std::string& ip, const bytes& request) {
  auto s = raw::session::open(ip);
  if (!s) return std::nullopt;
  return s->ask(request);
}
std::optional<unsigned> general_of(const std::optional<raw::cip_reply>& r) {
  if (!r) return std::nullopt;
  return r->general;
}
// The extended status of a refused Forward_Open (0 when it was not general 0x01).
std::optional<unsigned> extended_of(const std::optional<raw::cip_reply>& r) {
  if (!r) return std::nullopt;
  return r->general == 0x01 ? raw::extended(*r) : 0u;
}
scenario general_for(const char* request) {
  return [request](const std::string& ip) { return general_of(ask(ip, hex(request))); };
}

// Connection1 of OpENer's EDS changed by `edit`, on a session of its own
// (the connection, if the device grants it, is closed again).
scenario connection1_with(std::uint16_t serial, std::function<void(raw::forward_open_fields&)> edit) {
  return [serial, edit](const std::string& ip) -> std::optional<unsigned> {
    auto s = raw::session::open(ip);
    if (!s) return std::nullopt;
    auto f = raw::opener_connection1(serial);
    edit(f);
    const auto r = s->ask(raw::forward_open(f));
    if (r && r->general == 0) (void)s->ask(raw::forward_close(serial, hex(raw::opener_owner_path)));
    return extended_of(r);
  };
}

bytes with_path(const bytes& key, const char* app) { return raw::cat({key, hex(app)}); }

// Two Forward_Opens on one session: the answer to the second.
std::optional<unsigned> second_of_two(const std::string& ip, const raw::forward_open_fields& first,
                                      const raw::forward_open_fields& second) {
  auto s = raw::session::open(ip);
  if (!s) return std::nullopt;
  const auto a = s->ask(raw::forward_open(first));
  if (!a || a->general != 0) return std::nullopt;
  const auto b = s->ask(raw::forward_open(second));
  (void)s->ask(raw::forward_close(first.serial, hex(raw::opener_owner_path)));
  return extended_of(b);
}

// Class 3 connections to the Message Router until the device has none
// left: the status of the first it refuses. Each is closed again.
std::optional<unsigned> out_of_connections(const std::string& ip) {
  auto s = raw::session::open(ip);
  if (!s) return std::nullopt;
  std::optional<unsigned> refused;
  std::vector<std::uint16_t> opened;
  for (std::uint16_t serial = 0x3000; serial < 0x3000 + 300 && !refused; ++serial) {
    raw::forward_open_fields f;
    f.serial = serial;
    f.transport = 0xA3;  // server, application trigger, class 3
    f.ot_rpi = f.to_rpi = 10'000'000;
    f.ot_params = f.to_params = raw::params16(500);
    f.path = hex("20 02 24 01");
    const auto r = s->ask(raw::forward_open(f));
    if (!r) return std::nullopt;
    if (r->general == 0)
      opened.push_back(serial);
    else
      refused = extended_of(r);
  }
  for (const auto serial : opened) (void)s->ask(raw::forward_close(serial, hex("20 02 24 01")));
  return refused;
}

std::optional<unsigned> upload_transfer_out_of_turn(const std::string& ip, bool initiate) {
  auto s = raw::session::open(ip);
  if (!s) return std::nullopt;
  if (initiate) {
    const auto i = s->ask(hex("4B 02 20 37 24 C8 F0"));  // Initiate_Upload, transfer size 240
    if (!i || i->general != 0) return std::nullopt;
  }
  return general_of(s->ask(hex("4F 02 20 37 24 C8 05")));  // Upload_Transfer number 5
}

// --- the rows ---------------------------------------------------------------

const char* const unserved_services =
    "the simulator serves Get/Set_Attribute_Single, Get_Attributes_All, the Connection Manager's and the File "
    "object's services; a service it does not serve (list services, Multiple_Service_Packet, Unconnected_Send, "
    "Reset, save and restore, member access) gets 0x08 instead of anything that service would say";
const char* const scheduled_networks =
    "a status of scheduled or bridged networks (ControlNet, a chassis backplane): the simulator is one "
    "EtherNet/IP target and routes nothing";
const char* const routing = "the simulator is a target, not a router: it serves no Unconnected_Send";

std::vector<row> rows() {
  using L = layer;
  std::vector<row> r = {
      // Encapsulation (answered in the header's status field).
      {L::encap, 0x0000, [](const std::string& ip) { return encap_status(ip, raw::register_session(), false); }},
      {L::encap, 0x0001,
       [](const std::string& ip) { return encap_status(ip, raw::encap(0x0099, 0xFFFFFFFF, {})); }},  // unknown command
      {L::encap,
       0x0002,
       {},
       "the simulator never runs out of memory for a request: a 65th TCP client is not accepted, and a "
       "Forward_Open beyond its 256 connections is refused with 0x01/0x0113"},
      {L::encap, 0x0003,
       [](const std::string& ip) {  // SendRRData whose CPF lacks the unconnected data item
         return encap_status(ip, raw::encap(0x006F, 0xFFFFFFFF, hex("00 00 00 00 00 00 01 00 00 00 00 00")));
       }},
      {L::encap, 0x0064,
       [](const std::string& ip) {
         return encap_status(ip, raw::send_rr_data(0x0BADF00D, hex("0E 03 20 01 24 01 30 01")));
       }},
      {L::encap, 0x0065,
       [](const std::string& ip) {  // RegisterSession with 6 bytes of data
         return encap_status(ip, raw::encap(0x0065, 0, hex("01 00 00 00 00 00")), false);
       }},
      {L::encap, 0x0069,
       [](const std::string& ip) {  // RegisterSession, protocol version 2
         return encap_status(ip, raw::encap(0x0065, 0, hex("02 00 00 00")), false);
       }},

      // General status.
      {L::general, 0x00, general_for("0E 03 20 01 24 01 30 01")},
      {L::general, 0x01, [](const std::string& ip) { return general_of(ask(ip, raw::forward_close(0x7777, {}))); }},
      {L::general,
       0x02,
       {},
       "its limits are answered otherwise: a 65th TCP client is not accepted, a 257th connection gets 0x01/0x0113"},
      {L::general, 0x03, {}, "a value out of range is 0x09 (attribute) or 0x20 (service parameter) here"},
      {L::general, 0x04, general_for("0E 02 52 00 20 01")},        // a network segment where the path should be
      {L::general, 0x05, general_for("0E 03 20 99 24 01 30 01")},  // class 0x99
      {L::general, 0x06, {}, unserved_services},
      {L::general,
       0x07,
       {},
       "a class 3 request on a connection that is not open is dropped without a reply, as a device drops a "
       "frame it has no connection for"},
      {L::general, 0x08, general_for("33 02 20 06 24 01")},                    // service 0x33 to the Connection Manager
      {L::general, 0x09, general_for("10 03 20 0F 24 04 30 01 05 00 00 00")},  // Param4 (RPI) = 5 < its minimum
      {L::general, 0x0A, {}, unserved_services},
      {L::general, 0x0B, {}, unserved_services},
      {L::general, 0x0C, [](const std::string& ip) { return upload_transfer_out_of_turn(ip, false); }},
      {L::general, 0x0D, {}, "the simulator serves no Create service: no object is made by a request"},
      {L::general, 0x0E, general_for("10 03 20 01 24 01 30 01 02 00")},  // Set Identity vendor
      {L::general, 0x0F, {}, "the simulator has no access control: every request any session sends is served"},
      {L::general, 0x10, {}, "the simulated device is always operational: it has no state that refuses a request"},
      {L::general,
       0x11,
       {},
       "the replies the simulator builds hold one attribute or one object; none exceeds what its answer carries "
       "for the EDS files it serves"},
      {L::general, 0x12, {}, unserved_services},
      {L::general, 0x13, general_for("10 03 20 04 24 96 30 03 01 02")},  // 2 bytes for Assem150's 32
      {L::general, 0x14, general_for("0E 03 20 01 24 01 30 63")},        // Identity attribute 0x63
      {L::general, 0x15,
       [](const std::string& ip) {  // 33 bytes for Assem150's 32
         return general_of(ask(ip, raw::cat({hex("10 03 20 04 24 96 30 03"), bytes(33, 1)})));
       }},
      {L::general, 0x16, general_for("0E 03 20 0F 24 63 30 01")},  // Parameter instance 99
      {L::general, 0x17, {}, unserved_services},
      {L::general, 0x18, {}, unserved_services},
      {L::general, 0x19, {}, unserved_services},
      {L::general, 0x1A, {}, routing},
      {L::general, 0x1B, {}, routing},
      {L::general, 0x1C, {}, unserved_services},
      {L::general, 0x1D, {}, unserved_services},
      {L::general, 0x1E, {}, unserved_services},
      {L::general, 0x1F, {}, "the simulator has no vendor-specific error"},
      {L::general, 0x20, [](const std::string& ip) { return upload_transfer_out_of_turn(ip, true); }},
      {L::general, 0x21, {}, unserved_services},
      {L::general, 0x22, {}, routing},
      {L::general,
       0x25,
       {},
       "a key that does not fit refuses a Forward_Open with 0x01 and 0x0114-0x0116 (as OpENer answers); a key "
       "in an explicit request's path is a path segment error, 0x04"},
      {L::general, 0x26, {}, "a path size that runs past the request is a path segment error here, 0x04"},
      {L::general, 0x27, {}, unserved_services},
      {L::general, 0x28, {}, unserved_services},
      {L::general, 0x29, {}, unserved_services},

      // Extended status (general 0x01) of Forward_Open and Forward_Close.
      {L::extended, 0x0100,
       [](const std::string& ip) {  // the same connection triple twice
         const auto f = raw::opener_connection1(0x5100);
         return second_of_two(ip, f, f);
       }},
      {L::extended, 0x0103, connection1_with(0x5103, [](auto& f) { f.transport = 0x11; })},  // change of state
      {L::extended, 0x0106,
       [](const std::string& ip) {  // a second exclusive owner of Assem150
         return second_of_two(ip, raw::opener_connection1(0x5106), raw::opener_connection1(0x5107));
       }},
      {L::extended, 0x0107,
       [](const std::string& ip) {
         return extended_of(ask(ip, raw::forward_close(0x7777, hex(raw::opener_owner_path))));
       }},
      {L::extended,
       0x0108,
       {},
       "network connection parameters are read field by field: a wrong field has its own status"},
      {L::extended, 0x0109,
       connection1_with(0x5109, [](auto& f) { f.ot_params = raw::params16(38, raw::point_to_point, true); })},
      {L::extended, 0x0110, {}, "every connection point the EDS describes is served; none waits for configuration"},
      {L::extended, 0x0111, connection1_with(0x5111, [](auto& f) { f.ot_rpi = 1000; })},  // below Param4's 20000
      {L::extended,
       0x0112,
       {},
       "an RPI outside the limits is 0x0111 here, as docs/sim.md says; no acceptable RPI is offered"},
      {L::extended, 0x0113, out_of_connections},
      {L::extended, 0x0114,
       connection1_with(0x5114,
                        [](auto& f) { f.path = with_path(raw::key(1, 12, 65002, 2, 3), raw::opener_owner_path); })},
      {L::extended, 0x0115,
       connection1_with(0x5115,
                        [](auto& f) { f.path = with_path(raw::key(1, 13, 65001, 2, 3), raw::opener_owner_path); })},
      {L::extended, 0x0116,
       connection1_with(0x5116,
                        [](auto& f) { f.path = with_path(raw::key(1, 12, 65001, 3, 3), raw::opener_owner_path); })},
      {L::extended, 0x0117, {}, "a path that names no ConnectionN is 0x012F here, as OpENer answers"},
      {L::extended, 0x0118, {}, "a path that names no ConnectionN is 0x012F here, as OpENer answers"},
      {L::extended, 0x0119,
       connection1_with(0x5119,
                        [](auto& f) {  // listen-only (Connection3), no owner open
                          f.path = with_path(raw::opener_key(), raw::opener_listen_only_path);
                          f.ot_params = raw::params16(2);
                          f.to_params = raw::params16(34, raw::multicast);
                        })},
      {L::extended, 0x011A, {}, "the simulator's one limit on connections is the Connection Manager's, 0x0113"},
      {L::extended, 0x011B, {}, "the simulator has no production inhibit time"},
      {L::extended, 0x011C, connection1_with(0x511C, [](auto& f) { f.transport = 0x02; })},  // class 2
      {L::extended,
       0x011D,
       {},
       "class and trigger are judged together, 0x0103, as the EDS's transport field lists them"},
      {L::extended, 0x011E, {}, "the direction bit of the transport byte is not read"},
      {L::extended, 0x011F, {}, "a size kind the EDS does not allow is 0x0109, in either direction"},
      {L::extended, 0x0120, {}, "a size kind the EDS does not allow is 0x0109, in either direction"},
      {L::extended, 0x0121, {}, "priorities are not checked: every priority is accepted"},
      {L::extended, 0x0122, {}, "priorities are not checked: every priority is accepted"},
      {L::extended, 0x0123, connection1_with(0x5123, [](auto& f) { f.ot_params = raw::params16(38, raw::multicast); })},
      {L::extended, 0x0124,
       connection1_with(0x5124,
                        [](auto& f) {  // listen-only asked point-to-point
                          f.path = with_path(raw::opener_key(), raw::opener_listen_only_path);
                          f.ot_params = raw::params16(2);
                          f.to_params = raw::params16(34);
                        })},
      {L::extended, 0x0125, {}, "the redundant owner bit is not read: every connection has one owner"},
      {L::extended, 0x0126,
       connection1_with(0x5126,
                        [](auto& f) {  // 12 bytes of configuration for Assem151's 10
                          f.path = raw::cat({f.path, hex("80 06"), bytes(12, 0)});
                        })},
      {L::extended, 0x0127, connection1_with(0x5127, [](auto& f) { f.ot_params = raw::params16(39); })},
      {L::extended, 0x0128, connection1_with(0x5128, [](auto& f) { f.to_params = raw::params16(33); })},
      {L::extended,
       0x0129,
       {},
       "configuration data of the wrong length is 0x0126 here; the configuration path is 0x012F"},
      {L::extended, 0x012A, {}, "a path that names no ConnectionN is 0x012F here, as OpENer answers"},
      {L::extended, 0x012B, {}, "a path that names no ConnectionN is 0x012F here, as OpENer answers"},
      {L::extended, 0x012C, {}, "a symbolic connection path names no ConnectionN the simulator serves: 0x012F"},
      {L::extended, 0x012D, {}, "a symbolic connection path names no ConnectionN the simulator serves: 0x012F"},
      {L::extended, 0x012E, {}, "a symbolic connection path names no ConnectionN the simulator serves: 0x012F"},
      {L::extended, 0x012F,
       connection1_with(0x512F,
                        [](auto& f) {
                          f.path =
                              with_path(raw::opener_key(), "20 04 24 97 2C 96 2C 65");  // T->O 101: the EDS has 100
                        })},
      {L::extended, 0x0130, {}, "data formats are not checked beyond the sizes, 0x0127 and 0x0128"},
      {L::extended, 0x0131, {}, "data formats are not checked beyond the sizes, 0x0127 and 0x0128"},
      {L::extended, 0x0132, {}, "a null Forward_Open is held to the connection types the EDS lists: 0x0123"},
      {L::extended, 0x0133, {}, "every timeout multiplier is accepted (above 7 it counts as 7)"},
      {L::extended,
       0x0203,
       {},
       "a connection that times out is closed and logged (\"timeout\"); no request is answered with it, a later "
       "Forward_Close gets 0x0107"},
      {L::extended, 0x0204, {}, routing},
      {L::extended, 0x0205, {}, routing},
      {L::extended, 0x0206, {}, routing},
      {L::extended, 0x0207, {}, routing},
      {L::extended, 0x0301, {}, "the simulator's one limit on connections is the Connection Manager's, 0x0113"},
      {L::extended, 0x0302, {}, "the simulator does not budget bandwidth"},
      {L::extended, 0x0303, {}, "the simulator's one limit on connections is the Connection Manager's, 0x0113"},
      {L::extended, 0x0304, {}, scheduled_networks},
      {L::extended, 0x0305, {}, scheduled_networks},
      {L::extended, 0x0306, {}, scheduled_networks},
      {L::extended, 0x0311, {}, routing},
      {L::extended, 0x0312, {}, routing},
      {L::extended, 0x0315,
       connection1_with(0x5315,
                        [](auto& f) {  // a network segment in the path
                          f.path = raw::cat({raw::opener_key(), hex("52 00"), hex(raw::opener_owner_path)});
                        })},
      {L::extended, 0x0316, {}, "Forward_Close finds the connection by its triple; the path it carries is not read"},
      {L::extended, 0x0317, {}, scheduled_networks},
      {L::extended, 0x0318, {}, routing},
      {L::extended, 0x0319, {}, scheduled_networks},
      {L::extended, 0x031A, {}, scheduled_networks},
      {L::extended, 0x031B, {}, scheduled_networks},
      {L::extended, 0x031C, {}, "every refusal has a status of its own; none is \"miscellaneous\""},
      {L::extended, 0x031D, {}, "the redundant owner bit is not read: every connection has one owner"},
      {L::extended, 0x031E, {}, scheduled_networks},
      {L::extended, 0x031F, {}, scheduled_networks},
      {L::extended, 0x0800, {}, scheduled_networks},
      {L::extended, 0x0810, {}, scheduled_networks},
      {L::extended, 0x0811, {}, scheduled_networks},
      {L::extended, 0x0812, {}, scheduled_networks},
      {L::extended, 0x0813, {}, "the simulator joins and sends to no multicast group (docs/sim.md)"},
  };
  return r;
}

// --- the tables the rows are held to ----------------------------------------

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A status of cip/codes.def: its code and its enumerator's name.
struct named_status {
  unsigned code;
  std::string symbol;
};

std::map<layer, std::vector<named_status>> codes_def() {
  std::map<layer, std::vector<named_status>> all;
#define ENCAP_STATUS(sym, code, words) all[layer::encap].push_back({code, #sym});
#define GENERAL_STATUS(sym, code, words, ...) all[layer::general].push_back({code, #sym});
#define EXTENDED_STATUS(sym, code, words, ...) all[layer::extended].push_back({code, #sym});
#include "cip/codes.def"
#undef ENCAP_STATUS
#undef GENERAL_STATUS
#undef EXTENDED_STATUS
  return all;
}

// Every source of the simulator, as one text.
// compiler/sim, and the checks of what the EDS alone decides, which the
// simulator refuses by (and the capture judge explains by).
std::string simulator_sources() {
  const fs::path compiler = fs::path(EDSC_PROJECT_DIR) / "compiler";
  std::string all;
  for (const auto& e : fs::recursive_directory_iterator(compiler / "sim"))
    if (e.is_regular_file()) all += read(e.path()) + "\n";
  for (const char* shared : {"forward_open_fit.hpp", "forward_open_fit.cpp"})
    all += read(compiler / "connections" / shared) + "\n";
  return all;
}

// Whether the simulator's sources name a status by its enumerator, through
// the enum or the alias the simulator gives it (sim/objects.hpp: general,
// connections/forward_open_fit.hpp: ext, sim/encap.cpp: status).
bool named_by_simulator(const std::string& sources, layer kind, const std::string& symbol) {
  const std::vector<std::string> scopes = kind == layer::encap ? std::vector<std::string>{"encap_status", "status"}
                                          : kind == layer::general
                                              ? std::vector<std::string>{"general_status", "general"}
                                              : std::vector<std::string>{"extended_status", "ext"};
  for (const auto& scope : scopes) {
    const std::regex use("\\b" + scope + "::" + symbol + "\\b");
    if (std::regex_search(sources, use)) return true;
  }
  return false;
}

std::string four_digits(unsigned code) { return fmt::format("0x{:04X}", code); }

TEST(sim_status_coverage, every_named_status_has_a_row_and_every_row_is_honest) {
  const auto table = codes_def();
  std::map<layer, std::set<unsigned>> named;
  std::map<std::pair<layer, unsigned>, std::string> symbol;
  for (const auto& [kind, statuses] : table)
    for (const auto& st : statuses) {
      named[kind].insert(st.code);
      symbol[{kind, st.code}] = st.symbol;
    }
  for (const auto kind : {layer::encap, layer::general, layer::extended})
    ASSERT_GT(named[kind].size(), 5u) << "cip/codes.def: too few " << layer_name(kind) << " statuses read";
  std::map<layer, std::set<unsigned>> have;
  for (const auto& r : rows()) {
    EXPECT_TRUE(have[r.kind].insert(r.code).second) << layer_name(r.kind) << " " << four_digits(r.code) << " twice";
    EXPECT_TRUE(named.at(r.kind).count(r.code))
        << layer_name(r.kind) << " " << four_digits(r.code) << " has a row but is not in cip/codes.def";
    EXPECT_NE(static_cast<bool>(r.produce), *r.reason != 0)
        << four_digits(r.code) << ": a row has a request or a reason, not both or neither";
  }
  for (const auto& [kind, codes] : named)
    for (const auto c : codes)
      EXPECT_TRUE(have[kind].count(c)) << layer_name(kind) << " status " << four_digits(c)
                                       << " of cip/codes.def has no row: a request that produces it, or why none does";

  // What the simulator's sources name must be produced; what a row says is never sent, they must not name.
  const auto sources = simulator_sources();
  for (const auto& r : rows()) {
    const auto sym = symbol.find({r.kind, r.code});
    const bool named_by_sim = sym != symbol.end() && named_by_simulator(sources, r.kind, sym->second);
    if (r.code == 0) continue;  // success needs no name
    if (named_by_sim) {
      EXPECT_TRUE(r.produce) << layer_name(r.kind) << " " << four_digits(r.code)
                             << " is named by the simulator but its row gives no request: " << r.reason;
    } else {
      EXPECT_FALSE(r.produce) << layer_name(r.kind) << " " << four_digits(r.code)
                              << " is produced here but the simulator's sources do not name it";
    }
  }
}

TEST(sim_status_coverage, every_status_the_simulator_sends_is_produced_by_its_request) {
  auto sim = running_sim::start(opener_eds_path);
  if (!sim.net) GTEST_SKIP() << sim.why;
  ASSERT_TRUE(sim.running()) << sim.why;
  int produced = 0;
  for (const auto& r : rows()) {
    if (!r.produce) continue;
    SCOPED_TRACE(fmt::format("{} status {}", layer_name(r.kind), four_digits(r.code)));
    const auto got = r.produce(sim.ip());
    ASSERT_TRUE(got) << "no answer";
    EXPECT_EQ(four_digits(*got), four_digits(r.code));
    ++produced;
  }
  std::printf("%d statuses produced by hand-written requests\n", produced);
  // Every Forward_Open refused was logged with the status sent (Forward_Close refusals are not logged).
  const auto text = sim.stop();
  for (const auto& r : rows()) {
    if (r.produce && r.kind == layer::extended && r.code != 0x0107) {
      EXPECT_NE(text.find("\"status\":\"0x01\",\"extended\":\"" + four_digits(r.code) + "\""), std::string::npos)
          << four_digits(r.code) << " was sent but not logged";
    }
  }
  EXPECT_NE(text.find("\"event\":\"stopped\""), std::string::npos) << text;
}

}  // namespace
}  // namespace edsc::sim_test
