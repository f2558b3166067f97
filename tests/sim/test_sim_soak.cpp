// A bounded soak of `edsc sim` in its own namespace: 20 input-only
// connections at a 10 ms RPI for 10 s, every T->O frame counted on the
// scanner side. Measures what docs/sim.md reports: frames lost, jitter
// against the RPI, CPU per 1000 produced frames.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <signal.h>
#include <sys/socket.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>

#include "cip/io_frame.hpp"
#include "fuzz/fuzz_bodies.hpp"
#include "live/session.hpp"
#include "sim_network.hpp"

namespace edsc::sim_test {
namespace {

using namespace std::chrono_literals;

TEST(sim_soak, twenty_connections_at_10_ms_for_10_s) {
  std::string why;
  auto net = make_sim_network(why);
  if (!net) GTEST_SKIP() << why;
  const auto eds = net->dir + "/soak.eds";
  std::ofstream(eds) << fuzz::sim_fuzz_eds;  // Connection2: input-only, 8 bytes T->O, RPI 1-100 ms
  const auto pid = start_sim(*net, eds, why);
  ASSERT_GT(pid, 0) << why;
  auto to = live::resolve(net->device_ip, cip::enip_port);
  ASSERT_FALSE(live::failed(to));
  auto opened = live::session::open(std::get<live::endpoint>(to), 3000ms);
  ASSERT_FALSE(live::failed(opened)) << live::failed(opened)->message;
  auto& s = std::get<live::session>(opened);
  sockaddr_in local = s.local();
  local.sin_port = htons(cip::io_port);
  auto udp = live::udp_socket(local);
  ASSERT_FALSE(live::failed(udp)) << live::failed(udp)->message;
  const int sock = std::get<live::fd>(udp).get();

  constexpr unsigned connections = 20;
  constexpr std::uint32_t rpi_us = 10'000;
  std::map<std::uint32_t, std::uint32_t> ot_of;  // T->O id -> O->T id
  for (unsigned i = 0; i < connections; ++i) {
    cip::forward_open_request fo;
    fo.to_connection_id = 0x50000000u + i;
    fo.connection_serial = static_cast<std::uint16_t>(100 + i);
    fo.originator_vendor = 0xFFFF;
    fo.originator_serial = 0x736F616B;
    fo.timeout_multiplier = 7;  // 512 x 10 ms: a heartbeat a second keeps it open
    fo.ot_rpi_us = fo.to_rpi_us = rpi_us;
    fo.ot = {2, false, cip::conn_priority::low, cip::conn_type::point_to_point, false};
    fo.to = {10, false, cip::conn_priority::low, cip::conn_type::point_to_point, false};
    cip::put_key(fo.path, {0xFFFF, 12, 7, 1, 2, true});
    cip::put_bytes(fo.path, live_test::unhex("20 04 24 97 2C 98 2C 64"));
    auto rep = s.request_raw(cip::service::forward_open, cip::encode_forward_open(fo));
    ASSERT_FALSE(live::failed(rep));
    const auto& r = std::get<cip::reply>(rep);
    ASSERT_EQ(r.general, 0) << i;
    const auto ok = cip::decode_forward_open_ok(r.data, 0);
    ASSERT_TRUE(ok.ok());
    ot_of[ok->to_connection_id] = ok->ot_connection_id;
  }

  std::map<std::uint32_t, std::vector<live::clock::time_point>> arrivals;
  std::map<std::uint32_t, std::pair<std::uint16_t, std::uint16_t>> sequences;  // first, last
  const auto start = live::clock::now();
  const auto end = start + 10s;
  auto next_heartbeat = start;
  std::uint32_t hb_sequence = 0;
  sockaddr_in device = std::get<live::endpoint>(to).addr;
  device.sin_port = htons(cip::io_port);
  while (live::clock::now() < end) {  // bounded by `end`
    if (live::clock::now() >= next_heartbeat) {
      ++hb_sequence;
      for (const auto& [to_id, ot_id] : ot_of) {
        cip::io_frame f;
        f.connection_id = ot_id;
        f.encap_sequence = hb_sequence;
        f.sequence_count = static_cast<std::uint16_t>(hb_sequence);
        const auto b = cip::encode_io_frame(f);
        (void)::sendto(sock, b.data(), b.size(), 0, reinterpret_cast<const sockaddr*>(&device), sizeof device);
      }
      next_heartbeat += 1s;
    }
    if (!live::wait_readable(sock, std::min(end, next_heartbeat))) continue;
    std::uint8_t buf[512];
    const auto n = ::recv(sock, buf, sizeof buf, 0);
    if (n <= 0) continue;
    const auto f = cip::decode_io_frame(cip::byte_view(buf, static_cast<std::size_t>(n)), false);
    if (!f.ok() || !ot_of.count(f->connection_id) || f->data.size() != 8) continue;
    auto& times = arrivals[f->connection_id];
    if (times.empty()) sequences[f->connection_id].first = f->sequence_count;
    sequences[f->connection_id].second = f->sequence_count;
    times.push_back(live::clock::now());
  }
  s.close();
  net->stop(pid, SIGTERM);
  const auto log = live_test::shell("cat " + net->dir + "/sim.log").out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(log, m, std::regex(R"("stopped","produced":([0-9]+),"late":([0-9]+),"open_connections":[0-9]+,"cpu_s":([0-9.]+))")))
      << log;
  const double produced = std::stod(m[1]), cpu_s = std::stod(m[3]);

  std::size_t received = 0, lost = 0;
  for (const auto& [id, seq] : sequences)  // the CIP sequence count grows by one per frame produced
    lost += static_cast<std::uint16_t>(seq.second - seq.first) + 1u - arrivals[id].size();
  double sum_sq = 0, worst = 0;
  std::size_t intervals = 0;
  for (const auto& [id, times] : arrivals) {
    received += times.size();
    for (std::size_t i = 1; i < times.size(); ++i) {
      const double dev = std::chrono::duration<double, std::micro>(times[i] - times[i - 1]).count() - rpi_us;
      sum_sq += dev * dev;
      worst = std::max(worst, std::abs(dev));
      ++intervals;
    }
  }
  const double nominal = connections * 10.0 * 1e6 / rpi_us;
  const double jitter_us = intervals ? std::sqrt(sum_sq / static_cast<double>(intervals)) : 0;
  std::printf("soak: %u connections at %u us for 10 s: %zu frames received of %.0f nominal, %zu lost, "
              "%.0f produced (%s late), jitter %.0f us rms, %.0f us worst, CPU %.3f s = %.1f ms per 1000 frames\n",
              connections, rpi_us, received, nominal, lost, produced, m[2].str().c_str(), jitter_us, worst, cpu_s,
              produced > 0 ? cpu_s * 1e6 / produced : 0.0);
  EXPECT_EQ(arrivals.size(), connections);
  // Every frame produced arrives (no gap in any sequence count); a busy shared
  // machine may delay production, so the nominal count is a loose floor.
  EXPECT_EQ(lost, 0u);
  EXPECT_GE(static_cast<double>(received), 0.8 * nominal);
}

}  // namespace
}  // namespace edsc::sim_test
