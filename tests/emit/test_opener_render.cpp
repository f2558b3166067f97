// render_opener (`edsc header --stack opener`) without building OpENer: the
// lines of each generated file that carry the EDS's facts, checked against
// values worked out by hand from the EDS (or the plan) the test gives, and
// OpENer's meaning of its macros and calls (opener_api.h, appcontype.c,
// devicedata.h.in): ConfigureXConnectionPoint(connection_number, output
// assembly, input assembly, configuration assembly), CreateAssemblyObject(
// instance, data, length), arrays sized by OPENER_CIP_NUM_*_CONNS.
#include <gtest/gtest.h>

#include "opener_support.hpp"

namespace edsc::test {
namespace {

// The text of the generated file called `name`.
std::string file(const std::vector<emit::opener_file>& files, const std::string& name) {
  for (const auto& f : files)
    if (f.name == name) return f.text;
  ADD_FAILURE() << "no file " << name;
  return {};
}

// True when `line` is a whole line of `text`.
bool has_line(const std::string& text, const std::string& line) {
  return text.starts_with(line + "\n") || text.find("\n" + line + "\n") != std::string::npos;
}

#define EXPECT_LINE(text, line) EXPECT_TRUE(has_line(text, line)) << "no line: " << (line) << "\nin:\n" << (text)

// four_connections(): instances 100 (16 bytes), 120 (10), 130 (32) and the
// heartbeat instances 198 and 199 with no data.
std::vector<emit::opener_file> four_connection_files() {
  const auto c = plan_connections(four_connections());
  EXPECT_TRUE(c->diags.empty());
  return emit::render_opener(c->plan);
}

TEST(OpenerRender, FiveFilesInTheOrderTheyAreWritten) {
  std::vector<std::string> names;
  for (const auto& f : four_connection_files()) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"opener_identity.cmake", "opener_user_conf.h", "edsc_opener_app.h",
                                             "edsc_opener_app.c", "CMakeLists.txt"}));
}

TEST(OpenerRender, TheIdentityIsOpENersCacheVariables) {
  const auto text = file(four_connection_files(), "opener_identity.cmake");
  // [Device] of opener_support.hpp: VendCode 1234, ProdType 12, ProdCode 4321, 2.7, "Widget".
  EXPECT_LINE(text, "set(OpENer_Device_Config_Vendor_Id 1234 CACHE STRING \"[Device] VendCode\" FORCE)");
  EXPECT_LINE(text, "set(OpENer_Device_Config_Device_Type 12 CACHE STRING \"[Device] ProdType\" FORCE)");
  EXPECT_LINE(text, "set(OpENer_Device_Config_Product_Code 4321 CACHE STRING \"[Device] ProdCode\" FORCE)");
  EXPECT_LINE(text, "set(OpENer_Device_Config_Device_Name \"Widget\" CACHE STRING \"[Device] ProdName\" FORCE)");
  EXPECT_LINE(text, "set(OpENer_Device_Major_Version 2 CACHE STRING \"[Device] MajRev\" FORCE)");
  EXPECT_LINE(text, "set(OpENer_Device_Minor_Version 7 CACHE STRING \"[Device] MinRev\" FORCE)");
}

TEST(OpenerRender, IdentityNumbersAtTheTopOfTheirRanges) {
  emit::opener_plan p;
  p.identity.vendor_id = 65535;
  p.identity.device_type = 65535;
  p.identity.product_code = 65535;
  p.identity.major_revision = 255;
  p.identity.minor_revision = 255;
  const auto text = file(emit::render_opener(p), "opener_identity.cmake");
  EXPECT_LINE(text, "set(OpENer_Device_Config_Vendor_Id 65535 CACHE STRING \"[Device] VendCode\" FORCE)");
  EXPECT_LINE(text, "set(OpENer_Device_Config_Device_Type 65535 CACHE STRING \"[Device] ProdType\" FORCE)");
  EXPECT_LINE(text, "set(OpENer_Device_Config_Product_Code 65535 CACHE STRING \"[Device] ProdCode\" FORCE)");
  EXPECT_LINE(text, "set(OpENer_Device_Major_Version 255 CACHE STRING \"[Device] MajRev\" FORCE)");
  EXPECT_LINE(text, "set(OpENer_Device_Minor_Version 255 CACHE STRING \"[Device] MinRev\" FORCE)");
}

TEST(OpenerRender, TheNameIsEscapedForCAndThenForCMake) {
  // devicedata.h pastes the cache value between quotes, so it is the inside
  // of a C literal: `"` -> \", `\` -> \\, `?` -> \? (no trigraph), a byte
  // outside ASCII -> octal (ü is C3 BC: \303\274); `$` is plain C. CMake
  // then needs `\`, `"` and `$` escaped once more.
  emit::opener_plan p;
  p.identity.product_name = "a\"b\\c?d$e\xC3\xBC";
  const auto text = file(emit::render_opener(p), "opener_identity.cmake");
  EXPECT_LINE(
      text,
      R"(set(OpENer_Device_Config_Device_Name "a\\\"b\\\\c\\?d\$e\\303\\274" CACHE STRING "[Device] ProdName" FORCE))");
}

TEST(OpenerRender, TheNameFromAnEdsStringReachesCMakeEscaped) {
  // The EDS string "Say \"hi\"" holds Say "hi".
  const auto c = plan_eds(device_section(R"("Say \"hi\"")") + assembly_section() + connection_manager({conn{}}));
  ASSERT_TRUE(c->diags.empty());
  EXPECT_EQ(c->plan.identity.product_name, "Say \"hi\"");
  const auto text = file(emit::render_opener(c->plan), "opener_identity.cmake");
  EXPECT_LINE(text, R"(set(OpENer_Device_Config_Device_Name "Say \\\"hi\\\"" CACHE STRING "[Device] ProdName" FORCE))");
}

TEST(OpenerRender, TheBannerNamesTheSourceAndCannotCloseAComment) {
  emit::opener_plan p;
  p.source_name = "dir*/x\n.eds";
  p.source_sha256 = "0123abcd";
  const auto files = emit::render_opener(p);
  // In C comments `*/` becomes `* /` and a control byte `?`.
  for (const auto* name : {"opener_user_conf.h", "edsc_opener_app.h", "edsc_opener_app.c"}) {
    SCOPED_TRACE(name);
    const auto text = file(files, name);
    EXPECT_TRUE(
        text.starts_with("/* Generated by `edsc header --stack opener` from dir* /x?.eds\n * (sha256 0123abcd).\n"
                         " * Do not edit: regenerate."))
        << text.substr(0, 200);
    // The banner's own `*/` is the first one.
    EXPECT_EQ(text.find("*/"), text.find("names the hooks). */\n") + std::string("names the hooks). ").size());
  }
  // In CMake comments the line ends the comment: only the newline matters.
  for (const auto* name : {"opener_identity.cmake", "CMakeLists.txt"}) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(file(files, name)
                    .starts_with("# Generated by `edsc header --stack opener` from dir* /x?.eds\n# (sha256 "
                                 "0123abcd).\n# Do not edit: regenerate."));
  }
}

TEST(OpenerRender, ConnectionCountsSizeOpENersArraysAtLeastOne) {
  const auto text = file(four_connection_files(), "opener_user_conf.h");
  EXPECT_LINE(text, "#define OPENER_CIP_NUM_EXLUSIVE_OWNER_CONNS 1  /* exclusive-owner ConnectionN: 1 */");
  EXPECT_LINE(text, "#define OPENER_CIP_NUM_INPUT_ONLY_CONNS 2  /* input-only ConnectionN: 2 */");
  EXPECT_LINE(text, "#define OPENER_CIP_NUM_LISTEN_ONLY_CONNS 1  /* listen-only ConnectionN: 1 */");

  // None of a kind: OpENer still gets an array of one.
  emit::opener_plan p;
  p.exclusive_owner = 0;
  p.input_only = 3;
  p.listen_only = 0;
  const auto none = file(emit::render_opener(p), "opener_user_conf.h");
  EXPECT_LINE(none, "#define OPENER_CIP_NUM_EXLUSIVE_OWNER_CONNS 1  /* exclusive-owner ConnectionN: 0 */");
  EXPECT_LINE(none, "#define OPENER_CIP_NUM_INPUT_ONLY_CONNS 3  /* input-only ConnectionN: 3 */");
  EXPECT_LINE(none, "#define OPENER_CIP_NUM_LISTEN_ONLY_CONNS 1  /* listen-only ConnectionN: 0 */");
}

TEST(OpenerRender, TheHeaderDeclaresEachAssemblyWithItsSize) {
  const auto text = file(four_connection_files(), "edsc_opener_app.h");
  EXPECT_LINE(text, "/* output assembly, instance 100 (0x64) */");
  EXPECT_LINE(text, "#define EDSC_ASSEMBLY_100_SIZE 16u");
  EXPECT_LINE(text, "extern EipUint8 edsc_assembly_100[16];");
  EXPECT_LINE(text, "/* configuration assembly, instance 120 (0x78) */");
  EXPECT_LINE(text, "#define EDSC_ASSEMBLY_120_SIZE 10u");
  EXPECT_LINE(text, "extern EipUint8 edsc_assembly_120[10];");
  EXPECT_LINE(text, "/* input assembly, instance 130 (0x82) */");
  EXPECT_LINE(text, "#define EDSC_ASSEMBLY_130_SIZE 32u");
  EXPECT_LINE(text, "extern EipUint8 edsc_assembly_130[32];");
  // A heartbeat instance has a size of 0 and no buffer (C has no empty array).
  EXPECT_LINE(text, "/* output assembly, instance 198 (0xC6) */");
  EXPECT_LINE(text, "#define EDSC_ASSEMBLY_198_SIZE 0u");
  EXPECT_EQ(text.find("edsc_assembly_198["), std::string::npos);
  EXPECT_LINE(text, "#define EDSC_ASSEMBLY_199_SIZE 0u");
  EXPECT_EQ(text.find("edsc_assembly_199["), std::string::npos);
}

TEST(OpenerRender, TheApplicationCreatesTheAssembliesAndConnectionPoints) {
  const auto text = file(four_connection_files(), "edsc_opener_app.c");
  EXPECT_LINE(text, "EipUint8 edsc_assembly_100[16];");
  EXPECT_LINE(text, "EipUint8 edsc_assembly_120[10];");
  EXPECT_LINE(text, "EipUint8 edsc_assembly_130[32];");
  EXPECT_EQ(text.find("edsc_assembly_198"), std::string::npos);
  EXPECT_LINE(text,
              "  CreateAssemblyObject(100, edsc_assembly_100, (EipUint16)sizeof edsc_assembly_100);  /* output */");
  EXPECT_LINE(
      text,
      "  CreateAssemblyObject(120, edsc_assembly_120, (EipUint16)sizeof edsc_assembly_120);  /* configuration */");
  EXPECT_LINE(text,
              "  CreateAssemblyObject(130, edsc_assembly_130, (EipUint16)sizeof edsc_assembly_130);  /* input */");
  EXPECT_LINE(text, "  CreateAssemblyObject(198, NULL, 0);  /* output, no data */");
  EXPECT_LINE(text, "  CreateAssemblyObject(199, NULL, 0);  /* output, no data */");
  // connection_number counted per kind, then output, input, configuration.
  EXPECT_LINE(text, "  ConfigureExclusiveOwnerConnectionPoint(0, 100, 130, 120);  /* Connection1 Owner */");
  EXPECT_LINE(text, "  ConfigureInputOnlyConnectionPoint(0, 198, 130, 120);  /* Connection2 In1 */");
  EXPECT_LINE(text, "  ConfigureListenOnlyConnectionPoint(0, 199, 130, 120);  /* Connection3 Listen */");
  EXPECT_LINE(text, "  ConfigureInputOnlyConnectionPoint(1, 198, 130, 120);  /* Connection4 In2 */");
  // The assemblies exist before a connection point names them.
  EXPECT_LT(text.find("CreateAssemblyObject(199"), text.find("ConfigureExclusiveOwnerConnectionPoint"));
}

TEST(OpenerRender, AConnectionNameCannotEndItsComment) {
  emit::opener_plan p;
  p.assemblies.push_back({101, 4, "input"});
  p.points.push_back({model::app_type::exclusive_owner, 0, 7, "x */ y\tz", 150, 101, 151});
  const auto text = file(emit::render_opener(p), "edsc_opener_app.c");
  EXPECT_LINE(text, "  ConfigureExclusiveOwnerConnectionPoint(0, 150, 101, 151);  /* Connection7 x * / y?z */");
}

TEST(OpenerRender, RunIdleHeadersAreTheProjectsBuildOptions) {
  emit::opener_plan p;
  p.consumed_run_idle = true;
  p.produced_run_idle = false;
  auto text = file(emit::render_opener(p), "CMakeLists.txt");
  EXPECT_LINE(text,
              "set(OPENER_CONSUMED_DATA_HAS_RUN_IDLE_HEADER ON CACHE BOOL \"O->T data has a run/idle header "
              "(EDS)\" FORCE)");
  EXPECT_LINE(text,
              "set(OPENER_PRODUCED_DATA_HAS_RUN_IDLE_HEADER OFF CACHE BOOL \"T->O data has a run/idle header "
              "(EDS)\" FORCE)");
  p.consumed_run_idle = false;
  p.produced_run_idle = true;
  text = file(emit::render_opener(p), "CMakeLists.txt");
  EXPECT_LINE(text,
              "set(OPENER_CONSUMED_DATA_HAS_RUN_IDLE_HEADER OFF CACHE BOOL \"O->T data has a run/idle header "
              "(EDS)\" FORCE)");
  EXPECT_LINE(text,
              "set(OPENER_PRODUCED_DATA_HAS_RUN_IDLE_HEADER ON CACHE BOOL \"T->O data has a run/idle header "
              "(EDS)\" FORCE)");
}

TEST(OpenerRender, TheRpisDoNotReachTheProject) {
  // OpENer takes the RPI from each Forward_Open; the EDS's (10 ms here, 50
  // ms in the copy) configure nothing, so the files are the same.
  auto slow_text = device_section() + assembly_section() + connection_manager({conn{}});
  for (auto at = slow_text.find("10000"); at != std::string::npos; at = slow_text.find("10000", at))
    slow_text.replace(at, 5, "50000");
  const auto fast = plan_connections({conn{}});
  const auto slow = plan_eds(slow_text);
  ASSERT_TRUE(slow->diags.empty());
  const auto a = emit::render_opener(fast->plan), b = emit::render_opener(slow->plan);
  ASSERT_EQ(a.size(), b.size());
  // Only the banner's sha256 differs: the source bytes do.
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE(a[i].name);
    auto strip = [](std::string s, const std::string& sha) { return s.replace(s.find(sha), sha.size(), ""); };
    EXPECT_EQ(strip(a[i].text, fast->plan.source_sha256), strip(b[i].text, slow->plan.source_sha256));
  }
}

}  // namespace
}  // namespace edsc::test
