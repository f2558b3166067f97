// Every diagnostic edsc reports on the shared corpora, recorded and reviewed in
// tests/check/corpus/<file>.txt (eds-corpus) and
// tests/check/corpus/rockwell/<file>.txt (eds-corpus-rockwell), so any change in what edsc says about real
// files shows as a diff. Header lines (`#`) explain each error: an error on a
// real vendor file must be a real defect of that file.
//
// Regenerate with EDSC_UPDATE_GOLDEN=1 (header comments are kept), then
// review the diff before committing.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "check/check_file.hpp"
#include "corpus_dirs.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpus_files() { return edsc::corpora::all_files(); }

// Where the reviewed record of a corpus file lives.
fs::path golden_of(const fs::path& eds) {
  auto dir = fs::path(EDSC_TESTS_DIR) / "check" / "corpus";
  if (eds.parent_path() == fs::path(EDSC_CORPUS_ROCKWELL_DIR)) dir /= "rockwell";
  return dir / (eds.filename().string() + ".txt");
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// One line a diagnostic, without the path (the corpus may live anywhere).
std::string render(const edsc::checked_file& r) {
  std::string out;
  const auto& src = *r.report.source;
  for (const auto& d : r.report.diags) {
    const auto pos = src.position(d.where.begin);
    out += fmt::format("{}:{}: {}: {} [{}]\n", pos.line, pos.column, edsc::to_string(d.level), d.message,
                       edsc::rule_of(d.id).name);
  }
  return out;
}

std::pair<std::string, std::string> split_header(const std::string& golden) {
  std::string header, body;
  std::istringstream in(golden);
  for (std::string line; std::getline(in, line);) (line.starts_with("#") ? header : body) += line + "\n";
  return {header, body};
}

class corpus_golden : public ::testing::TestWithParam<fs::path> {};

TEST_P(corpus_golden, diagnostics_match_the_reviewed_record) {
  const auto& path = GetParam();
  const auto name = path.filename().string();
  const auto golden_path = golden_of(path);
  const auto result = edsc::check_file(path.string(), edsc::check_options{});
  ASSERT_FALSE(result.io_error);
  const auto actual = render(result);
  auto [header, expected] = split_header(fs::exists(golden_path) ? read(golden_path) : "");
  if (std::getenv("EDSC_UPDATE_GOLDEN") != nullptr) {
    if (header.empty()) header = fmt::format("# {}\n", name);
    std::ofstream(golden_path, std::ios::binary) << header << actual;
    GTEST_SKIP() << "golden updated";
  }
  EXPECT_EQ(actual, expected) << "diagnostics on " << name << " changed; review, then EDSC_UPDATE_GOLDEN=1";
  // Errors on real files must be explained in the header.
  if (actual.find(": error: ") != std::string::npos) {
    EXPECT_NE(header.find("error"), std::string::npos)
        << name << " has errors but its golden file does not explain them";
  }
}

INSTANTIATE_TEST_SUITE_P(corpus, corpus_golden, ::testing::ValuesIn(corpus_files()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                           return fmt::format("file{:03}", info.index);
                         });

}  // namespace
