// `edsc header`, `header --stack opener` and `edsc sim` refuse a file in which
// an entry (or a section) they read is written twice: `check` calls that an
// error (duplicate-entry, duplicate-section), and building from one of the
// two values would hide it. Every field each of them takes from the file is
// tried, with a conflicting and with an identical second value; a field none
// of them reads is not a reason to refuse.
#include <gtest/gtest.h>

#include "emit_support.hpp"
#include "test_paths.hpp"

using namespace edsc::test;

namespace {

// [File] and [Device] of a device of `type` (its name in `type_name`).
std::string identity(int type, const std::string& type_name, int code) {
  return R"([File]
DescText = "emitter needs";
CreateDate = 01-01-2020;
CreateTime = 00:00:00;
ModDate = 01-01-2020;
ModTime = 00:00:00;
Revision = 1.2;

[Device]
VendCode = 65535;
VendName = "edsc-example";
ProdType = )" +
         std::to_string(type) + ";\nProdTypeStr = \"" + type_name + "\";\nProdCode = " + std::to_string(code) +
         R"(;
MajRev = 1;
MinRev = 1;
ProdName = "emitter needs";
Catalog = "EN-1";

)";
}

// An EtherNet/IP adapter with everything header, stack and simulator read:
// identity, networks, a parameter with its enumeration, [ParamClass], the
// assemblies and connection of an exclusive owner, [Capacity].
const std::string eip_eds = identity(12, "Communications Adapter", 2) + R"([Device Classification]
Class1 = EtherNetIP;

[ParamClass]
Descriptor = 0x0003;
CfgAssembly = 0;

[Params]
Param1 = 0,,,0x0002,0xC6,1,"Mode","","",0,9,1,,,,,,,,,;
Enum1 = 1,"one",4,"four";

[Assembly]
Assem100 = "Input", "", 4, 0x0000,,;
Assem150 = "Output", "", 2, 0x0000,,;

[Connection Manager]
Connection1 = 0x04010002, 0x44640405, , 2, Assem150, , 4, Assem100, , , , , "Exclusive Owner", "",
              "20 04 24 97 2C 96 2C 64";

[Port]
Port1 = TCP, "EtherNet/IP Port", "20 F5 24 01", 2;

[Capacity]
MaxIOConnections = 1;
MaxMsgConnections = 2;
TSpec1 = TxRx, 4, 1000;
)";

// A DeviceNet node: [IO_Info] is what the header reads of it.
const std::string dnet_eds = identity(7, "General Purpose Discrete I/O", 3) + R"([Device Classification]
Class1 = DeviceNet;

[IO_Info]
Default = 0x0001;
PollInfo = 0x0001, 1, 1;
Input1 = 2, 0, 0x0001, "Input", 6, "20 04 24 64 30 03", "";
Output1 = 1, 0, 0x0001, "Output", 6, "20 04 24 96 30 03", "";
)";

// `base` with `extra` written right after the entry `keyword` ends (its `;`).
std::string with_after(const std::string& base, const std::string& keyword, const std::string& extra) {
  const auto at = base.find("\n" + keyword + " =");
  EXPECT_NE(at, std::string::npos) << keyword;
  const auto end = base.find(";\n", at);
  return base.substr(0, end + 2) + extra + "\n" + base.substr(end + 2);
}

struct field_case {
  const char* keyword;  // the entry duplicated
  const char* second;   // the second entry, with another value
};

// What the header (and the OpENer project, built from the same facts) reads.
const field_case header_fields[] = {
    {"VendCode", "VendCode = 1;"},
    {"VendName", "VendName = \"other\";"},
    {"ProdType", "ProdType = 43;"},
    {"ProdCode", "ProdCode = 9;"},
    {"MajRev", "MajRev = 2;"},
    {"MinRev", "MinRev = 9;"},
    {"ProdName", "ProdName = \"other\";"},
    {"Catalog", "Catalog = \"other\";"},
    {"Class1", "Class1 = CompoNet;"},
    {"Param1", "Param1 = 0,,,0x0000,0xC7,2,\"Other\",\"\",\"\",0,9,1,,,,,,,,,;"},
    {"Assem100", "Assem100 = \"Input\", \"\", 8, 0x0000,,;"},
    {"Connection1",
     "Connection1 = 0x04010002, 0x44640405, , 2, Assem150, , 8, Assem100, , , , , \"Other\", \"\", "
     "\"20 04 24 97 2C 96 2C 64\";"},
    {"MaxIOConnections", "MaxIOConnections = 4;"},
};

const field_case devicenet_fields[] = {
    {"Default", "Default = 0x0004;"},
    {"PollInfo", "PollInfo = 0x0001, 0, 0;"},
    {"Input1", "Input1 = 4, 0, 0x0001, \"Input\", 6, \"20 04 24 64 30 03\", \"\";"},
    {"Output1", "Output1 = 2, 0, 0x0001, \"Output\", 6, \"20 04 24 96 30 03\", \"\";"},
};

// What the simulated device serves.
const field_case sim_fields[] = {
    {"VendCode", "VendCode = 1;"},
    {"ProdType", "ProdType = 43;"},
    {"ProdCode", "ProdCode = 9;"},
    {"MajRev", "MajRev = 2;"},
    {"MinRev", "MinRev = 9;"},
    {"ProdName", "ProdName = \"other\";"},
    {"Revision", "Revision = 2.0;"},
    {"Descriptor", "Descriptor = 0x0001;"},
    {"Param1", "Param1 = 0,,,0x0000,0xC7,2,\"Other\",\"\",\"\",0,9,1,,,,,,,,,;"},
    {"Enum1", "Enum1 = 2,\"two\";"},
    {"Assem100", "Assem100 = \"Input\", \"\", 8, 0x0000,,;"},
    {"Connection1",
     "Connection1 = 0x04010002, 0x44640405, , 2, Assem150, , 8, Assem100, , , , , \"Other\", \"\", "
     "\"20 04 24 97 2C 96 2C 64\";"},
};

// The second entry with the first one's value.
std::string same_again(const std::string& base, const std::string& keyword) {
  const auto at = base.find("\n" + keyword + " =") + 1;
  return base.substr(at, base.find(";\n", at) + 1 - at);
}

class EmitterRefusals : public ::testing::Test {
 protected:
  fs::path eds(const std::string& text) {
    const auto p = dir_.path() / ("in" + std::to_string(++n_) + ".eds");
    write_text(p, text);
    return p;
  }
  command_result edsc(const std::string& args) { return run_shell(edsc_command() + " " + args); }

  // `header` refuses: exit 1, the duplicate shown, no header written and an
  // existing one left as it was.
  void expect_header_refuses(const std::string& text, const char* rule, const std::string& what) {
    const auto in = eds(text);
    const auto out = dir_.path() / "new.h";
    auto r = edsc("header " + quoted(in) + " -o " + quoted(out));
    EXPECT_EQ(r.status, 1) << what << "\n" << r.output;
    EXPECT_NE(r.output.find(std::string("[") + rule + "]"), std::string::npos) << what << "\n" << r.output;
    EXPECT_FALSE(fs::exists(out)) << what;
    const auto kept = dir_.path() / "kept.h";
    write_text(kept, "old");
    r = edsc("header " + quoted(in) + " -o " + quoted(kept));
    EXPECT_EQ(r.status, 1) << what;
    EXPECT_EQ(read_text(kept), "old") << what;
    const auto project = dir_.path() / "project";
    r = edsc("header --stack opener " + quoted(in) + " -o " + quoted(project));
    EXPECT_EQ(r.status, 1) << what << "\n" << r.output;
    EXPECT_NE(r.output.find(std::string("[") + rule + "]"), std::string::npos) << what << "\n" << r.output;
    EXPECT_FALSE(fs::exists(project)) << what;
  }

  // `sim` refuses before it opens a socket: exit 1 and the duplicate shown.
  // Started, it would fail to bind an address no interface has (exit 2).
  command_result sim(const std::string& text) { return edsc("sim " + quoted(eds(text)) + " --address 198.51.100.1"); }

  temp_dir dir_{"emitter-refusals"};
  int n_ = 0;
};

TEST_F(EmitterRefusals, TheBaseFilesAreServed) {
  for (const auto* base : {&eip_eds, &dnet_eds}) {
    const auto in = eds(*base);
    auto r = edsc("check " + quoted(in));
    EXPECT_EQ(r.status, 0) << r.output;
    r = edsc("header " + quoted(in) + " -o " + quoted(dir_.path() / "ok.h"));
    EXPECT_EQ(r.status, 0) << r.output;
  }
  const auto r = edsc("header --stack opener " + quoted(eds(eip_eds)) + " -o " + quoted(dir_.path() / "project"));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir_.path() / "project"));
  const auto s = sim(eip_eds);
  EXPECT_EQ(s.status, 2) << s.output;  // it got as far as the socket
}

TEST_F(EmitterRefusals, HeaderAndStackRefuseEveryFieldTheyReadTwice) {
  for (const auto& f : header_fields) {
    expect_header_refuses(with_after(eip_eds, f.keyword, f.second), "duplicate-entry", f.keyword);
    expect_header_refuses(with_after(eip_eds, f.keyword, same_again(eip_eds, f.keyword)), "duplicate-entry",
                          std::string(f.keyword) + " (same value)");
  }
}

TEST_F(EmitterRefusals, HeaderRefusesDeviceNetIoReadTwice) {
  for (const auto& f : devicenet_fields)
    expect_header_refuses(with_after(dnet_eds, f.keyword, f.second), "duplicate-entry", f.keyword);
}

TEST_F(EmitterRefusals, SectionsTheyReadWrittenTwice) {
  for (const char* section : {"[Device]\nVendCode = 1;\n", "[Connection Manager]\n", "[Params]\n", "[Assembly]\n"})
    expect_header_refuses(std::string(eip_eds) + section, "duplicate-section", section);
  for (const char* section : {"[Device]\nVendCode = 1;\n", "[Params]\n", "[File]\n"}) {
    const auto r = sim(std::string(eip_eds) + section);
    EXPECT_EQ(r.status, 1) << section << r.output;
    EXPECT_NE(r.output.find("[duplicate-section]"), std::string::npos) << section << r.output;
  }
}

TEST_F(EmitterRefusals, SimRefusesEveryFieldItServesTwice) {
  for (const auto& f : sim_fields) {
    for (const auto& second : {std::string(f.second), same_again(eip_eds, f.keyword)}) {
      const auto r = sim(with_after(eip_eds, f.keyword, second));
      EXPECT_EQ(r.status, 1) << f.keyword << ": " << second << "\n" << r.output;
      EXPECT_NE(r.output.find("[duplicate-entry]"), std::string::npos) << f.keyword << "\n" << r.output;
      EXPECT_EQ(r.output.find("listening"), std::string::npos) << f.keyword;
    }
  }
}

// `check` calls any duplicate an error; a field none of these commands reads
// (ProdTypeStr, DescText, a [Port]) does not stop them.
TEST_F(EmitterRefusals, FieldsTheyDoNotReadDoNotStopThem) {
  for (const auto& [keyword, second] :
       {std::pair{"ProdTypeStr", "ProdTypeStr = \"other\";"}, std::pair{"DescText", "DescText = \"other\";"},
        std::pair{"Port1", "Port1 = TCP, \"other\", \"20 F5 24 01\", 2;"}}) {
    const auto in = eds(with_after(eip_eds, keyword, second));
    EXPECT_EQ(edsc("check " + quoted(in)).status, 1) << keyword;
    const auto r = edsc("header " + quoted(in) + " -o " + quoted(dir_.path() / "ok.h"));
    EXPECT_EQ(r.status, 0) << keyword << "\n" << r.output;
    EXPECT_EQ(edsc("sim " + quoted(in) + " --address 198.51.100.1").status, 2) << keyword;
  }
}

}  // namespace
