// The OpENer project `edsc header --stack opener` writes, whole, for three
// EDS files of different shapes, against reviewed text goldens in
// tests/emit/golden/opener/<case>/ (one file per generated file):
//   config            OpENer's own sample: an owner with a configuration
//                     assembly, input-only and listen-only beside it
//   input-only        one produced assembly and an input-only connection
//                     (tests/emit/golden/opener/input-only.eds, written for
//                     this: no corpus file the stack serves has that shape)
//   many-assemblies   a Rockwell file of 25 assemblies, 8 of them
//                     configuration, and 16 connections
// A file generated and not in the golden folder fails as well as a
// difference. EDSC_UPDATE_GOLDEN=1 rewrites the folder; read `git diff`.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "emit_support.hpp"
#include "golden_file.hpp"
#include "test_paths.hpp"

namespace edsc::test {
namespace {

struct golden_case {
  const char* name;
  fs::path eds;
};

const fs::path goldens = fs::path(EDSC_TESTS_DIR) / "emit" / "golden" / "opener";

std::vector<golden_case> cases() {
  return {{"config", fs::path(EDSC_CORPUS_DIR) / "EIPStackGroup__OpENer__opener_sample_app.eds"},
          {"input-only", goldens / "input-only.eds"},
          {"many-assemblies", fs::path(EDSC_CORPUS_ROCKWELL_DIR) / "031F000E030000010001.eds"}};
}

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir)) out.insert(e.path().filename().string());
  return out;
}

TEST(OpenerGolden, TheGeneratedProjectIsTheReviewedOne) {
  for (const auto& c : cases()) {
    temp_dir tmp("opener-golden");
    const auto out = tmp.path() / "project";
    const auto r = run_shell(edsc_command() + " header --stack opener " + quoted(c.eds) + " -o " + quoted(out));
    ASSERT_EQ(r.status, 0) << c.name << "\n" << r.output;
    const auto made = names_in(out);
    EXPECT_GE(made.size(), 5u) << c.name;
    const auto golden_dir = goldens / c.name;
    if (update_golden()) fs::remove_all(golden_dir);
    for (const auto& name : made) expect_golden(golden_dir / name, read_text(out / name));
    for (const auto& name : names_in(golden_dir))
      EXPECT_TRUE(made.count(name) > 0) << c.name << ": " << name << " is in the goldens but no longer generated";
  }
}

}  // namespace
}  // namespace edsc::test
