// tshark, a dissector nobody here wrote, as the judge of what an
// Unconnected_Send carries: on a capture this test writes, the embedded
// service and object the tracker records a write at, and the route it reads.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <pcap/dlt.h>

#include <sstream>

#include "capture/trace.hpp"
#include "cip/connection_manager.hpp"
#include "cip/device_reply.hpp"
#include "cip/encap.hpp"
#include "cip/request.hpp"
#include "tcp_capture.hpp"
#include "tshark_tools.hpp"

namespace edsc::capture::test {
namespace {

bytes rr_data(const bytes& cip) {
  return cip::encode_encap(cip::command::send_rr_data, 0x44332211, {}, cip::send_rr_data(cip, 5).value()).value();
}

bytes wrapped_write(std::uint32_t instance, const bytes& route) {
  const auto write =
      cip::encode_request(cip::service::set_attribute_single, cip::logical_path(0x0F, instance, 1), bytes{0x2C, 0x01})
          .value();
  return rr_data(cip::encode_unconnected_send({0x0A, 0x0E, write, route}).value());
}

// A write to Parameter 3 for the device itself (empty route), its reply, and
// one to Parameter 4 routed to backplane slot 2.
void write_capture(const std::string& path) {
  const tcp_side client;
  const tcp_side server{.to_client = true};
  const bytes first = wrapped_write(3, {});
  const bytes reply = rr_data(cip::encode_reply(cip::service::set_attribute_single, cip::general_status::success));
  const bytes routed = wrapped_write(4, {0x01, 0x02});
  capture_writer w(path, DLT_EN10MB);
  std::int64_t t = 1;
  for (const bytes& f : {client.syn(), server.syn(), client.at(0, first), server.at(0, reply),
                         client.at(static_cast<std::uint32_t>(first.size()), routed)})
    w.write(f, t++);
}

// "frame services class instance attribute route-words" of each request,
// the services the outer and the embedded one.
std::string tshark_requests(const std::string& path) {
  return run("tshark -r '" + path +
             "' -Y 'cip.cm.msg_req_size' -T fields -E occurrence=l -e frame.number -e cip.service -e cip.class "
             "-e cip.instance -e cip.attribute -e cip.cm.route_path_size 2>/dev/null");
}

TEST(CaptureTsharkUnconnected, WrappedRequestsDecodeAsTsharkDecodesThem) {
  if (!have("tshark")) GTEST_SKIP() << "tshark is not installed (Debian package tshark)";
  scratch_file file("unconnected.pcap");
  write_capture(file.path());
  const auto r = read_all(file.path());
  ASSERT_EQ(r.error, "");
  tracker t;
  std::ostringstream ours;
  for (const auto& m : r.messages) {
    t.add(m);
    // The route as the codec reads it, for each request (24 + 16: the CIP request's start).
    const cip::byte_view cip = cip::byte_view(m.payload).subspan(40);
    if ((cip[0] & 0x80) != 0) continue;
    const auto us = cip::decode_unconnected_send(cip.subspan(6), 46).value();
    const auto inner = cip::decode_request(us.message, 0).value();
    const auto where = cip::address_of(cip::decode_path(inner.path, 2).value()).value();
    ours << fmt::format("{}\t0x{:02x}\t0x{:02x}\t0x{:02x}\t{}\t{}\n", m.frame, cip::code(inner.service), where.class_id,
                        where.instance, where.attribute.value_or(0), us.route.size() / 2);
  }
  ASSERT_EQ(t.writes().size(), 1U);  // the routed one is not the device's
  EXPECT_EQ(t.writes()[0].frame, 3U);
  EXPECT_EQ(t.writes()[0].instance, 3U);
  EXPECT_EQ(t.writes()[0].reply_general, 0);
  EXPECT_EQ(t.routed(), 1U);
  EXPECT_EQ(ours.str(), tshark_requests(file.path()));
}

}  // namespace
}  // namespace edsc::capture::test
