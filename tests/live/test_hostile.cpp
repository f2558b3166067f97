// A broken or hostile device (a server on loopback, in this test, not in
// edsc) never crashes or hangs edsc: each misbehaviour gets a clear message
// and exit 2. Here only what needs a socket: silence, a close or a reset
// mid-reply; replies that are wrong in their bytes are fed to the session
// machine in test_session_machine.cpp. The bound on time is generous (the suite also runs under the
// sanitizers); what is checked is that edsc ends and says why.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <functional>
#include <thread>

#include "cip/encap.hpp"
#include "loopback_server.hpp"
#include "netns/run_edsc.hpp"
#include "test_paths.hpp"

namespace edsc::live_test {
namespace {

// Answers nothing until the client goes away (the next client waits for that).
void stay_silent(int s, const std::atomic<bool>& stop) {
  while (!stop) {
    pollfd p{s, POLLIN, 0};
    if (::poll(&p, 1, 20) <= 0) continue;
    std::uint8_t buf[256];
    if (::recv(s, buf, sizeof buf, 0) <= 0) return;
  }
}

struct hostile_case {
  const char* name;
  behaviour server;
  const char* message;  // a part of the message edsc must give
};

void PrintTo(const hostile_case& c, std::ostream* os) { *os << c.name; }

class live_hostile : public loopback_test, public ::testing::WithParamInterface<hostile_case> {};

TEST_P(live_hostile, ends_with_a_message_and_exit_2) {
  loopback_server server(GetParam().server);
  const auto eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
  for (const auto& cmd : {"verify --live " + server.address() + " " + quoted(eds) + " --connections --timeout 1",
                          "probe " + server.address() + " --timeout 1"}) {
    const auto r = run_edsc(cmd, 120);
    EXPECT_EQ(r.status, 2) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find(GetParam().message), std::string::npos) << cmd << "\n" << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    // Far above the 1 s timeout, so sanitizer slowness cannot fail it; a hang would.
    EXPECT_LT(r.seconds, 60.0) << cmd;
  }
}

const hostile_case cases[] = {
    {"truncated_header",
     [](int s, const std::atomic<bool>& stop) {
       const auto req = read_message(s, stop);
       const auto full = reply_to(req, 0x0065, 0x1234, {1, 0, 0, 0});
       send_bytes(s, cip::bytes(full.begin(), full.begin() + 10));
     },
     "closed the connection after 10 of the 24 bytes"},
    {"length_that_lies",
     [](int s, const std::atomic<bool>& stop) {
       const auto req = read_message(s, stop);
       auto full = reply_to(req, 0x0065, 0x1234, {1, 0, 0, 0});
       full[2] = 100;  // says 100 bytes follow; 4 do, then nothing
       send_bytes(s, full);
       stay_silent(s, stop);
     },
     "sent 4 of the 100 bytes"},
    {"silence", [](int s, const std::atomic<bool>& stop) { stay_silent(s, stop); }, "within the timeout"},
    {"reset_mid_reply",
     [](int s, const std::atomic<bool>& stop) {
       const auto req = read_message(s, stop);
       const auto full = reply_to(req, 0x0065, 0x1234, {1, 0, 0, 0});
       send_bytes(s, cip::bytes(full.begin(), full.begin() + 12));
       linger l{1, 0};  // close with RST
       ::setsockopt(s, SOL_SOCKET, SO_LINGER, &l, sizeof l);
     },
     "12 of the 24 bytes"},
};

INSTANTIATE_TEST_SUITE_P(cases, live_hostile, ::testing::ValuesIn(cases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace edsc::live_test
