// A device that accepts every connection but produces frames that are wrong:
// 16 data bytes where the EDS says 32, every 50 ms where it granted 10 ms.
// OpENer never does this (it checks sizes at Forward_Open), so a loopback
// stand-in shows that edsc judges the frames themselves (live-io-frames,
// live-io-rate). The stand-in answers only what verify --live asks.
#include <gtest/gtest.h>

#include <signal.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cip/device_reply.hpp"
#include "cip/encap.hpp"
#include "cip/io_frame.hpp"
#include "loopback_server.hpp"
#include "netns/live_support.hpp"
#include "netns/run_edsc.hpp"
#include "test_paths.hpp"

namespace edsc::live_test {
namespace {

// Sends T->O frames of 16 bytes to 127.0.0.1:2222 every 50 ms while `on`.
class frame_sender {
 public:
  explicit frame_sender(std::uint32_t connection_id) : id_(connection_id) {
    thread_ = std::thread([this] { run(); });
  }
  ~frame_sender() {
    on_ = false;
    thread_.join();
  }

 private:
  void run() {
    const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(2222);
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    std::uint32_t n = 0;
    while (on_) {
      cip::io_frame f{id_, ++n, static_cast<std::uint16_t>(n), std::nullopt, cip::bytes(16, 0xAB)};
      const auto b = cip::encode_io_frame(f).value();
      ::sendto(s, b.data(), b.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ::close(s);
  }
  std::uint32_t id_;
  std::atomic<bool> on_{true};
  std::thread thread_;
};

cip::bytes cip_reply(std::uint8_t service, const cip::bytes& data, std::uint8_t general = 0) {
  cip::bytes r;
  cip::put_u8(r, static_cast<std::uint8_t>(service | 0x80));
  cip::put_u8(r, 0);
  cip::put_u8(r, general);
  cip::put_u8(r, 0);
  for (const auto c : data) r.push_back(c);  // (put_bytes trips GCC 12's -Wstringop-overread on {} here)
  return r;
}

// How the stand-in departs from OpENer besides its frames.
struct quirks {
  bool one_byte_sizes = false;         // an Assembly size in one byte where it takes two
  std::uint16_t open_refused = 0;      // Forward_Open refused: 0x01 with this extended status
  bool close_refused = false;          // Forward_Close refused: 0x01
  bool silent_io = false;              // no T->O frame at all
  bool hang_up_at_close = false;       // the session ends at the Forward_Close, unanswered
  std::uint8_t missing_instance = 0;   // Assembly attribute 4 of it: 0x05 path destination unknown
  bool no_assembly_class = false;      // the class (instance 0) answers 0x05 too
  std::atomic<int>* opened = nullptr;  // counts the connections granted
  std::atomic<int>* closed = nullptr;  // counts the Forward_Closes received
};

// One client's requests, answered as OpENer would, but for the frames and `q`.
void fake_device(int s, const std::atomic<bool>& stop, quirks q) {
  std::unique_ptr<frame_sender> sender;
  std::uint32_t next_id = 0x22220001;
  for (;;) {
    const auto req = read_message(s, stop);
    if (req.size() < cip::encap_header_size) return;
    const auto command = static_cast<std::uint16_t>(req[0] | (req[1] << 8));
    if (command == 0x0065) {
      send_bytes(s, reply_to(req, 0x0065, 0x1234, {1, 0, 0, 0}));
      continue;
    }
    if (command != 0x006F || req.size() < 24 + 16 + 2) return;
    // SendRRData: handle, timeout, 2 items, null address, unconnected data header, then the request.
    const cip::bytes request(req.begin() + 24 + 16, req.end());
    const auto service = request[0];
    const std::size_t data_at = 2 + 2u * request[1];
    cip::bytes answer;
    if (service == 0x01) {  // Identity attributes 1-7 of OpENer
      answer = cip_reply(service, unhex("01 00 0C 00 E9 FD 02 03 30 00 15 CD 5B 07 09 4F 70 45 4E 65 72 20 50 43"));
    } else if (service == 0x0E && request.size() >= 6) {  // Assembly attribute 4 (and the class's Max Instance)
      const auto instance = request[5];
      const std::uint8_t size = instance == 151 ? 10 : 32;
      if ((instance != 0 && instance == q.missing_instance) || (instance == 0 && q.no_assembly_class))
        answer = cip_reply(service, {}, 0x05);
      else
        answer = cip_reply(service, q.one_byte_sizes ? cip::bytes{size} : cip::bytes{size, 0});
    } else if (service == 0x54 && q.open_refused != 0) {
      answer = {static_cast<std::uint8_t>(service | 0x80), 0, 0x01, 1};
      cip::put_u16(answer, q.open_refused);
    } else if (service == 0x54 && request.size() >= data_at + 18) {  // Forward_Open: granted, API 10 ms
      cip::bytes d;
      cip::put_u32(d, next_id + 0x100);
      cip::put_u32(d, next_id);
      d.insert(d.end(), request.begin() + static_cast<long>(data_at) + 10,
               request.begin() + static_cast<long>(data_at) + 18);
      cip::put_u32(d, 10000);
      cip::put_u32(d, 10000);
      cip::put_u16(d, 0);
      if (!q.silent_io) sender = std::make_unique<frame_sender>(next_id);
      ++next_id;
      if (q.opened) ++*q.opened;
      answer = cip_reply(service, d);
    } else if (service == 0x4E && q.hang_up_at_close) {
      return;
    } else if (service == 0x4E && q.close_refused) {
      sender.reset();
      answer = cip_reply(service, {}, 0x01);
    } else if (service == 0x4E && request.size() >= data_at + 10) {  // Forward_Close
      sender.reset();
      if (q.closed) ++*q.closed;
      cip::bytes d(request.begin() + static_cast<long>(data_at) + 2, request.begin() + static_cast<long>(data_at) + 10);
      cip::put_u16(d, 0);
      answer = cip_reply(service, d);
    } else {
      answer = cip_reply(service, {}, 0x08);  // service not supported
    }
    send_bytes(s, reply_to(req, 0x006F, 0x1234, cip::send_rr_data(answer, 0).value()));
  }
}

class live_fake_device : public loopback_test {};

TEST_F(live_fake_device, wrong_frames_are_found_at_the_connection) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {}); });
  const auto eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
  const auto r = run_edsc("verify --live " + device.address() + " " + quoted(eds) + " --connections --color never");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("T->O frames carry 16 data bytes, the EDS says 32 [live-io-frames]"), std::string::npos)
      << r.output;
  // 50 ms between frames against 10 ms granted: slower than twice the interval, however slow this host is.
  EXPECT_NE(r.output.find("ms granted [live-io-rate]"), std::string::npos) << r.output;
}

// A size in one byte is no size: verify --live says so in words instead of
// reading a byte past the reply, and checks nothing of that assembly.
TEST_F(live_fake_device, verify_takes_an_assembly_size_of_one_byte_for_no_size) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {.one_byte_sizes = true}); });
  const auto eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
  const auto r = run_edsc("verify --live " + device.address() + " " + quoted(eds) + " --color never");
  EXPECT_NE(r.output.find("Assem151: the device does not give the size of assembly instance 151 (a reply without "
                          "the size)"),
            std::string::npos)
      << r.output;
}

// A refusal for the configuration (extended status 0x0129) is told with
// the configuration's size and instance (Assem151: 10 bytes, instance 151);
// one for the consuming path (0x012A) with the O->T point of Connection1's
// path (20 04 24 97 2C 96 2C 64), in the words `edsc explain --eds` uses.
TEST_F(live_fake_device, a_refusal_is_told_with_the_eds_values_it_concerns) {
  const auto eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
  for (const auto& [ext, words] :
       {std::pair<std::uint16_t, const char*>{
            0x0129, "the path names configuration instance 151 (24 97); 10 bytes of configuration data go with it"},
        {0x012A, "the path names O->T connection point 150 (2C 96): the output assembly"}}) {
    SCOPED_TRACE(ext);
    loopback_server device(
        [ext](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {.open_refused = ext}); });
    const auto r = run_edsc("verify --live " + device.address() + " " + quoted(eds) + " --connections --color never");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("Connection1 refused: 0x01"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(fmt::format("0x{:04X}", ext)), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(fmt::format(": {} [live-connection-refused]", words)), std::string::npos) << r.output;
  }
}

// A Forward_Close refused after the frames is said at the connection.
TEST_F(live_fake_device, a_refused_forward_close_is_said) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {.close_refused = true}); });
  const auto eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
  const auto r = run_edsc("verify --live " + device.address() + " " + quoted(eds) + " --connections --color never");
  EXPECT_NE(r.output.find("Connection1: Forward_Close refused: 0x01"), std::string::npos) << r.output;
}

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

// The 1-based number of the first line of `path` holding `needle`.
unsigned line_of(const std::string& path, const std::string& needle) {
  std::ifstream in(path);
  std::string line;
  for (unsigned n = 1; std::getline(in, line); ++n)
    if (line.find(needle) != std::string::npos) return n;
  return 0;
}

// The summary table travels in the machine-readable reports: each check
// with the EDS's and the device's value, and for an open connection the
// frames counted, their size, the measured and the granted interval.
TEST_F(live_fake_device, json_and_sarif_carry_the_summary_table) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {}); });
  const auto base = "verify --live " + device.address() + " " + quoted(opener_eds) + " --connections --watch 0.3";
  for (const auto* format : {"json", "sarif"}) {
    SCOPED_TRACE(format);
    const auto r = run_edsc(base + " --format " + format + " 2>/dev/null");
    EXPECT_EQ(r.status, 1) << r.output;
    const auto doc = nlohmann::json::parse(r.output, nullptr, false);
    ASSERT_FALSE(doc.is_discarded()) << r.output;
    const auto& live = std::string(format) == "json" ? doc["live"] : doc["runs"][0]["properties"]["live"];
    ASSERT_TRUE(live.is_object()) << r.output;
    EXPECT_EQ(live["host"], device.address());
    std::map<std::string, nlohmann::json> checks;
    for (const auto& c : live["checks"]) checks[c["check"]] = c;
    EXPECT_EQ(checks["VendCode"]["eds"], "1");
    EXPECT_EQ(checks["VendCode"]["device"], "1");
    EXPECT_EQ(checks["VendCode"]["result"], "match");
    EXPECT_EQ(checks["Assem100 size (instance 100)"]["device"], "32");
    const auto& c1 = checks["Connection1"];
    EXPECT_EQ(c1["result"], "mismatch");
    EXPECT_EQ(c1["io"]["frame_bytes"], 16);
    EXPECT_GE(c1["io"]["frames"].get<int>(), 2);
    EXPECT_GT(c1["io"]["interval_ms"].get<double>(), 20.0);  // 50 ms apart, however slow the host
    EXPECT_EQ(c1["io"]["granted_interval_ms"], 10.0);
    EXPECT_GE(c1["io"]["watched_ms"].get<int>(), 300);
    EXPECT_EQ(checks["Connection3"]["result"], "not tried");
  }
}

// The watch is --watch long, however short --timeout is, and the message
// about a connection that sent nothing gives that time: the one used.
TEST_F(live_fake_device, the_watch_time_printed_is_the_one_used) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {.silent_io = true}); });
  const auto r = run_edsc("verify --live " + device.address() + " " + quoted(opener_eds) +
                          " --connections --watch 0.5 --timeout 0.2 --color never");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("Connection1 opened, but no T->O frame came within 500 ms"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Connection2 opened, but no T->O frame came within 500 ms"), std::string::npos) << r.output;
  EXPECT_GE(r.seconds, 1.0);  // two connections watched 0.5 s each
  const auto watch_alone = run_edsc("verify --live " + device.address() + " " + quoted(opener_eds) + " --watch 1");
  EXPECT_EQ(watch_alone.status, 2) << watch_alone.output;
  EXPECT_NE(watch_alone.output.find("--watch"), std::string::npos) << watch_alone.output;
  EXPECT_NE(watch_alone.output.find("needs --connections"), std::string::npos) << watch_alone.output;
}

// An assembly instance the device calls unknown (0x05) while its Assembly
// class answers is an error where the EDS gives the instance: Assem151 has
// no path of its own, Connection1's path names instance 151 (2C 97... as
// configuration 24 97). When the class does not answer either, nothing is
// certain: a note, as for any size the device does not give.
TEST_F(live_fake_device, an_assembly_instance_the_device_lacks_is_an_error_at_its_path) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {.missing_instance = 151}); });
  const auto r = run_edsc("verify --live " + device.address() + " " + quoted(opener_eds) + " --color never");
  EXPECT_EQ(r.status, 1) << r.output;
  const auto where = fmt::format("{}:{}:", opener_eds, line_of(opener_eds, "\"20 04 24 97 2C 96 2C 64\""));
  const auto at = r.output.find(where);
  ASSERT_NE(at, std::string::npos) << where << "\n" << r.output;
  EXPECT_NE(r.output.find("error: the device has no assembly instance 151 (0x05 path destination unknown), which "
                          "Assem151 says it has [live-assembly-missing]",
                          at),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("no such instance"), std::string::npos) << r.output;

  loopback_server classless([](int s, const std::atomic<bool>& stop) {
    fake_device(s, stop, {.missing_instance = 151, .no_assembly_class = true});
  });
  const auto n = run_edsc("verify --live " + classless.address() + " " + quoted(opener_eds) + " --color never");
  EXPECT_EQ(n.status, 0) << n.output;
  EXPECT_NE(n.output.find("Assem151: the device does not give the size of assembly instance 151 (0x05 path "
                          "destination unknown) [live-not-checked]"),
            std::string::npos)
      << n.output;
}

// A refusal for the device's own state (another scanner owns the outputs)
// says nothing of the EDS: no diagnostic, a message that the device is
// busy, exit 2; the other connections are still checked.
TEST_F(live_fake_device, an_ownership_conflict_is_a_busy_device_not_an_eds_error) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {.open_refused = 0x0106}); });
  const auto r =
      run_edsc("verify --live " + device.address() + " " + quoted(opener_eds) + " --connections --color never");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output.find("[live-connection-refused]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("0 errors"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("is busy: Connection1 not checked: the device refused it with 0x01 connection failure, "
                          "extended 0x0106 ownership conflict: another scanner owns what it connects to"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("busy 0x01/0x0106"), std::string::npos) << r.output;
}

// SIGTERM while a connection's I/O is watched: edsc closes it (the device
// sees the Forward_Close), reports the checks made, marks the rest not
// reached, and exits 128 + 15, long before the watch would have ended.
TEST_F(live_fake_device, a_signal_midway_closes_the_connection_and_reports_what_was_found) {
  std::atomic<int> opened{0}, closed{0};
  loopback_server device(
      [&](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {.opened = &opened, .closed = &closed}); });
  const auto log = (std::filesystem::temp_directory_path() / ("edsc-signal-" + std::to_string(::getpid()))).string();
  edsc_child edsc(
      {"verify", "--live", device.address(), opener_eds, "--connections", "--watch", "30", "--color", "never"}, log);
  ASSERT_TRUE(edsc.started());
  for (int i = 0; i < 600 && opened == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_EQ(opened, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // some frames
  edsc.signal(SIGTERM);
  const auto r = edsc.finish();
  std::filesystem::remove(log);
  EXPECT_EQ(r.status, 128 + SIGTERM) << r.output;
  EXPECT_EQ(closed, 1) << r.output;
  EXPECT_NE(r.output.find("\nVendCode "), std::string::npos) << r.output;
  // The watch ended at the signal, not at its 30 s: edsc's own account.
  const auto after = r.output.find("; interrupted after ");
  ASSERT_NE(after, std::string::npos) << r.output;
  EXPECT_LT(std::stod(r.output.substr(after + 20)), 30.0) << r.output;
  const auto c2 = r.output.find("\nConnection2 ");
  ASSERT_NE(c2, std::string::npos) << r.output;
  EXPECT_NE(r.output.substr(c2, r.output.find('\n', c2 + 1) - c2).find("not reached: interrupted"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("interrupted by SIGTERM"), std::string::npos) << r.output;
}

// A SIGINT ignored when edsc starts (a shell's background job, `trap ""
// INT`) stays ignored: the run goes on to its end and its own exit status.
TEST_F(live_fake_device, an_interrupt_ignored_on_entry_stays_ignored) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {}); });
  const auto script = "trap '' INT; " + quoted(EDSC_BINARY) + " verify --live " + device.address() + " " +
                      quoted(opener_eds) + " --connections --watch 0.6 --color never & p=$!; sleep 0.4; " +
                      "kill -INT $p; wait $p; echo exit $?";
  const auto r = shell("sh -c " + quoted(script) + " 2>&1");
  EXPECT_NE(r.out.find("exit 1\n"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("interrupted"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("T->O frames carry 16 data bytes"), std::string::npos) << r.out;
}

// The device goes away in mid-run (it hangs up instead of answering the
// Forward_Close): the checks made so far stay in the report, the failure
// follows it, exit 2.
TEST_F(live_fake_device, a_device_lost_midway_keeps_the_report_so_far) {
  loopback_server device(
      [](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {.hang_up_at_close = true}); });
  const auto r = run_edsc("verify --live " + device.address() + " " + quoted(opener_eds) +
                          " --connections --watch 0.3 --timeout 1 --color never");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("\nVendCode "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\nAssem100 size (instance 100) "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("; device lost after "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("T->O frames carry 16 data bytes"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(": Forward_Close: the device closed the connection"), std::string::npos) << r.output;
}

// While the run takes more than a second and standard error is a terminal,
// a line there says what it does; into a pipe, never.
TEST_F(live_fake_device, progress_shows_on_a_terminal_only) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { fake_device(s, stop, {}); });
  const auto args = "verify --live " + device.address() + " " + quoted(opener_eds) + " --connections --watch 0.8";
  const auto piped = run_edsc(args);
  EXPECT_EQ(piped.output.find("edsc: opening Connection"), std::string::npos) << piped.output;
  const auto tty = shell("python3 -c 'import pty, sys; sys.exit(pty.spawn(sys.argv[1:]) >> 8)' " + quoted(EDSC_BINARY) +
                         " " + args + " </dev/null 2>&1");
  EXPECT_EQ(tty.status, 1) << tty.out;
  EXPECT_NE(tty.out.find("edsc: opening Connection2 (2 of 3) and watching its I/O for 0.8 s"), std::string::npos)
      << tty.out;
  EXPECT_NE(tty.out.find("\r\033[K"), std::string::npos) << tty.out;  // erased, not left in the report
  const auto quick =
      shell("python3 -c 'import pty, sys; sys.exit(pty.spawn(sys.argv[1:]) >> 8)' " + quoted(EDSC_BINARY) +
            " verify --live " + device.address() + " " + quoted(opener_eds) + " </dev/null 2>&1");
  EXPECT_EQ(quick.out.find("edsc: "), std::string::npos) << quick.out;
}

// What `edsc probe` asks, answered: OpENer's identity, ListServices, the
// Assembly class's Max Instance (2 unless `max_instance` says otherwise) and
// attribute 4 (size) of instance 1 in one byte where a size takes two, the
// other instances 32 bytes. Its File object announces 4 bytes; with
// `typed_transfers` Upload_Transfer 0 is a first packet of 2 bytes and every
// later one has the packet type 5 (none), else each answer is the transfer
// number alone. `hang_up_at` closes the session at that instance's size.
struct probe_quirks {
  std::uint16_t max_instance = 2;
  std::uint8_t hang_up_at = 0;
  bool typed_transfers = false;
};

void probe_device(int s, const std::atomic<bool>& stop, probe_quirks q) {
  for (;;) {
    const auto req = read_message(s, stop);
    if (req.size() < cip::encap_header_size) return;
    const auto command = static_cast<std::uint16_t>(req[0] | (req[1] << 8));
    if (command == 0x0065 || command == 0x0004) {  // RegisterSession, ListServices
      const auto data = command == 0x0065 ? cip::bytes{1, 0, 0, 0} : cip::list_services_reply();
      send_bytes(s, reply_to(req, command, 0x1234, data));
      continue;
    }
    if (command != 0x006F || req.size() < 24 + 16 + 2) return;
    const cip::bytes request(req.begin() + 24 + 16, req.end());
    const auto service = request[0];
    cip::bytes answer;
    if (service == 0x01) {
      answer = cip_reply(service, unhex("01 00 0C 00 E9 FD 02 03 30 00 15 CD 5B 07 09 4F 70 45 4E 65 72 20 50 43"));
    } else if (service == 0x0E && request.size() >= 8) {  // path 20 04 24 <instance> 30 <attribute>
      const auto instance = request[5], attribute = request[7];
      if (instance == q.hang_up_at && attribute == 4) return;
      if (instance == 0 && attribute == 2)
        answer = cip_reply(service,
                           {static_cast<std::uint8_t>(q.max_instance), static_cast<std::uint8_t>(q.max_instance >> 8)});
      else if (instance == 1)
        answer = cip_reply(service, {0x20});
      else
        answer = cip_reply(service, {0x20, 0});
    } else if (service == 0x4B) {  // Initiate_Upload: a file of 4 bytes, transfers of up to 255
      answer = cip_reply(service, {4, 0, 0, 0, 0xFF});
    } else if (service == 0x4F) {  // Upload_Transfer
      const auto n = request.back();
      answer = !q.typed_transfers ? cip_reply(service, {n})
                                  : cip_reply(service, {n, n == 0 ? std::uint8_t{0} : std::uint8_t{5}, 'E', 'D'});
    } else {
      answer = cip_reply(service, {}, 0x08);
    }
    send_bytes(s, reply_to(req, 0x006F, 0x1234, cip::send_rr_data(answer, 0).value()));
  }
}

TEST_F(live_fake_device, probe_skips_an_assembly_size_of_one_byte) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { probe_device(s, stop, {}); });
  const auto r = run_edsc("probe " + device.address() + " --timeout 2");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("      2: 32\n"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("      1: "), std::string::npos) << r.output;
}

// Max Instance 513 (01 02: 0x0201) is more than the 512 instances a probe reads.
TEST_F(live_fake_device, probe_reads_max_instance_in_two_bytes) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { probe_device(s, stop, {.max_instance = 513}); });
  const auto r = run_edsc("probe " + device.address() + " --timeout 2");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("(only instances 1-512 of 513 read)"), std::string::npos) << r.output;
}

// The device hangs up while its assembly sizes are read: the probe ends
// there with the network failure in words (exit 2), the reply it waited for.
TEST_F(live_fake_device, probe_stops_where_the_device_hangs_up) {
  loopback_server device([](int s, const std::atomic<bool>& stop) { probe_device(s, stop, {.hang_up_at = 2}); });
  const auto r = run_edsc("probe " + device.address() + " --timeout 2");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(": the device closed the connection instead of sending SendRRData reply header\n"),
            std::string::npos)
      << r.output;
}

// `edsc probe --upload-eds` from probe_device(q), which leaves no file
// behind: the upload fails in these tests.
auto refused_upload(probe_quirks q) {
  loopback_server device([q](int s, const std::atomic<bool>& stop) { probe_device(s, stop, q); });
  const auto out =
      (std::filesystem::temp_directory_path() / ("edsc-refused-upload-" + std::to_string(::getpid()) + ".eds"))
          .string();
  std::filesystem::remove(out);
  auto r = run_edsc("probe " + device.address() + " --timeout 2 --upload-eds " + quoted(out));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  return r;
}

// Packet type 5 is none of first (0), middle (1), last (2), first and last
// (4): the upload stops at transfer 1, the first that has it.
TEST_F(live_fake_device, an_upload_packet_of_type_5_is_out_of_turn) {
  const auto r = refused_upload({.typed_transfers = true});
  EXPECT_NE(r.output.find("upload of the EDS from the device: Upload_Transfer 1: packet type 5 out of turn"),
            std::string::npos)
      << r.output;
}

// An Upload_Transfer reply of one byte has no packet type: the upload stops
// at it in words (exit 2) instead of reading the type past the reply.
TEST_F(live_fake_device, an_upload_transfer_of_one_byte_is_no_packet) {
  const auto r = refused_upload({});
  EXPECT_NE(r.output.find("upload of the EDS from the device: Upload_Transfer 0 answered another transfer"),
            std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace edsc::live_test
