// The proof that the generated header is enough: a small C DeviceNet slave
// (responder/) built from `edsc header` output answers the master side of the
// RightSight 42EF start-up capture byte for byte, save for what the EDS explains.
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "emit_support.hpp"
#include "responder_support.hpp"
#include "test_paths.hpp"

using namespace edsc::test;

namespace {

// Replays the capture; `deviations` maps a step to the answer this EDS
// implies instead of the captured one, each with its reason.
void replay_capture(const fs::path& eds, const std::map<int, std::pair<std::string, std::string>>& deviations) {
  temp_dir dir("responder");
  const auto exe = build_responder(dir, eds);
  const auto steps = read_capture();
  ASSERT_EQ(steps.size(), 15u);
  std::vector<std::string> requests;
  for (const auto& s : steps) requests.push_back(s.request.text());
  const auto answers = replay(dir, exe, requests);
  ASSERT_EQ(answers.size(), steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const auto& s = steps[i];
    ASSERT_EQ(s.answers.size(), 1u);
    ASSERT_EQ(answers[i].size(), 1u) << "step " << s.step;
    const auto it = deviations.find(s.step);
    const auto expected = it == deviations.end() ? s.answers[0].text() : it->second.first;
    EXPECT_EQ(answers[i][0], expected) << "step " << s.step << " (" << s.request.text() << ")"
                                       << (it == deviations.end() ? "" : ": " + it->second.second);
    if (it != deviations.end()) {
      EXPECT_NE(expected, s.answers[0].text()) << "step " << s.step << " now matches";
    }
  }
}

const auto diffuse = fs::path(EDSC_PROJECT_DIR) / "eds" / "rightsight-42ef-diffuse.eds";

const std::pair<std::string, std::string> revision_deviation{
    "0x44B 00 8E 01 04", "the captured sensor reports revision 1.6; its EDS (MajRev 1, MinRev 4) says 1.4"};

}  // namespace

TEST(Responder, ReplaysTheRightSightStartUp) {
  // Everything else matches, including the three Set replies that carry data:
  // the responder keeps times in 8 ms ticks and answers with the value kept
  // (ack timer 16 -> 16, production inhibit 1 -> 8, packet rate 250 -> 256).
  replay_capture(diffuse, {{7, revision_deviation}});
}

const std::pair<std::string, std::string> three_byte_deviation{
    "0x44B 00 8E 03 00", "the variant's Input1, and so the COS produced size, is 3 bytes"};

TEST(Responder, ThreeByteVariantProducesThreeBytes) {
  replay_capture(fs::path(EDSC_PROJECT_DIR) / "eds" / "rightsight-42ef-3byte.eds",
                 {{7, revision_deviation}, {12, three_byte_deviation}});
}

TEST(Responder, ProducedSizeFollowsInput1) {
  // The diffuse EDS with only Input1's size changed, made at run time: the
  // answer depends on that one field and nothing else of the variant file.
  temp_dir dir("variant");
  auto text = read_text(diffuse);
  const std::string one_byte = "Input1 =\n                1,";
  const auto at = text.find(one_byte);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, one_byte.size(), "Input1 =\n                3,");
  const auto eds = dir.path() / "resized.eds";
  write_text(eds, text);
  replay_capture(eds, {{7, revision_deviation}, {12, three_byte_deviation}});
}

TEST(Responder, FragmentsTheProductNameAndAnswersErrors) {
  temp_dir dir("fragments");
  const auto exe = build_responder(dir, diffuse);
  const auto answers = replay(dir, exe,
                              {
                                  "0x44E 00 4B 03 01 01 00",  // duplicate MAC check first
                                  "0x44E 00 4B 03 01 01 00",  // explicit allocated
                                  "0x44C 00 0E 01 01 07",     // product name: 29 body bytes, 5 fragments
                                  "0x44C 80 C0 00",
                                  "0x44C 80 C1 00",
                                  "0x44C 80 C2 00",
                                  "0x44C 80 C3 00",
                                  "0x44C 80 C4 00",
                                  "0x44C 00 0E 01 01 06",        // serial number from --serial
                                  "0x44C 00 0E 01 01 08",        // no such attribute
                                  "0x44C 00 10 01 01 01 02 00",  // identity is read-only
                                  "0x44C 00 0E 64 01 01",        // no such object
                                  "0x44C 00 05 01 01",           // no such service
                                  "0x44C 00 4B 03 01 02 00",     // poll is not offered by the EDS
                                  "0x44C 00 0E 05 04 07",        // COS not allocated yet
                                  "0x44C 00 4B 03 01 10 00",     // COS
                                  "0x44C 00 10 05 04 07 01 00",  // produced size is not settable
                                  "0x44C 00 10 05 04 0C 03",     // deferred delete is for explicit connections only
                                  "0x44C 00 4C 03 01 10",        // release COS
                                  "0x44C 00 0E 05 04 08",        // gone again
                              });
  const std::vector<std::vector<std::string>> expected{
      {"0x44F 00 01 00 2B F5 0A 50"},
      {"0x44B 00 CB 00"},
      {"0x44B 80 00 8E 1B 52 69 67 68"},  // "Righ"
      {"0x44B 80 41 74 53 69 67 68 74"},  // "tSight"
      {"0x44B 80 42 20 53 74 61 6E 64"},  // " Stand"
      {"0x44B 80 43 61 72 64 20 44 69"},  // "ard Di"
      {"0x44B 80 84 66 66 75 73 65"},     // "ffuse", last
      {},                                 // the last acknowledgement ends it
      {"0x44B 00 8E 2B F5 0A 50"},
      {"0x44B 00 94 14 FF"},
      {"0x44B 00 94 0E FF"},
      {"0x44B 00 94 16 FF"},
      {"0x44B 00 94 08 FF"},
      {"0x44B 00 94 02 FF"},
      {"0x44B 00 94 16 FF"},
      {"0x44B 00 CB 00"},
      {"0x44B 00 94 0E FF"},
      {"0x44B 00 94 09 FF"},
      {"0x44B 00 CC"},
      {"0x44B 00 94 16 FF"},
  };
  EXPECT_EQ(answers, expected);
}
