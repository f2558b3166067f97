// `edsc connection --format c`: the header compiles as C99 with every
// warning an error, its offsets are where the originator's fields are (a C
// program fills them and the request decodes with those values), and the
// bytes, wrapped by text2pcap in TCP to port 44818, decode in tshark — a
// dissector nobody here wrote — with the path, sizes, RPIs, transport and
// key the settings announce, and nothing malformed.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "cip/encap.hpp"
#include "cip/request.hpp"
#include "connections/settings.hpp"
#include "connections/summary.hpp"
#include "corpus_dirs.hpp"
#include "emit/connection_render.hpp"
#include "emit_support.hpp"
#include "opener_support.hpp"

namespace edsc::test {
namespace {

const std::string opener_eds = std::string(EDSC_CORPUS_DIR) + "/EIPStackGroup__OpENer__opener_sample_app.eds";

// O->T 600 bytes: over 511 with its headers, so a Large_Forward_Open.
std::string large_eds() {
  return device_section() +
         "[Assembly]\n"
         "    Assem100 = \"Out\", \"\", 600, 0x0001, , ;\n"
         "    Assem130 = \"In\", \"\", 8, 0x0000, , ;\n"
         "[Connection Manager]\n"
         "    Connection1 = 0x84010002, 0x44640405, 20000, , Assem100, 40000, , Assem130, , , , , \"Big\", \"\", "
         "\"20 04 24 01 2C 64 2C 82\";\n";
}

// Fills the originator's fields through the header's offsets and prints the request in hex.
const char* const main_c = R"(#include <stdio.h>
#include <string.h>
#include "conn.h"
static void put(uint8_t *r, int at, uint32_t v, int n) { for (int i = 0; i < n; ++i) r[at + i] = (uint8_t)(v >> (8 * i)); }
int main(void) {
    uint8_t r[2048];
    const struct edsc_connection *c = &edsc_connection1;
    memcpy(r, c->request, c->request_size);
    put(r, EDSC_FO_TO_CONNECTION_ID, 0x11223344u, 4);
    put(r, EDSC_FO_CONNECTION_SERIAL, 0x1234u, 2);
    put(r, EDSC_FO_ORIGINATOR_VENDOR, 0x5678u, 2);
    put(r, EDSC_FO_ORIGINATOR_SERIAL, 0x9ABCDEF0u, 4);
    put(r, EDSC_FO_TIMEOUT_MULTIPLIER, 3u, 1);
    for (unsigned i = 0; i < c->request_size; ++i) printf("%s%02X", i ? " " : "", r[i]);
    printf("\n%u %u %u\n", (unsigned)c->path_size, (unsigned)c->ot_wire_size, (unsigned)c->large);
    return 0;
}
)";

struct filled {
  cip::bytes request;
  std::string tail;
};

// The header for `eds`, compiled with main_c and run.
filled compile_and_run(const temp_dir& dir, const std::string& eds) {
  write_text(dir.path() / "device.eds", eds);
  write_text(dir.path() / "main.c", main_c);
  const auto gen = run_shell(edsc_command() + " connection " + quoted(dir.path() / "device.eds") + " 1 --format c -o " +
                             quoted(dir.path() / "conn.h"));
  EXPECT_EQ(gen.status, 0) << gen.output;
  const auto exe = dir.path() / "main";
  const auto cc = run_shell("gcc -std=c99 -Wall -Wextra -Werror -pedantic -I" + quoted(dir.path()) + " " +
                            quoted(dir.path() / "main.c") + " -o " + quoted(exe));
  EXPECT_EQ(cc.status, 0) << cc.output;
  const auto run = run_shell(quoted(exe));
  EXPECT_EQ(run.status, 0) << run.output;
  filled out;
  const auto nl = run.output.find('\n');
  std::string hex = run.output.substr(0, nl);
  for (std::size_t i = 0; i + 1 < hex.size(); i += 3)
    out.request.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
  out.tail = nl == std::string::npos ? "" : run.output.substr(nl + 1);
  return out;
}

std::vector<connections::connection_setting> settings(const std::string& eds) {
  const auto c = plan_eds(eds);
  return connections::describe_connections(c->dev);
}

void expect_filled_in(const filled& f, const connections::connection_setting& s) {
  ASSERT_GE(f.request.size(), 2u);
  const auto body = cip::byte_view(f.request).subspan(2 + 2 * f.request[1]);
  const auto fo = cip::decode_forward_open(body, s.large, 0);
  ASSERT_TRUE(fo.ok()) << fo.error().what;
  EXPECT_EQ(fo->to_connection_id, 0x11223344u);
  EXPECT_EQ(fo->connection_serial, 0x1234u);
  EXPECT_EQ(fo->originator_vendor, 0x5678u);
  EXPECT_EQ(fo->originator_serial, 0x9ABCDEF0u);
  EXPECT_EQ(fo->timeout_multiplier, 3u);
  EXPECT_EQ(fo->ot_rpi_us, s.ot.rpi.asked_us);
  EXPECT_EQ(fo->to_rpi_us, s.to.rpi.asked_us);
  EXPECT_EQ(fo->ot.size, s.ot.asked.size);
  EXPECT_EQ(fo->to.size, s.to.asked.size);
  EXPECT_EQ(connections::hex_bytes(fo->path), connections::hex_bytes(s.connection_path));
}

TEST(ConnectionC, TheOffsetsAreTheOriginatorsFields) {
  temp_dir dir("conn-c");
  const auto text = read_text(opener_eds);
  const auto f = compile_and_run(dir, text);
  const auto all = settings(text);
  ASSERT_FALSE(all.empty());
  expect_filled_in(f, all[0]);
  EXPECT_EQ(f.tail, "30 38 0\n");  // key 10 + path 8 + data segment 2 + 10 bytes; 32 + 2 + 4; not large
}

TEST(ConnectionC, ALargeConnectionIsALargeForwardOpen) {
  temp_dir dir("conn-c-large");
  const auto f = compile_and_run(dir, large_eds());
  const auto all = settings(large_eds());
  ASSERT_EQ(all.size(), 1u);
  ASSERT_TRUE(all[0].large);
  ASSERT_FALSE(f.request.empty());
  EXPECT_EQ(f.request[0], 0x5B);
  expect_filled_in(f, all[0]);
  EXPECT_EQ(f.tail, "18 606 1\n");  // key 10 + path 8; 600 + 2 + 4
}

// The request inside SendRRData, as text2pcap reads a hex dump, then tshark's fields.
std::string tshark_fields(const temp_dir& dir, const cip::bytes& request, const std::string& fields) {
  const auto framed =
      cip::encode_encap(cip::command::send_rr_data, 0x1234, {}, cip::send_rr_data(request, 3).value()).value();
  std::string dump;
  for (std::size_t i = 0; i < framed.size(); ++i)
    dump +=
        (i % 16 == 0 ? fmt::format("{}{:06x}", i ? "\n" : "", i) : std::string()) + fmt::format(" {:02x}", framed[i]);
  write_text(dir.path() / "dump.txt", dump + "\n");
  const auto pcap = dir.path() / "fo.pcap";
  const auto t2p = run_shell("text2pcap -q -T 40000,44818 " + quoted(dir.path() / "dump.txt") + " " + quoted(pcap));
  EXPECT_EQ(t2p.status, 0) << t2p.output;
  // tshark's notes go to standard error, which run_shell would fold in.
  const auto tshark = [&](const std::string& args) {
    return run_shell("{ tshark -r " + quoted(pcap) + " " + args + " 2>/dev/null; }").output;
  };
  EXPECT_EQ(tshark("-Y _ws.malformed -T fields -e frame.number"), "") << "malformed";
  return tshark("-T fields -E separator=, " + fields);
}

bool have(const char* tool) { return run_shell(std::string("command -v ") + tool + " >/dev/null").status == 0; }

TEST(ConnectionC, TsharkReadsTheRequestAsAnnounced) {
  if (!have("tshark") || !have("text2pcap"))
    GTEST_SKIP() << "tshark or text2pcap is missing (Debian packages tshark, wireshark-common)";
  temp_dir dir("conn-c-tshark");
  const auto text = read_text(opener_eds);
  const auto f = compile_and_run(dir, text);
  const auto s = settings(text)[0];
  const auto got = tshark_fields(dir, f.request,
                                 "-e cip.cm.sc -e cip.cm.otrpi -e cip.cm.torpi -e cip.cm.fwo.consize "
                                 "-e cip.cm.transport_type_trigger -e cip.ekey.vendor -e cip.ekey.devtype "
                                 "-e cip.ekey.product_code -e cip.ekey.major_rev -e cip.ekey.minor_rev "
                                 "-e cip.class -e cip.instance -e cip.connpoint -e cip.data_segment.size");
  // Key vendor 1, type 12, code 65001 (0xfde9), revision 2.3; classes 6 (the
  // Connection Manager the request goes to) and 4, instances 1 and 151
  // (configuration), connection points 150 and 100; ten bytes of configuration
  // are five words.
  EXPECT_EQ(got, fmt::format("0x54,{},{},{},{},0x{:02x},0x0001,0x000c,0xfde9,2,3,0x06,0x04,0x01,0x97,0x96,0x64,5\n",
                             s.ot.rpi.asked_us, s.to.rpi.asked_us, s.ot.asked.size, s.to.asked.size, s.transport))
      << got;
}

}  // namespace
}  // namespace edsc::test
