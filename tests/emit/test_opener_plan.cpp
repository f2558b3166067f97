// plan_opener (`edsc header --stack opener`) without OpENer: the assemblies,
// connection points and build options it derives from an EDS, and each
// opener-* diagnostic with its severity and where it points. Every expected
// value is worked out from the EDS text of the test (docs: EDS_FORMAT.md for
// the ConnectionN fields, catalogue_opener.def for what OpENer cannot serve).
#include <gtest/gtest.h>

#include <tuple>
#include <utility>

#include "opener_support.hpp"

namespace edsc::test {
namespace {

using model::app_type;

// "instance:size:role" per planned assembly, in the plan's order.
std::vector<std::string> assemblies(const emit::opener_plan& p) {
  std::vector<std::string> out;
  for (const auto& a : p.assemblies) out.push_back(fmt::format("{}:{}:{}", a.instance, a.size, a.role));
  return out;
}

// "kind#index ConnectionN out/in/config name" per connection point.
std::vector<std::string> points(const emit::opener_plan& p) {
  std::vector<std::string> out;
  for (const auto& pt : p.points) {
    const char* kind = pt.kind == model::app_type::exclusive_owner ? "owner"
                       : pt.kind == model::app_type::input_only    ? "input-only"
                                                                   : "listen-only";
    out.push_back(fmt::format("{}#{} Connection{} {}/{}/{} {}", kind, pt.index, pt.connection, pt.output_instance,
                              pt.input_instance, pt.config_instance, pt.name));
  }
  return out;
}

// The single diagnostic of a case: its id, severity (every opener-* finding
// is an error: no files are written), message and the text it points at.
void expect_one(const opener_case& c, diag_id id, const std::string& message, span where) {
  ASSERT_EQ(c.diags.size(), 1u) << (c.diags.empty() ? std::string("none") : c.diags[0].message);
  const auto& d = c.diags[0];
  EXPECT_EQ(d.id, id);
  EXPECT_EQ(d.level, severity::error);
  EXPECT_EQ(d.message, message);
  EXPECT_EQ(d.where, where) << "points at '" << c.src->text(d.where) << "'";
}

TEST(OpenerPlan, AnExclusiveOwnerGivesItsThreeAssembliesSortedAndOnePoint) {
  const auto c = plan_connections({conn{}});
  EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
  EXPECT_TRUE(c->issues.empty()) << c->issues[0].message;
  // Planned input 130, output 100, configuration 120; listed by instance.
  EXPECT_EQ(assemblies(c->plan), (std::vector<std::string>{"100:16:output", "120:10:configuration", "130:32:input"}));
  EXPECT_EQ(points(c->plan), (std::vector<std::string>{"owner#0 Connection1 100/130/120 Owner"}));
  EXPECT_EQ(c->plan.exclusive_owner, 1u);
  EXPECT_EQ(c->plan.input_only, 0u);
  EXPECT_EQ(c->plan.listen_only, 0u);
  // 0x44640405: O->T format (bits 8-10) 4 = run/idle header, T->O format (bits 12-14) 0.
  EXPECT_TRUE(c->plan.consumed_run_idle);
  EXPECT_FALSE(c->plan.produced_run_idle);
}

TEST(OpenerPlan, IdentityAndSourceComeFromTheDeviceSection) {
  const auto c = plan_connections({conn{}});
  EXPECT_EQ(c->plan.identity.vendor_id, 1234);
  EXPECT_EQ(c->plan.identity.device_type, 12);
  EXPECT_EQ(c->plan.identity.product_code, 4321);
  EXPECT_EQ(c->plan.identity.major_revision, 2);
  EXPECT_EQ(c->plan.identity.minor_revision, 7);
  EXPECT_EQ(c->plan.identity.product_name, "Widget");
  EXPECT_EQ(c->plan.source_name, "opener-unit.eds");
  EXPECT_EQ(c->plan.source_sha256.size(), 64u);
}

TEST(OpenerPlan, EachKindIsCountedFromZeroAndHeartbeatInstancesHaveNoData) {
  // Connection4 names configuration 120 with no size: 0 bytes there leaves
  // the 10 bytes Connection1 gave it.
  const auto c = plan_connections(four_connections());
  EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
  EXPECT_EQ(assemblies(c->plan), (std::vector<std::string>{"100:16:output", "120:10:configuration", "130:32:input",
                                                           "198:0:output", "199:0:output"}));
  EXPECT_EQ(points(c->plan),
            (std::vector<std::string>{
                "owner#0 Connection1 100/130/120 Owner", "input-only#0 Connection2 198/130/120 In1",
                "listen-only#0 Connection3 199/130/120 Listen", "input-only#1 Connection4 198/130/120 In2"}));
  EXPECT_EQ(c->plan.exclusive_owner, 1u);
  EXPECT_EQ(c->plan.input_only, 2u);
  EXPECT_EQ(c->plan.listen_only, 1u);
  // Only the owner's O->T carries data: the heartbeats' format 2 is no disagreement.
  EXPECT_TRUE(c->plan.consumed_run_idle);
}

TEST(OpenerPlan, AConnectionWithoutConfigurationNamesInstance0AndPlansNoAssemblyForIt) {
  // No 0x24 segment and no configuration format: OpENer's configuration
  // assembly id is 0, which is no instance to create.
  conn c1{.config_format = "", .path = "\"20 04 2C 64 2C 82\""};
  const auto c = plan_connections({c1});
  EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
  EXPECT_EQ(assemblies(c->plan), (std::vector<std::string>{"100:16:output", "130:32:input"}));
  EXPECT_EQ(points(c->plan), (std::vector<std::string>{"owner#0 Connection1 100/130/0 Owner"}));
}

TEST(OpenerPlan, InstanceNumber1IsAnAssemblyLikeAnyOther) {
  // Configuration instance 1 (24 01), 10 bytes from Assem120.
  conn c1{.path = "\"20 04 24 01 2C 64 2C 82\""};
  const auto c = plan_connections({c1});
  EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
  EXPECT_EQ(assemblies(c->plan), (std::vector<std::string>{"1:10:configuration", "100:16:output", "130:32:input"}));
}

TEST(OpenerPlan, AHeartbeatInstanceTakesTheSizeALaterConnectionGivesIt) {
  // Connection1 (input only) names O->T instance 100 with no data; Connection2
  // (owner) sends 16 bytes to it: the instance gets 16.
  conn in{.number = 1, .trigger = "0x82010002", .params = "0x44640205", .ot_format = ""};
  conn owner{.number = 2};
  const auto c = plan_connections({in, owner});
  EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
  EXPECT_EQ(assemblies(c->plan), (std::vector<std::string>{"100:16:output", "120:10:configuration", "130:32:input"}));
}

TEST(OpenerPlan, TheTransportTypeMustBeExactlyOneOfOpENersThreeKinds) {
  const struct {
    const char* trigger;
    const char* why;
  } cases[] = {
      {"0x88010002", "redundant owner has no OpENer connection point"},  // bit 27 only
      {"0x80010002", "it names no transport type (exclusive owner, input only, listen only)"},
      {"0x86010002", "it names more than one transport type; OpENer configures one kind per point"},  // 26 + 25
      {"0x85010002", "it names more than one transport type; OpENer configures one kind per point"},  // 26 + 24
      {"0x83010002", "it names more than one transport type; OpENer configures one kind per point"},  // 25 + 24
  };
  for (const auto& k : cases) {
    SCOPED_TRACE(k.trigger);
    // Connection1 is served; Connection2 is the one in question, and the
    // finding points at its own trigger/transport field.
    conn bad{.number = 2, .trigger = k.trigger};
    const auto c = plan_connections({conn{}, bad});
    expect_one(*c, diag_id::opener_connection_kind, fmt::format("Connection2: {}", k.why), c->at(k.trigger));
    EXPECT_EQ(points(c->plan), (std::vector<std::string>{"owner#0 Connection1 100/130/120 Owner"}));
  }
}

TEST(OpenerPlan, ParametersThatAreNotANumberLeaveTheKindUnknown) {
  conn bad{.params = "Param1"};
  const auto c = plan_connections({bad});
  expect_one(*c, diag_id::opener_connection_kind,
             "Connection1: its trigger/transport is not a number OpENer's kinds can be read from", c->at("0x84010002"));
  EXPECT_TRUE(c->plan.points.empty());
  EXPECT_TRUE(c->plan.assemblies.empty());
}

TEST(OpenerPlan, PathsOpENerCannotServeAreReportedAtThePath) {
  const struct {
    const char* path;
    const char* why;
  } cases[] = {
      {"\"20 05 24 78 2C 64 2C 82\"", "its path names class 0x05; OpENer connects to assemblies (class 0x04) only"},
      {"\"01 00 20 04 24 78 2C 64 2C 82\"", "its path routes through a port; OpENer serves its own assemblies only"},
      {"\"20 04 24 78 24 64 2C 82\"",
       "its path names instance 100 with a 0x24 segment where OpENer expects a connection point (0x2C); OpENer "
       "refuses it with 0x0315"},
      {"\"20 04 24 78 2C 64 2E 00 00 00 01 00\"",
       "its path names instance 65536; OpENer numbers assembly instances in 16 bits"},
      {"\"20 04 24 SLOT 2C 64 2C 82\"", "its path holds a placeholder the tool fills in, not an instance"},
      {"\"20 04 SLOT 2C 64 2C 82\"", "its path holds a placeholder the tool fills in, not an instance"},
      {"\"20 04 91 02 41 42 2C 64 2C 82\"", "its path holds a segment OpENer does not match connection points by"},
  };
  for (const auto& k : cases) {
    SCOPED_TRACE(k.path);
    conn bad{.number = 2, .path = k.path};
    const auto c = plan_connections({conn{}, bad});
    expect_one(*c, diag_id::opener_connection_path, fmt::format("Connection2: {}", k.why), c->at(k.path));
    EXPECT_EQ(c->plan.points.size(), 1u);
  }
}

TEST(OpenerPlan, EachDirectionWithDataNeedsAnInstance) {
  // The assemblies of this file state no path, so a format gives no instance.
  {
    // One connection point (130) goes to T->O, which has a format; O->T has
    // 16 bytes (Assem100) and no instance.
    conn c1{.path = "\"20 04 24 78 2C 82\""};
    const auto c = plan_connections({c1});
    expect_one(*c, diag_id::opener_connection_path, "Connection1: its O->T data has no assembly instance in the path",
               c->at(c1.path));
  }
  {
    // No connection point; T->O has 32 bytes, O->T none.
    conn c1{.ot_format = "", .to_size = "32", .to_format = "", .path = "\"20 04 24 78\""};
    const auto c = plan_connections({c1});
    expect_one(*c, diag_id::opener_connection_path, "Connection1: its T->O data has no assembly instance in the path",
               c->at(c1.path));
  }
  {
    // Neither direction has data nor an instance.
    conn c1{.ot_format = "", .to_format = "", .path = "\"20 04 24 78\""};
    const auto c = plan_connections({c1});
    expect_one(*c, diag_id::opener_connection_path,
               "Connection1: its path names no input (T->O) instance, which every OpENer connection point needs",
               c->at(c1.path));
  }
}

TEST(OpenerPlan, APathNeedsAConnectionPointPerDirectionTheConnectionOpens) {
  // Input only (bit 25), O->T a heartbeat offered point-to-point (0x44640205:
  // bit 18), T->O multicast or point-to-point (bits 21, 22): OpENer reads two
  // points after configuration 120, and this path gives only T->O's 130.
  conn in{.trigger = "0x82010002", .params = "0x44640205", .ot_format = "", .path = "\"20 04 24 78 2C 82\""};
  {
    const auto c = plan_connections({in});
    expect_one(*c, diag_id::opener_connection_path,
               "Connection1: its path gives 1 connection point (0x2C) where OpENer reads 2, one per direction the "
               "connection opens (O->T, then T->O); OpENer refuses it with 0x0315",
               c->at(in.path));
    EXPECT_TRUE(c->plan.points.empty());
  }
  {
    // O->T offered null only (0x44610205: bit 16): one direction, one point.
    in.params = "0x44610205";
    const auto c = plan_connections({in});
    EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
    EXPECT_EQ(points(c->plan), (std::vector<std::string>{"input-only#0 Connection1 0/130/120 Owner"}));
  }
  {
    // An owner whose output instance its assembly's own path gives (150),
    // with a path of the configuration instance and one point.
    conn owner{.ot_format = "Assem150", .config_format = "", .path = "\"20 04 24 96 2C 82\""};
    const auto c = plan_connections({owner}, "    Assem150 = \"Out2\", \"20 04 24 96 30 03\", 16, 0x0001, , ;\n");
    expect_one(*c, diag_id::opener_connection_path,
               "Connection1: its path gives 1 connection point (0x2C) where OpENer reads 2, one per direction the "
               "connection opens (O->T, then T->O); OpENer refuses it with 0x0315",
               c->at(owner.path));
  }
}

TEST(OpenerPlan, AConnectionWithoutAPathIsReportedAtItsEntry) {
  const std::string entry =
      "Connection1 = 0x84010002, 0x44640405, 10000, , Assem100, 10000, , Assem130, , , , "
      "Assem120, \"Owner\", \"\";";
  const auto c = plan_eds(device_section() + assembly_section() + "[Connection Manager]\n    " + entry + "\n");
  ASSERT_EQ(c->diags.size(), 1u);
  EXPECT_EQ(c->diags[0].id, diag_id::opener_connection_path);
  EXPECT_EQ(c->diags[0].level, severity::error);
  EXPECT_EQ(c->diags[0].message, "Connection1: it has no path OpENer could match a Forward_Open against");
  // The entry, not a field: it starts where the keyword does.
  EXPECT_EQ(c->diags[0].where.begin, c->at("Connection1").begin);
  EXPECT_GT(c->diags[0].where.size(), 0u);
}

TEST(OpenerPlan, InstancesUpTo0xFFFFAreServed) {
  // A 16-bit connection point (2D, pad, FF FF) for T->O, which states 32 bytes.
  conn c1{.to_size = "32", .to_format = "", .path = "\"20 04 24 78 2C 64 2D 00 FF FF\""};
  const auto c = plan_connections({c1});
  EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
  EXPECT_EQ(assemblies(c->plan), (std::vector<std::string>{"100:16:output", "120:10:configuration", "65535:32:input"}));
}

TEST(OpenerPlan, OpENersBufferGrowsWithTheLargestAssemblyOnly) {
  // 64 bytes of headers around the data: 448 fits OpENer's default 512 bytes,
  // 449 needs 513, and the larger of input and output decides.
  const auto buffer = [](conn c1) { return plan_connections({c1})->plan.ethernet_buffer_bytes; };
  EXPECT_EQ(buffer(conn{.to_size = "448", .to_format = ""}), 512u);
  EXPECT_EQ(buffer(conn{.to_size = "449", .to_format = ""}), 513u);
  EXPECT_EQ(buffer(conn{.ot_size = "600", .ot_format = "", .to_size = "520", .to_format = ""}), 664u);
  EXPECT_EQ(buffer(conn{.ot_size = "520", .ot_format = "", .to_size = "600", .to_format = ""}), 664u);
}

TEST(OpenerPlan, AConfigurationAssemblyGrowsTheBufferByTheForwardOpenAroundIt) {
  // Its data arrives inside the Forward_Open: 128 bytes around it, so 384
  // fits the default 512 and 385 needs 513 (as an input of 449 does).
  const auto buffer = [](const char* size) {
    conn c1{.config_format = "Assem121", .path = "\"20 04 24 79 2C 64 2C 82\""};
    return plan_connections({c1}, fmt::format("    Assem121 = \"Cfg2\", \"\", {}, 0x0001, , ;\n", size))
        ->plan.ethernet_buffer_bytes;
  };
  EXPECT_EQ(buffer("384"), 512u);
  EXPECT_EQ(buffer("385"), 513u);
  EXPECT_EQ(buffer("408"), 536u);  // the corpus file whose Forward_Open OpENer dropped at 512
}

TEST(OpenerPlan, AnAssemblyOverTheEncapsulationLengthIsRefused) {
  // The 16-bit encapsulation length less 64 bytes of headers: 65471 fits, 65472 does not.
  {
    conn c1{.to_size = "65471", .to_format = ""};
    const auto c = plan_connections({c1});
    EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
    EXPECT_EQ(assemblies(c->plan),
              (std::vector<std::string>{"100:16:output", "120:10:configuration", "130:65471:input"}));
    EXPECT_EQ(c->plan.ethernet_buffer_bytes, 65535u);
  }
  conn input_over{.to_size = "65472", .to_format = ""};
  conn output_over{.ot_size = "65472", .ot_format = ""};
  for (const auto& [c1, what] : {std::pair{input_over, "input assembly 130"}, {output_over, "output assembly 100"}}) {
    SCOPED_TRACE(what);
    const auto c = plan_connections({c1});
    expect_one(*c, diag_id::opener_assembly_size,
               fmt::format("Connection1: the {} has 65472 bytes; an OpENer message holds at most 65471", what),
               c->at("65472"));
    // The input may be planned before the output fails; no point is.
    EXPECT_TRUE(c->plan.points.empty());
  }
}

TEST(OpenerPlan, ASizeThatDiffersFromTheNamedAssemblyIsRefused) {
  conn input_20{.to_size = "20"};       // Assem130 states 32
  conn config_12{.config_size = "12"};  // Assem120 states 10
  for (const auto& [c1, size, what] :
       {std::tuple{input_20, "20", "input has 20 bytes but the assembly it names has 32"},
        {config_12, "12", "configuration has 12 bytes but the assembly it names has 10"}}) {
    SCOPED_TRACE(what);
    const auto c = plan_connections({c1});
    expect_one(*c, diag_id::opener_assembly_size,
               fmt::format("Connection1: the {}; OpENer holds one buffer per instance", what),
               c->in(fmt::format(" {},", size), size));
  }
}

TEST(OpenerPlan, AnAssemblyThatStatesNoSizeTakesTheConnections) {
  // Assem140 has neither a size nor members: 0 bytes declared, nothing to
  // disagree with; the connection's 24 bytes are the instance's.
  conn c1{.to_size = "24", .to_format = "Assem140", .path = "\"20 04 24 78 2C 64 2C 8C\""};
  const auto c = plan_connections({c1}, "    Assem140 = \"Empty\", \"\", , 0x0000, , ;\n");
  EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
  EXPECT_EQ(assemblies(c->plan), (std::vector<std::string>{"100:16:output", "120:10:configuration", "140:24:input"}));
}

TEST(OpenerPlan, TwoConnectionsGivingOneInstanceTwoSizesAreRefused) {
  // Connection2 (input only) reads T->O instance 130 as 8 bytes; Connection1 gave it 32.
  conn in{.number = 2,
          .trigger = "0x82010002",
          .params = "0x44640205",
          .ot_format = "",
          .to_size = "8",
          .to_format = "",
          .path = "\"20 04 24 78 2C C6 2C 82\""};
  const auto c = plan_connections({conn{}, in});
  expect_one(*c, diag_id::opener_assembly_size,
             "Connection2: assembly 130 has 8 bytes here but 32 as the input of an earlier connection; OpENer holds "
             "one buffer per instance",
             c->in(" 8,", "8"));
  EXPECT_EQ(points(c->plan), (std::vector<std::string>{"owner#0 Connection1 100/130/120 Owner"}));
  EXPECT_EQ(c->plan.input_only, 0u);
}

TEST(OpenerPlan, ANegativeSizeFallsBackToTheNamedAssembly) {
  // A size is an unsigned number: -16 is no size, and the format (Assem100, 16 bytes) gives it.
  conn c1{.ot_size = "-16"};
  const auto c = plan_connections({c1});
  EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
  EXPECT_EQ(assemblies(c->plan), (std::vector<std::string>{"100:16:output", "120:10:configuration", "130:32:input"}));
}

TEST(OpenerPlan, OwnersMustAgreeOnTheRunIdleHeaderOfEachDirection) {
  {
    // Connection2's O->T is modeless (0x0005: format 0), Connection1's has the header.
    conn c2{.number = 2, .params = "0x44640005"};
    const auto c = plan_connections({conn{}, c2});
    expect_one(*c, diag_id::opener_run_idle,
               "Connection2: its O->T data has no run/idle header but Connection1's has one", c->at("0x44640005"));
    EXPECT_TRUE(c->plan.consumed_run_idle);  // the first connection's choice stands
  }
  {
    // Connection2's T->O has the header (format 4 in bits 12-14), Connection1's has not.
    conn c2{.number = 2, .params = "0x44644405"};
    const auto c = plan_connections({conn{}, c2});
    expect_one(*c, diag_id::opener_run_idle,
               "Connection2: its T->O data has a run/idle header but Connection1's has none", c->at("0x44644405"));
    EXPECT_FALSE(c->plan.produced_run_idle);
  }
  {
    // All agree: the T->O header is built in, the O->T one left out.
    conn c1{.params = "0x44644005"};
    conn c2{.number = 2, .params = "0x44644005"};
    const auto c = plan_connections({c1, c2});
    EXPECT_TRUE(c->diags.empty()) << c->diags[0].message;
    EXPECT_FALSE(c->plan.consumed_run_idle);
    EXPECT_TRUE(c->plan.produced_run_idle);
  }
}

TEST(OpenerPlan, WithoutAServedConnectionOpENersDefaultsStay) {
  conn bad{.trigger = "0x80010002"};
  const auto c = plan_connections({bad});
  ASSERT_EQ(c->diags.size(), 1u);
  EXPECT_TRUE(c->plan.consumed_run_idle);
  EXPECT_FALSE(c->plan.produced_run_idle);
  EXPECT_TRUE(c->plan.assemblies.empty());
}

TEST(OpenerPlan, AFileWithoutConnectionNHasNothingToServe) {
  const std::string message = "no ConnectionN in [Connection Manager]: OpENer would have no I/O connection to serve";
  {
    const auto c = plan_eds(device_section() + assembly_section());
    expect_one(*c, diag_id::opener_no_connection, message, span{});
  }
  {
    // A proxy entry is no I/O connection of this device.
    const auto c = plan_eds(device_section() + assembly_section() +
                            "[Connection Manager]\n    ProxyConnect1 = 0x84010002, 0x44640405, 10000, , Assem100, "
                            "10000, , Assem130, , , , Assem120, \"Proxy\", \"\", \"20 04 24 78 2C 64 2C 82\";\n");
    expect_one(*c, diag_id::opener_no_connection, message, span{});
    EXPECT_TRUE(c->plan.points.empty());
  }
}

}  // namespace
}  // namespace edsc::test
