// Every corpus file with a ConnectionN (the corpus-wide sample), one test
// each so ctest runs them side by side: the generator either serves it, and
// then the OpENer device `edsc header --stack opener` builds from it opens
// every connection `edsc connection --format json` announces (as the sample
// of test_eipscanner_announced_opener.cpp does, with the same list of
// connections OpENer cannot open), or refuses it with the opener-* rules
// docs/header.md's table ("Which corpus files OpENer can serve") gives it.
// So the set of served files is the generator's, and the table stays true.
// Label `opener_sweep` (tests/CMakeLists.txt); each device keeps its build
// folder under the stack root, compiled through ccache.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

#include "announced_file.hpp"
#include "corpus_dirs.hpp"
#include "multicast_group.hpp"
#include "scanner_support.hpp"
#include "stack/opener_project.hpp"

namespace edsc::scanner_test {
namespace {

namespace fs = std::filesystem;

// "corpus folder/file" -> the table's last two cells ("can", "" or "cannot",
// "rules: first finding"), from docs/header.md.
std::map<std::string, std::pair<std::string, std::string>> coverage_table() {
  std::map<std::string, std::pair<std::string, std::string>> out;
  std::ifstream in(std::string(EDSC_PROJECT_DIR) + "/docs/header.md");
  const std::regex row(R"(^\| ([^|]+) \| ([^|]+) \| (can|cannot) \| (.*) \|$)");
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_match(line, m, row)) out[m[1].str() + "/" + m[2].str()] = {m[3].str(), m[4].str()};
  return out;
}

// The opener-* rules of `text`, sorted and comma-joined as the table writes them.
std::string rules_in(const std::string& text) {
  std::set<std::string> rules;
  const std::regex rule(R"(\[(opener-[a-z-]+)\])");
  for (std::sregex_iterator i(text.begin(), text.end(), rule), end; i != end; ++i) rules.insert((*i)[1].str());
  std::string out;
  for (const auto& r : rules) out += (out.empty() ? "" : ", ") + r;
  return out;
}

// Entries of the list for `name`: each must still fail on its device.
unsigned listed_for(const reviewed& listed, const std::string& name) {
  unsigned n = 0;
  for (const auto& [key, why] : listed) n += key.starts_with(name + ":");
  return n;
}

// A test name from a file name: letters and digits, the rest '_'.
std::string test_name(const fs::path& f) {
  auto s = f.parent_path().filename().string() + "_" + f.stem().string();
  for (auto& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

// One of the corpus files with syntax errors (corpus_dirs.hpp).
bool is_broken(const std::string& name) {
  return std::find(std::begin(corpora::broken), std::end(corpora::broken), name) != std::end(corpora::broken);
}

class eipscanner_opener_sweep : public ::testing::TestWithParam<fs::path> {};

TEST_P(eipscanner_opener_sweep, served_and_opened_or_refused_as_documented) {
  const auto& file = GetParam();
  const auto name = file.filename().string();
  const auto table = coverage_table();
  const auto row = table.find(file.parent_path().filename().string() + "/" + name);
  ASSERT_NE(row, table.end()) << name << " has no row in docs/header.md's table: run scripts/opener-coverage";
  if (!fs::exists(std::string(EDSC_OPENER_SOURCE_DIR) + "/CMakeLists.txt"))
    GTEST_SKIP() << "OpENer's sources are missing: " << EDSC_OPENER_SOURCE_DIR;
  const auto built = stack_test::build_device("sweep/" + test_name(file), file.string());
  const auto& [can, reason] = row->second;
  if (built.generate_status != 0) {
    // Refused: with the opener-* rules the table names, nothing else.
    EXPECT_EQ(can, "cannot") << name << ": the generator refuses it, docs/header.md says it can be served\n"
                             << built.log;
    EXPECT_EQ(built.generate_status, 1) << built.log;
    EXPECT_EQ(reason.substr(0, reason.find(':')), rules_in(built.log)) << built.log;
    return;
  }
  ASSERT_EQ(can, "can") << name << ": served, docs/header.md says it cannot be: run scripts/opener-coverage";
  ASSERT_TRUE(built.ok) << built.log;
  std::string why;
  auto net = live_test::test_network::make(why, opener_net());
  if (!net) GTEST_SKIP() << why;
  ASSERT_TRUE(net->start_opener(built.binary, why)) << why;
  const auto all = announce(file.string(), why);
  if (is_broken(name)) {
    // The header reads past a syntax error it does not depend on (docs/cli.md);
    // `edsc connection` reads no settings from such a file, so nothing is announced.
    EXPECT_NE(why.find("fix the syntax errors"), std::string::npos) << why;
    return;
  }
  const auto listed = not_opened("announced_not_opened_opener.txt");
  ASSERT_TRUE(why.empty()) << why;
  eipScanner::utils::Logger::setLogLevel(eipScanner::utils::LogLevel::ERROR);
  live_test::thread_in_namespace inside(net->scanner_ns);
  ASSERT_TRUE(inside.entered());
  multicast_membership group(net->device_ip, net->host_ip);
  ASSERT_TRUE(group.joined()) << "cannot join the device's multicast group";
  const auto out = open_every_connection(file.string(), all, net->device_ip, "", listed);
  for (const auto& failure : out.failures) ADD_FAILURE() << failure;
  EXPECT_GT(out.opened + out.listed, 0u) << name << ": a served file with no class 1 connection tried";
  EXPECT_EQ(out.listed, listed_for(listed, name)) << "a connection of announced_not_opened_opener.txt was not tried";
  std::printf("%s: %u opened, %u listed; generated in %.2f s, built in %.1f s\n", name.c_str(), out.opened, out.listed,
              built.generate_s, built.build_s);
}

INSTANTIATE_TEST_SUITE_P(corpus, eipscanner_opener_sweep, ::testing::ValuesIn(files_with_connections()),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace edsc::scanner_test
