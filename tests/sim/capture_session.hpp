#pragma once
// What the session-capture tests share: tcpdump recording `edsc verify --live
// --connections` against a device in a namespace (`edsc sim` or OpENer), and
// tshark's reading of the same file to hold `edsc verify --capture` to.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "capture/tshark_tools.hpp"
#include "sim_network.hpp"

namespace edsc::sim_test {

using capture::test::run;  // a command's standard output

// tcpdump writes what it read a little after the wire carried it: wait until
// the file stops growing (the Forward_Close was the last thing sent; the
// device produces nothing after it), at most 5 s.
inline void settle(const std::string& pcap) {
  std::error_code ec;
  std::uintmax_t last = 0;
  for (int quiet = 0, i = 0; quiet < 3 && i < 50; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const auto now = std::filesystem::file_size(pcap, ec);
    quiet = !ec && now == last ? quiet + 1 : 0;
    last = now;
  }
}

struct session {
  std::string pcap, eds, verify_output;
  int verify_status = -1;
};

// A device started by `start` (its pid, or -1 with the reason) and tcpdump
// on its interface; the pids of both, or none after saying why.
struct recording {
  session s;
  pid_t device = -1, dump = -1;
};
using device_starter = std::function<pid_t(test_network&, std::string& why)>;
inline std::optional<recording> start_recording(test_network& net, const device_starter& start) {
  recording r;
  std::string why;
  r.device = start(net, why);
  if (r.device <= 0) {
    ADD_FAILURE() << why;
    return std::nullopt;
  }
  r.s.pcap = net.dir + "/session.pcap";
  r.dump = net.capture(r.s.pcap);
  if (r.dump <= 0) {
    ADD_FAILURE() << "tcpdump did not start";
    return std::nullopt;
  }
  return r;
}

// The scanner side, `verify --live --connections`, configured from the EDS
// text `scanner` (the device's own file unless a fault is asked for), while
// tcpdump records; the session with the device's file as `device_eds`.
inline std::optional<session> record(test_network& net, const device_starter& start, const std::string& device_eds,
                                     const std::string& scanner) {
  auto r = start_recording(net, start);
  if (!r) return std::nullopt;
  r->s.eds = device_eds;
  const auto scanner_eds = net.dir + "/scanner.eds";
  std::ofstream(scanner_eds) << scanner;
  const auto v = run_edsc("verify --live " + net.device_ip + " " + quoted(scanner_eds) +
                          " --connections --watch 0.4 --color never");
  r->s.verify_status = v.status;
  r->s.verify_output = v.output;
  settle(r->s.pcap);
  net.stop(r->dump, SIGINT);
  return r->s;
}

// `edsc ARGS` with its standard output alone, and its exit status.
inline std::pair<int, std::string> edsc_stdout(const std::string& args) {
  const auto out = run("timeout -s KILL 120 " + quoted(EDSC_BINARY) + " " + args + " 2>/dev/null; echo \"#exit $?\"");
  const auto at = out.rfind("#exit ");
  if (at == std::string::npos) return {-1, out};
  return {std::stoi(out.substr(at + 6)), out.substr(0, at)};
}

// The frame numbers tshark shows for a display filter, one per line.
inline std::vector<unsigned> tshark_frames(const std::string& pcap, const std::string& filter) {
  std::istringstream lines(
      run("tshark -r " + quoted(pcap) + " -Y " + quoted(filter) + " -T fields -e frame.number 2>/dev/null"));
  std::vector<unsigned> out;
  for (unsigned n; lines >> n;) out.push_back(n);
  return out;
}

// One line of tshark fields (separated by ':') for the frame numbered `frame`.
inline std::string tshark_fields(const std::string& pcap, unsigned frame, const std::string& fields) {
  return run("tshark -r " + quoted(pcap) + " -Y " + quoted("frame.number == " + std::to_string(frame)) +
             " -T fields -E separator=: " + fields + " 2>/dev/null");
}

// One connection of `verify --capture --format json` held to tshark's
// reading of the same file: the Forward_Open's fields, the granted reply's
// connection ids and APIs, and for a granted connection the frames of each
// direction (count, first, last) by connection id. tshark shows serial
// numbers and ids in hex; a Large_Forward_Open's sizes in its own field.
inline void expect_as_tshark(const std::string& pcap, const nlohmann::json& c) {
  const auto request = c["request_frame"].get<unsigned>();
  SCOPED_TRACE(fmt::format("the connection opened at frame {}", request));
  const auto fo = tshark_fields(pcap, request,
                                "-e cip.cm.conn_serial_num -e cip.cm.vendor -e cip.cm.orig_serial_num "
                                "-e cip.cm.timeout_multiplier -e cip.cm.otrpi -e cip.cm.torpi -e cip.cm.fwo.consize");
  EXPECT_EQ(fo,
            fmt::format("0x{:04x}:0x{:04x}:0x{:08x}:{}:{}:{}:{},{}\n", c["serial"].get<unsigned>(),
                        c["originator_vendor"].get<unsigned>(), c["originator_serial"].get<unsigned>(),
                        c["timeout_multiplier"].get<unsigned>(), c["ot_rpi_us"].get<unsigned>(),
                        c["to_rpi_us"].get<unsigned>(), c["ot_size"].get<unsigned>(), c["to_size"].get<unsigned>()));
  const auto reply = c["reply_frame"].get<unsigned>();
  ASSERT_NE(reply, 0U);
  if (c.contains("refused")) {
    // tshark's general status of the reply, in hex.
    EXPECT_EQ(tshark_fields(pcap, reply, "-e cip.genstat"),
              fmt::format("0x{:02x}\n", c["refused"]["general"].get<unsigned>()));
    return;
  }
  EXPECT_EQ(tshark_fields(pcap, reply, "-e cip.cm.ot_connid -e cip.cm.to_connid -e cip.cm.otapi -e cip.cm.toapi"),
            fmt::format("0x{:08x}:0x{:08x}:{}:{}\n", c["ot_connection_id"].get<std::uint32_t>(),
                        c["to_connection_id"].get<std::uint32_t>(), c["ot_api_us"].get<unsigned>(),
                        c["to_api_us"].get<unsigned>()));
  for (const char* dir : {"ot", "to"}) {
    const auto id = c[std::string(dir) + "_connection_id"].get<std::uint32_t>();
    const auto frames = tshark_frames(pcap, "enip.cpf.sai.connid == " + std::to_string(id));
    EXPECT_EQ(frames.size(), c[dir]["frames"].get<std::size_t>()) << dir;
    EXPECT_FALSE(frames.empty()) << dir << ": a granted connection's frames (a heartbeat's too)";
    if (frames.empty()) continue;
    EXPECT_EQ(frames.front(), c[dir]["first_frame"].get<unsigned>()) << dir;
    EXPECT_EQ(frames.back(), c[dir]["last_frame"].get<unsigned>()) << dir;
  }
}

// The Forward_Open request frames of a capture, as tshark finds them
// (Forward_Open 0x54 and Large_Forward_Open 0x5B, requests only).
inline std::vector<unsigned> tshark_forward_opens(const std::string& pcap) {
  return tshark_frames(pcap, "cip.service == 0x54 || cip.service == 0x5b");
}

// The line (1-based) of the first line of `path` holding `text`, or 0.
inline unsigned line_holding(const std::string& path, const std::string& text) {
  std::ifstream in(path);
  unsigned n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.find(text) != std::string::npos) return n;
  }
  return 0;
}

}  // namespace edsc::sim_test
