// Every verdict of `verify --live` from facts made by hand, no device: the
// comparison (judge_facts) against OpENer's sample EDS (VendCode 1, ProdType
// 12, ProdCode 65001, revision 2.3, "OpENer PC"; assemblies 150, 100, 151 of
// 32, 32, 10 bytes; Connection1 and 2 openable, Connection3 listen-only).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "edit/analyze.hpp"
#include "live/facts.hpp"
#include "test_paths.hpp"

namespace edsc::live {
namespace {

const model::device& opener() {
  static const auto a = [] {
    const auto path = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return edit::analyze(path, text.str());
  }();
  return a->dev;
}

cip::reply size_reply(std::uint8_t general, cip::bytes data) {
  cip::reply r;
  r.service = 0x8E;
  r.general = general;
  r.data = std::move(data);
  return r;
}

connection_outcome opened(unsigned frames, std::size_t wrong_size = 0) {
  connection_outcome o;
  o.opened = true;
  o.granted.to_api_us = 10'000;
  o.io.frames = frames;
  o.io.wrong_size = wrong_size ? frames : 0;
  o.io.a_wrong_size = wrong_size;
  o.io.mean_interval_us = 10'000;
  o.io.watched = std::chrono::milliseconds(300);
  return o;
}

connection_outcome refused(std::uint16_t ext) {
  connection_outcome o;
  o.general = 0x01;
  o.additional = {ext};
  return o;
}

// What the device answers when it is the EDS's twin.
live_facts matching() {
  live_facts f;
  f.connected = true;
  cip::identity id;
  id.vendor = 1, id.device_type = 12, id.product_code = 65001, id.major = 2, id.minor = 3;
  id.product_name = "OpENer PC";
  f.identity = id;
  f.assemblies = {{size_reply(0, {32, 0}), {}}, {size_reply(0, {32, 0}), {}}, {size_reply(0, {10, 0}), {}}};
  f.connections = {opened(30), opened(30), std::nullopt};
  return f;
}

std::string row_of(const live_report& r, const std::string& check) {
  for (const auto& row : r.rows)
    if (row.check == check) return row.device + " | " + std::string(to_string(row.result));
  return "(no row)";
}

std::vector<diag_id> ids(const live_report& r) {
  std::vector<diag_id> out;
  for (const auto& d : r.diags) out.push_back(d.id);
  return out;
}

TEST(live_verdicts, the_twin_of_the_eds_matches_everywhere) {
  const auto r = judge_facts(opener(), matching(), true);
  ASSERT_EQ(r.rows.size(), 11u);
  for (const auto& row : r.rows) {
    if (row.check != "Connection3") {
      EXPECT_EQ(row.result, verdict::match) << row.check;
    }
  }
  EXPECT_EQ(row_of(r, "Connection3"), "not opened | not tried");
  EXPECT_EQ(ids(r), std::vector<diag_id>{diag_id::live_not_checked});
  EXPECT_FALSE(r.failure);
  EXPECT_TRUE(r.busy.empty());
}

TEST(live_verdicts, another_vendor_is_refused_by_the_key) {
  auto f = matching();
  f.identity->vendor = 2;
  const auto r = judge_facts(opener(), f, false);
  EXPECT_EQ(row_of(r, "VendCode"), "2 | mismatch");
  EXPECT_EQ(r.diags.front().id, diag_id::live_identity);
  EXPECT_NE(r.diags.front().message.find("the device reports VendCode 2, the EDS says 1"), std::string::npos);
}

TEST(live_verdicts, a_newer_minor_revision_is_a_warning_an_older_an_error) {
  auto f = matching();
  f.identity->minor = 4;
  auto r = judge_facts(opener(), f, false);
  EXPECT_EQ(row_of(r, "MinRev"), "2.4 | mismatch");
  EXPECT_EQ(r.diags.front().id, diag_id::live_minor_revision);
  f.identity->minor = 2;
  r = judge_facts(opener(), f, false);
  EXPECT_EQ(r.diags.front().id, diag_id::live_identity);
  f.identity->minor = 3;
  f.identity->major = 3;
  r = judge_facts(opener(), f, false);
  EXPECT_EQ(row_of(r, "MajRev"), "3.3 | mismatch");
  EXPECT_EQ(r.diags.front().id, diag_id::live_identity);
}

TEST(live_verdicts, another_product_name_is_a_warning) {
  auto f = matching();
  f.identity->product_name = "OpENer";
  const auto r = judge_facts(opener(), f, false);
  EXPECT_EQ(row_of(r, "ProdName"), "\"OpENer\" | mismatch");
  EXPECT_EQ(r.diags.front().id, diag_id::live_product_name);
}

TEST(live_verdicts, assembly_sizes_missing_and_unreadable) {
  auto f = matching();
  f.assemblies[0].size = size_reply(0, {16, 0});
  f.assemblies[1] = {size_reply(0x05, {}), true};   // path destination unknown; the class answers
  f.assemblies[2] = {size_reply(0x05, {}), false};  // the same, but the class does not answer either
  const auto r = judge_facts(opener(), f, false);
  EXPECT_EQ(row_of(r, "Assem150 size (instance 150)"), "16 | mismatch");
  EXPECT_EQ(row_of(r, "Assem100 size (instance 100)"), "no such instance | mismatch");
  EXPECT_EQ(row_of(r, "Assem151 size (instance 151)"), "not readable | not readable");
  auto got = ids(r);
  std::sort(got.begin(), got.end());
  std::vector<diag_id> want{diag_id::live_assembly_size, diag_id::live_assembly_missing, diag_id::live_not_checked};
  std::sort(want.begin(), want.end());
  EXPECT_EQ(got, want);
}

TEST(live_verdicts, a_refusal_for_the_eds_is_an_error_a_busy_device_is_not) {
  auto f = matching();
  f.connections[0] = refused(0x0127);  // invalid O->T size
  f.connections[1] = refused(0x0106);  // ownership conflict
  const auto r = judge_facts(opener(), f, true);
  EXPECT_EQ(row_of(r, "Connection1"), "refused 0x01/0x0127 | mismatch");
  EXPECT_EQ(row_of(r, "Connection2"), "busy 0x01/0x0106 | not tried");
  ASSERT_EQ(r.busy.size(), 1u);
  EXPECT_NE(r.busy[0].find("another scanner owns what it connects to"), std::string::npos);
  const auto got = ids(r);
  EXPECT_EQ(std::count(got.begin(), got.end(), diag_id::live_connection_refused), 1);
}

TEST(live_verdicts, frames_of_the_wrong_size_none_at_all_or_too_slow) {
  auto f = matching();
  f.connections[0] = opened(30, 16);
  f.connections[1] = opened(0);
  auto r = judge_facts(opener(), f, true);
  EXPECT_EQ(row_of(r, "Connection1").substr(0, 20), "open; 30 frames of 1");
  EXPECT_EQ(r.rows[8].result, verdict::mismatch);
  EXPECT_EQ(r.rows[9].result, verdict::mismatch);
  auto got = ids(r);
  EXPECT_EQ(std::count(got.begin(), got.end(), diag_id::live_io_frames), 2);
  f = matching();
  f.connections[0]->io.mean_interval_us = 25'000;  // over twice the 10 ms granted
  r = judge_facts(opener(), f, true);
  got = ids(r);
  EXPECT_EQ(std::count(got.begin(), got.end(), diag_id::live_io_rate), 1);
}

TEST(live_verdicts, a_failure_midway_leaves_one_check_unfinished_and_the_rest_not_reached) {
  auto f = matching();
  f.assemblies.resize(1);
  f.connections.clear();
  f.failure = error{net::error_id::timeout, "no SendRRData reply header from the device within the timeout"};
  const auto r = judge_facts(opener(), f, true);
  EXPECT_EQ(row_of(r, "Assem150 size (instance 150)"), "32 | match");
  EXPECT_EQ(row_of(r, "Assem100 size (instance 100)"), "not finished | not tried");
  EXPECT_EQ(row_of(r, "Assem151 size (instance 151)"), "not reached | not tried");
  EXPECT_EQ(row_of(r, "Connection1"), "not reached | not tried");
  EXPECT_EQ(row_of(r, "Connection3"), "not reached | not tried");
  ASSERT_TRUE(r.failure);
  EXPECT_EQ(r.failure->id, "live-timeout");
}

TEST(live_verdicts, a_failure_after_a_watch_keeps_what_the_watch_saw) {
  auto f = matching();
  f.connections.resize(1);
  f.connections[0]->failure = error{net::error_id::closed, "the device closed the connection"};
  f.during_check = false;
  const auto r = judge_facts(opener(), f, true);
  EXPECT_EQ(row_of(r, "Connection1").substr(0, 5), "open;");
  EXPECT_EQ(row_of(r, "Connection2"), "not reached | not tried");
}

TEST(live_verdicts, a_signal_before_the_connections_says_so) {
  auto f = matching();
  f.connections.clear();
  f.interrupted = 2;
  const auto r = judge_facts(opener(), f, true);
  EXPECT_EQ(row_of(r, "Connection1"), "not reached: interrupted | not tried");
  EXPECT_EQ(r.interrupted, 2);
  EXPECT_FALSE(r.failure);
}

TEST(live_verdicts, no_connection_to_the_device_gives_no_rows) {
  live_facts f;
  f.failure = error{net::error_id::connect, "cannot connect to 198.51.100.7:44818: Connection refused"};
  const auto r = judge_facts(opener(), f, true);
  EXPECT_TRUE(r.rows.empty());
  ASSERT_TRUE(r.failure);
  EXPECT_EQ(r.failure->id, "live-connect");
}

TEST(live_verdicts, connections_not_asked_for_are_not_tried) {
  const auto r = judge_facts(opener(), matching(), false);
  EXPECT_EQ(row_of(r, "Connection2"), "--connections not given | not tried");
  EXPECT_EQ(r.rows.size(), 11u);
}

}  // namespace
}  // namespace edsc::live
