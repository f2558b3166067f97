// What `probe` and `verify --live --connections` print about OpENer
// (../shared/opener, in a namespace of its own), against reviewed text
// goldens in tests/live/golden/. What varies from run to run or machine to
// machine is masked before the comparison: the device's address
// (<device>), the shared folder (<shared>), durations and frame counts
// (<n>), and the columns' padding (runs of spaces become two).
// EDSC_UPDATE_GOLDEN=1 rewrites the goldens; read `git diff`.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "golden_file.hpp"
#include "netns/run_edsc.hpp"
#include "opener_device.hpp"
#include "test_paths.hpp"

namespace edsc::live_test {
namespace {

namespace fs = std::filesystem;

const fs::path goldens = fs::path(EDSC_TESTS_DIR) / "live" / "golden";

class live_opener_golden : public opener_device_test {
 protected:
  // `text` with what differs between runs replaced by its kind.
  [[nodiscard]] std::string masked(std::string text) const {
    const auto replace = [&](const std::string& pattern, const std::string& with) {
      text = std::regex_replace(text, std::regex(pattern), with);
    };
    replace(std::regex_replace(device(), std::regex("\\."), "\\."), "<device>");
    replace(std::regex_replace(std::string(EDSC_SHARED_DIR), std::regex(R"([.^$|()\[\]{}*+?\\])"), "\\$&"), "<shared>");
    replace(R"([0-9]+(\.[0-9]+)? ?ms\b)", "<n> ms");
    replace(R"([0-9]+(\.[0-9]+)? s\b)", "<n> s");
    replace(R"(\b[0-9]+ frames\b)", "<n> frames");
    replace("   +", "  ");
    return text;
  }
};

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

TEST_F(live_opener_golden, probe_text) {
  const auto r = run_edsc("probe " + device());
  EXPECT_EQ(r.status, 0) << r.output;
  test::expect_golden(goldens / "probe-opener.txt", masked(r.output));
}

TEST_F(live_opener_golden, verify_live_connections_text) {
  const auto r = run_edsc("verify --live " + device() + " " + quoted(opener_eds) + " --connections --color never");
  EXPECT_EQ(r.status, 0) << r.output;
  test::expect_golden(goldens / "verify-live-opener.txt", masked(r.output));
}

}  // namespace
}  // namespace edsc::live_test
