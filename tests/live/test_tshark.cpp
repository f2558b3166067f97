// tshark, an independent dissector, reads what edsc encodes with the same
// fields and finds nothing malformed.
#include <gtest/gtest.h>

#include <filesystem>

#include <unistd.h>

#include "cip/connection_manager.hpp"
#include "cip/encap.hpp"
#include "cip/io_frame.hpp"
#include "cip/message.hpp"
#include "netns/live_support.hpp"
#include "pcap_writer.hpp"

namespace edsc::live_test {
namespace {

namespace fs = std::filesystem;

bool have_tshark() { return shell("command -v tshark >/dev/null 2>&1").status == 0; }

TEST(live_tshark, encoded_session_decodes_with_the_same_fields) {
  if (!have_tshark()) GTEST_SKIP() << "tshark is not installed (Debian package tshark)";
  const auto path = (fs::temp_directory_path() / ("edsc-tshark-" + std::to_string(::getpid()) + ".pcap")).string();
  {
    pcap_writer w(path);
    const cip::sender_context ctx{'e', 'd', 's', 'c', 1, 0, 0, 0};
    // ListIdentity request and OpENer's reply (the bytes of test_cip_codec.cpp).
    w.tcp(true, 40000, 44818, cip::encode_encap(cip::command::list_identity, 0, ctx, {}).value());
    const auto li = unhex(
        "01 00 0C 00 2B 00 01 00 00 02 AF 12 C6 33 64 02 00 00 00 00 00 00 00 00 01 00 0C 00 E9 FD 02 03 30 00 "
        "15 CD 5B 07 09 4F 70 45 4E 65 72 20 50 43 03");
    w.tcp(false, 44818, 40000, cip::encode_encap(cip::command::list_identity, 0, ctx, li).value());
    // RegisterSession.
    w.tcp(true, 40000, 44818,
          cip::encode_encap(cip::command::register_session, 0, ctx, cip::register_session_data()).value());
    w.tcp(false, 44818, 40000,
          cip::encode_encap(cip::command::register_session, 0x1234, ctx, cip::register_session_data()).value());
    // Forward_Open of Connection1 and its success reply.
    const auto fo = cip::encode_forward_open(opener_connection1_request()).value();
    w.tcp(true, 40000, 44818,
          cip::encode_encap(cip::command::send_rr_data, 0x1234, ctx, cip::send_rr_data(fo, 3).value()).value());
    const auto ok = unhex("D4 00 00 00 11 11 11 11 01 00 44 45 01 45 FF FF 65 64 73 63 30 75 00 00 30 75 00 00 00 00");
    w.tcp(false, 44818, 40000,
          cip::encode_encap(cip::command::send_rr_data, 0x1234, ctx, cip::send_rr_data(ok, 0).value()).value());
    // One O->T frame with the run/idle header and one T->O frame without.
    cip::io_frame ot{0x11111111, 1, 1, 0u, cip::bytes(32, 0)};
    w.udp(true, 2222, 2222, cip::encode_io_frame(ot).value());
    cip::io_frame to{0x45440001, 1, 1, std::nullopt, cip::bytes(32, 7)};
    w.udp(false, 2222, 2222, cip::encode_io_frame(to).value());
  }
  const auto base = "tshark -r " + path + " -d udp.port==2222,cipio ";
  const auto malformed = shell(base + "-Y _ws.malformed -T fields -e frame.number 2>/dev/null");
  EXPECT_EQ(malformed.status, 0) << malformed.out;
  EXPECT_EQ(malformed.out, "") << "malformed frames: " << malformed.out;
  const auto id = shell(base +
                        "-Y enip.lir.name -T fields -E separator=, -e enip.lir.vendor -e enip.lir.devtype "
                        "-e enip.lir.prodcode -e enip.lir.serial -e enip.lir.name 2>/dev/null");
  EXPECT_EQ(id.out, "0x0001,12,65001,0x075bcd15,OpENer PC\n");  // tshark shows the vendor id in hex
  const auto fwo = shell(base +
                         "-Y cip.cm.ot_net_params -T fields -E separator=, -e cip.cm.sc -e cip.cm.otrpi "
                         "-e cip.cm.fwo.consize -e cip.cm.fwo.type -e cip.cm.vendor 2>/dev/null");
  EXPECT_EQ(fwo.out, "0x54,30000,38,34,2,2,0xffff\n") << fwo.out;
  const auto io = shell(
      base + "-Y enip.cpf.sai.connid -T fields -E separator=, -e enip.cpf.sai.connid -e enip.cpf.sai.seq 2>/dev/null");
  EXPECT_EQ(io.out, "0x11111111,1\n0x45440001,1\n") << io.out;
  fs::remove(path);
}

}  // namespace
}  // namespace edsc::live_test
