// edsc against a real device: OpENer (../shared/opener) in its own network
// namespace. Its own EDS passes `verify --live --connections`; faults made
// with `edsc edit` on a copy are reported at the edited line with the
// device's status; a capture of the session decodes cleanly in tshark.
#include <gtest/gtest.h>

#include <signal.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <thread>

#include <nlohmann/json.hpp>

#include "cip/connection_manager.hpp"
#include "cip/message.hpp"
#include "live/client.hpp"
#include "netns/live_support.hpp"
#include "netns/run_edsc.hpp"
#include "netns/test_network.hpp"
#include "opener_device.hpp"
#include "test_paths.hpp"

namespace edsc::live_test {
namespace {

namespace fs = std::filesystem;

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

class live_opener : public opener_device_test {
 protected:
  // A copy of OpENer's EDS in the test's folder, edited by `edsc edit`.
  std::string faulty_copy(const std::string& set) {
    const auto path = net_->dir + "/faulty.eds";
    fs::copy_file(opener_eds, path, fs::copy_options::overwrite_existing);
    const auto r = run_edsc("edit " + quoted(path) + " --in-place --force --set " + quoted(set));
    EXPECT_EQ(r.status, 0) << r.output;
    return path;
  }
};

// The 1-based line of the first line of `path` holding `needle` after line `from`.
unsigned line_of(const std::string& path, const std::string& needle, const std::string& after = {}) {
  std::ifstream in(path);
  std::string line;
  unsigned n = 0;
  bool armed = after.empty();
  while (std::getline(in, line)) {
    ++n;
    if (!armed && line.find(after) != std::string::npos) armed = true;
    if (armed && line.find(needle) != std::string::npos) return n;
  }
  return 0;
}

TEST_F(live_opener, its_own_eds_passes_with_every_connection_opened) {
  const auto r = run_edsc("verify --live " + device() + " " + quoted(opener_eds) + " --connections --color never");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("0 errors"), std::string::npos) << r.output;
  // Connection1 (exclusive owner) and 2 (input only) open and deliver 32-byte frames.
  for (const auto* c : {"Connection1 ", "Connection2 "}) {
    const auto at = r.output.find(std::string("\n") + c);
    ASSERT_NE(at, std::string::npos) << r.output;
    const auto row = r.output.substr(at + 1, r.output.find('\n', at + 1) - at - 1);
    EXPECT_NE(row.find("open; "), std::string::npos) << row;
    EXPECT_NE(row.find("frames of 32 B"), std::string::npos) << row;
    EXPECT_EQ(row.find("open; 0 frames"), std::string::npos) << row;
    EXPECT_TRUE(row.ends_with("match")) << row;
  }
  for (const auto* a :
       {"\nAssem100 size (instance 100) ", "\nAssem150 size (instance 150) ", "\nAssem151 size (instance 151) "}) {
    const auto at = r.output.find(a);
    ASSERT_NE(at, std::string::npos) << a << r.output;
    const auto row = r.output.substr(at + 1, r.output.find('\n', at + 1) - at - 1);
    EXPECT_TRUE(row.ends_with(" match")) << row;
  }
  std::printf("verify --live --connections against OpENer: %.2f s\n", r.seconds);
  const auto quick = run_edsc("verify --live " + device() + " " + quoted(opener_eds) + " --color never");
  EXPECT_EQ(quick.status, 0) << quick.output;
  EXPECT_NE(quick.output.find("--connections not given"), std::string::npos) << quick.output;
  std::printf("verify --live against OpENer: %.2f s\n", quick.seconds);
}

TEST_F(live_opener, probe_reads_identity_assemblies_and_matches_the_library) {
  const auto lib = net_->dir + "/library";
  fs::create_directories(lib);
  fs::copy_file(opener_eds, lib + "/opener.eds");
  const auto r = run_edsc("probe " + device() + " --library " + quoted(lib) + " --format json");
  ASSERT_EQ(r.status, 0) << r.output;
  std::printf("probe --library against OpENer: %.2f s\n", r.seconds);
  const auto j = nlohmann::json::parse(r.output, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << r.output;
  EXPECT_EQ(j["identity"]["vendor_id"], 1);
  EXPECT_EQ(j["identity"]["device_type"], 12);
  EXPECT_EQ(j["identity"]["product_code"], 65001);
  EXPECT_EQ(j["identity"]["revision"]["major"], 2);
  EXPECT_EQ(j["identity"]["serial_number"], 123456789);
  EXPECT_EQ(j["identity"]["product_name"], "OpENer PC");
  std::map<int, int> sizes;
  for (const auto& a : j["assemblies"]) sizes[a["instance"]] = a["size"];
  EXPECT_EQ(sizes[100], 32);
  EXPECT_EQ(sizes[150], 32);
  EXPECT_EQ(sizes[151], 10);
  ASSERT_EQ(j["library"].size(), 1u);
  EXPECT_EQ(j["library"][0]["keying"], "exact");
  const auto text = run_edsc("probe " + device() + " --udp --timeout 5");
  EXPECT_EQ(text.status, 0) << text.output;
  EXPECT_NE(text.output.find("product name  \"OpENer PC\""), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("service       \"Communications\""), std::string::npos) << text.output;
}

// OpENer keeps no File object: the upload is refused in words, exit 2,
// and no file is left behind (the probe's own findings still print).
TEST_F(live_opener, upload_eds_from_a_device_without_a_file_object_is_refused) {
  const auto out = net_->dir + "/uploaded.eds";
  const auto r = run_edsc("probe " + device() + " --upload-eds " + quoted(out));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("product name  \"OpENer PC\""), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("upload of the EDS from the device: Initiate_Upload of the File object refused: 0x"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out));
}

struct fault {
  const char* name;
  const char* set;     // the edit
  const char* needle;  // text of the edited line
  const char* after;   // the line is after the first line holding this
  const char* expect;  // in the diagnostic
  int status = 1;      // edsc's exit status: 1 errors, 0 warnings only
};

// Named in test listings by its name, not by its bytes (which hold pointers).
void PrintTo(const fault& f, std::ostream* os) { *os << f.name; }

class live_opener_fault : public live_opener, public ::testing::WithParamInterface<fault> {};

TEST_P(live_opener_fault, is_reported_at_the_edited_line_with_the_device_status) {
  const auto& f = GetParam();
  const auto path = faulty_copy(f.set);
  const auto line = line_of(path, f.needle, f.after);
  ASSERT_NE(line, 0u) << f.needle;
  const auto r = run_edsc("verify --live " + device() + " " + quoted(path) + " --connections --color never");
  EXPECT_EQ(r.status, f.status) << r.output;
  const auto where = path + ":" + std::to_string(line) + ":";
  bool found = false;
  for (std::size_t at = r.output.find(where); at != std::string::npos; at = r.output.find(where, at + 1)) {
    const auto msg = r.output.substr(at, r.output.find('\n', at) - at);
    found = found || msg.find(f.expect) != std::string::npos;
  }
  EXPECT_TRUE(found) << "expected \"" << f.expect << "\" at " << where << "\n" << r.output;
}

const fault faults[] = {
    {"wrong_product_code", "Device.ProdCode=65002", "ProdCode = 65002", "", "0x0114"},
    {"wrong_major_revision", "Device.MajRev=3", "MajRev = 3", "", "0x0116"},
    {"ot_size_33", "Connection Manager.Connection1.ot_size=33", "Param4,33,Assem150", "Connection1",
     "extended 0x0127 invalid O->T size (additional 0x0026): the device accepts 38 bytes O->T; the EDS says 33 + 2 "
     "sequence + 4 run/idle = 39 (with the same headers, the device wants 32 data bytes)"},
    {"to_size_16", "Connection Manager.Connection1.to_size=16", "Param4,16,Assem100", "Connection1",
     "extended 0x0128 invalid T->O size (additional 0x0022): the device accepts 34 bytes T->O; the EDS says 16 + 2 "
     "sequence = 18 (with the same headers, the device wants 32 data bytes)"},
    {"wrong_instance_in_path", "Connection Manager.Connection1.path=\"20 04 24 97 2C 96 2C 65\"", "2C 96 2C 65",
     "Connection1", "0x012F"},
    {"config_size_refused", "Connection Manager.Connection1.target_config_size=12", ",,12", "Connection1",
     "the path names configuration instance 151 (24 97); 12 bytes of configuration data go with it"},
    {"assembly_size", "Assembly.Assem100.size=16", "16,", "Assem100", "holds 32 bytes on the device, Assem100 says 16"},
    {"minor_revision_newer", "Device.MinRev=4", "MinRev = 4", "", "compatible keying refuses it too"},
    // Assem100 gets a path of its own naming instance 101, which OpENer lacks (0x05).
    {"assembly_missing", "Assembly.Assem100.path=\"20 04 24 65 30 03\"", "20 04 24 65 30 03", "Assem100",
     "the device has no assembly instance 101 (0x05 path destination unknown), which Assem100 says it has"},
    {"minor_revision_refused", "Device.MinRev=4", "MinRev = 4", "", "0x0116 revision mismatch"},
    {"minor_revision_older", "Device.MinRev=1", "MinRev = 1", "", "compatible keying accepts it", 0},
    {"product_name", "Device.ProdName=\"OpENer\"", "ProdName = \"OpENer\"", "", "product name \"OpENer PC\"", 0},
};

INSTANTIATE_TEST_SUITE_P(faults, live_opener_fault, ::testing::ValuesIn(faults),
                         [](const auto& info) { return std::string(info.param.name); });

// An EDS whose MinRev is newer than the device's minor revision: exact and
// compatible keying both refuse the device, so a scanner keyed from the file
// never connects. An error at MinRev even without --connections.
TEST_F(live_opener, a_minor_revision_newer_than_the_device_is_an_error) {
  const auto path = faulty_copy("Device.MinRev=4");
  const auto r = run_edsc("verify --live " + device() + " " + quoted(path) + " --color never");
  EXPECT_EQ(r.status, 1) << r.output;
  const auto where = path + ":" + std::to_string(line_of(path, "MinRev = 4")) + ":";
  const auto at = r.output.find(where);
  ASSERT_NE(at, std::string::npos) << r.output;
  const auto message = r.output.substr(at, r.output.find('\n', at) - at);
  EXPECT_NE(message.find(": error: the device reports revision 2.3, the EDS says 2.4: exact keying refuses it, "
                         "compatible keying refuses it too"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(message.ends_with("[live-identity]")) << message;
}

// Another scanner holds Connection1 (the test itself, from the host, with an
// originator of its own and a timeout long enough for the run): OpENer
// refuses edsc's Connection1 with 0x0106. That is the device being busy,
// not the EDS being wrong: no diagnostic, a message, exit 2; Connection2
// (input only) is still opened and checked.
TEST_F(live_opener, an_owned_device_is_busy_not_wrong) {
  auto to = net::resolve(device(), 44818);
  ASSERT_TRUE(to.ok());
  auto opened = live::client::open(*to, std::chrono::seconds(3));
  ASSERT_TRUE(opened.ok());
  auto& owner = *opened;
  auto fo = opener_connection1_request();
  fo.originator_vendor = 0x1234;  // not edsc's
  fo.originator_serial = 0x600D;
  fo.timeout_multiplier = 7;  // x512: 15 s at 30 ms
  const auto reply = owner.request_raw(cip::service::forward_open, cip::encode_forward_open(fo).value());
  ASSERT_TRUE(reply.ok());
  ASSERT_EQ(reply->general, 0);

  const auto r = run_edsc("verify --live " + device() + " " + quoted(opener_eds) + " --connections --color never");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output.find("[live-connection-refused]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("0 errors"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(": error: " + device() +
                          " is busy: Connection1 not checked: the device refused it with "
                          "0x01 connection failure, extended 0x0106 ownership conflict"),
            std::string::npos)
      << r.output;
  const auto c2 = r.output.find("\nConnection2 ");
  ASSERT_NE(c2, std::string::npos) << r.output;
  EXPECT_TRUE(r.output.substr(c2 + 1, r.output.find('\n', c2 + 1) - c2 - 1).ends_with(" match")) << r.output;

  cip::forward_close_request fc;
  fc.connection_serial = fo.connection_serial;
  fc.originator_vendor = fo.originator_vendor;
  fc.originator_serial = fo.originator_serial;
  fc.path = unhex("20 04 24 97 2C 96 2C 64");
  (void)owner.request_raw(cip::service::forward_close, cip::encode_forward_close(fc).value());
}

// The Identity object's extended device status (bits 4-7 of attribute 5):
// 6 or 7 once OpENer has had an I/O connection (it keeps saying so after
// the connection is closed, so this tells only that one was opened).
bool has_had_io_connection(const std::string& ip) {
  auto to = net::resolve(ip, 44818);
  if (!to) return false;
  auto s = live::client::open(*to, std::chrono::seconds(1));
  if (!s) return false;
  const auto id = live::read_identity(*s);
  if (!id) return false;
  const auto ext = (id->status >> 4) & 0xF;
  return ext == 6 || ext == 7;
}

// Ctrl-C while edsc watches Connection1: on the wire (tcpdump on the
// device's side, read by tshark) a Forward_Close follows, which OpENer
// answers with success; edsc prints the checks made and exits 130.
TEST_F(live_opener, ctrl_c_closes_the_open_connection_on_the_wire) {
  if (shell("command -v tcpdump >/dev/null && command -v tshark >/dev/null").status != 0)
    GTEST_SKIP() << "tcpdump or tshark is missing (Debian packages tcpdump, tshark)";
  const auto pcap = net_->dir + "/interrupted.pcap";
  const auto dump = net_->capture(pcap);
  ASSERT_GT(dump, 0);
  edsc_child edsc({"verify", "--live", device(), opener_eds, "--connections", "--watch", "30", "--color", "never"},
                  net_->dir + "/verify.log");
  ASSERT_TRUE(edsc.started());
  bool open = false;
  for (int i = 0; i < 100 && !(open = has_had_io_connection(device())); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(open) << "OpENer never reported an I/O connection";
  edsc.signal(SIGINT);
  const auto r = edsc.finish();
  EXPECT_EQ(r.status, 130) << r.output;
  EXPECT_NE(r.output.find("\nVendCode "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("; interrupted after "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("interrupted by SIGINT"), std::string::npos) << r.output;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  net_->stop(dump, SIGINT);
  // Forward_Close (service 0x4E): edsc's request (0) and OpENer's reply (1), status 0.
  const auto fc =
      shell("tshark -r " + quoted(pcap) + " -Y 'cip.sc == 0x4e' -T fields -e cip.rr -e cip.genstat 2>/dev/null");
  EXPECT_NE(fc.out.find("0\t\n"), std::string::npos) << fc.out;
  EXPECT_NE(fc.out.find("1\t0"), std::string::npos) << fc.out;
}

// The identity fields as tshark prints them (-T fields, separator ",").
std::string tshark_identity(const nlohmann::json& i) {
  char serial[16], vendor[8];
  std::snprintf(serial, sizeof serial, "0x%08x", i["serial_number"].get<unsigned>());
  std::snprintf(vendor, sizeof vendor, "0x%04x", i["vendor_id"].get<unsigned>());
  return std::string(vendor) + "," + std::to_string(i["device_type"].get<int>()) + "," +
         std::to_string(i["product_code"].get<int>()) + "," + serial + "," + i["product_name"].get<std::string>() +
         "\n";
}

TEST_F(live_opener, a_captured_session_decodes_in_tshark_with_the_same_identity) {
  if (shell("command -v tcpdump >/dev/null && command -v tshark >/dev/null").status != 0)
    GTEST_SKIP() << "tcpdump or tshark is missing (Debian packages tcpdump, tshark)";
  const auto pcap = net_->dir + "/session.pcap";
  const auto dump = net_->capture(pcap);
  ASSERT_GT(dump, 0);
  const auto probe = run_edsc("probe " + device() + " --udp --timeout 5 --format json");
  ASSERT_EQ(probe.status, 0) << probe.output;
  const auto verify = run_edsc("verify --live " + device() + " " + quoted(opener_eds) + " --connections");
  EXPECT_EQ(verify.status, 0) << verify.output;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  net_->stop(dump, SIGINT);
  const auto base = "tshark -r " + quoted(pcap) + " -d udp.port==2222,cipio ";
  const auto all = shell(base + "2>/dev/null | wc -l");
  EXPECT_GT(std::stoi(all.out), 20) << "too few packets captured; tcpdump said: "
                                    << shell("cat " + net_->dir + "/tcpdump.log").out;
  const auto malformed = shell(base + "-Y '_ws.malformed || _ws.expert.severity >= error' 2>/dev/null");
  EXPECT_EQ(malformed.out, "") << malformed.out;
  const auto j = nlohmann::json::parse(probe.output, nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  const auto id = shell(base +
                        "-Y enip.lir.name -T fields -E separator=, -e enip.lir.vendor -e enip.lir.devtype "
                        "-e enip.lir.prodcode -e enip.lir.serial -e enip.lir.name 2>/dev/null");
  const auto& i = j["identity"];
  EXPECT_EQ(id.out, tshark_identity(i)) << id.out;
  // Frames of Connection1 went both ways on UDP 2222.
  const auto io = shell(base + "-Y 'udp.port==2222 && enip.cpf.sai.connid' 2>/dev/null | wc -l");
  EXPECT_GT(std::stoi(io.out), 4) << io.out;
}

}  // namespace
}  // namespace edsc::live_test
