// A broken or hostile device (a server on loopback, in this test, not in
// edsc) never crashes or hangs edsc: each misbehaviour gets a clear message
// and exit 2. The bound on time is generous (the suite also runs under the
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

// Answers RegisterSession properly (handle 0x1234); then `after` takes over.
behaviour registered(std::function<void(int, const cip::bytes&, const std::atomic<bool>&)> after) {
  return [after](int s, const std::atomic<bool>& stop) {
    const auto reg = read_message(s, stop);
    if (reg.size() < cip::encap_header_size) return;
    send_bytes(s, reply_to(reg, 0x0065, 0x1234, {1, 0, 0, 0}));
    const auto next = read_message(s, stop);
    if (next.size() < cip::encap_header_size) return;
    after(s, next, stop);
  };
}

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
    {"wrong_session_handle",
     registered([](int s, const cip::bytes& req, const std::atomic<bool>&) {
       send_bytes(s, reply_to(req, 0x006F, 0x9999, {}));  // SendRRData with another handle
     }),
     "session handle 0x00009999, ours is 0x00001234"},
    {"reply_to_the_wrong_service",
     registered([](int s, const cip::bytes& req, const std::atomic<bool>&) {
       // A well-formed SendRRData reply holding a Get_Attribute_Single reply (0x8E).
       const cip::bytes cip_reply = {0x8E, 0, 0, 0, 1, 0};
       send_bytes(s, reply_to(req, 0x006F, 0x1234, cip::send_rr_data(cip_reply, 0).value()));
     }),
     "replied to service 0x0E when asked for service"},
    {"silence",
     [](int s, const std::atomic<bool>& stop) { stay_silent(s, stop); },
     "within the timeout"},
    {"reset_mid_reply",
     [](int s, const std::atomic<bool>& stop) {
       const auto req = read_message(s, stop);
       const auto full = reply_to(req, 0x0065, 0x1234, {1, 0, 0, 0});
       send_bytes(s, cip::bytes(full.begin(), full.begin() + 12));
       linger l{1, 0};  // close with RST
       ::setsockopt(s, SOL_SOCKET, SO_LINGER, &l, sizeof l);
     },
     "12 of the 24 bytes"},
    {"endless_data",
     [](int s, const std::atomic<bool>& stop) {
       const cip::bytes junk(4096, 0xFF);
       while (!stop) {
         pollfd p{s, POLLOUT, 0};
         if (::poll(&p, 1, 50) <= 0) continue;
         if (::send(s, junk.data(), junk.size(), MSG_NOSIGNAL | MSG_DONTWAIT) < 0 && errno != EAGAIN) return;
       }
     },
     "answered RegisterSession with 0xFFFF"},
};

INSTANTIATE_TEST_SUITE_P(cases, live_hostile, ::testing::ValuesIn(cases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace edsc::live_test
