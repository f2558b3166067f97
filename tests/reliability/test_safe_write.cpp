// --in-place and -o write through a temporary file in the target directory,
// fsync and rename (io/output_target.cpp): on any failure the original stays as
// it was and no temporary file is left behind.
#include "reliability/reliability_support.hpp"

namespace edsc::reliability_test {
namespace {

// The canonical layout differs from this, so `fmt` has something to write.
const std::string messy = good_eds + "[Params]\n Param1 =   0,,,;\n";

class SafeWrite : public Cli {
 protected:
  // Nothing but `expected` in the scratch directory (no stray temporaries).
  void expect_listing(std::vector<std::string> expected) {
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(listing(), expected);
  }
};

TEST_F(SafeWrite, InPlaceReplacesAndLeavesNoTemporary) {
  const auto p = file("dev.eds", messy);
  const auto r = run_edsc({"fmt", "--in-place", p.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(read_bytes(p), messy);
  expect_listing({"dev.eds"});
}

TEST_F(SafeWrite, InPlaceKeepsPermissions) {
  const auto p = file("dev.eds", messy);
  fs::permissions(p, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  ASSERT_EQ(run_edsc({"fmt", "--in-place", p.string()}).status, 0);
  EXPECT_EQ(fs::status(p).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST_F(SafeWrite, OutputIntoMissingDirectoryFails) {
  const auto p = file("dev.eds", messy);
  for (const char* cmd : {"fmt", "fix"}) {
    const auto r = run_edsc({cmd, p.string(), "-o", (dir_ / "nowhere" / "out.eds").string()});
    EXPECT_EQ(r.status, 2) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("the folder '" + (dir_ / "nowhere").string() + "' does not exist"), std::string::npos)
        << r.output;
  }
  EXPECT_EQ(read_bytes(p), messy);
  expect_listing({"dev.eds"});
}

TEST_F(SafeWrite, OutputOntoADirectoryFails) {
  const auto p = file("dev.eds", messy);
  fs::create_directory(dir_ / "target.eds");
  const auto r = run_edsc({"fmt", p.string(), "-o", (dir_ / "target.eds").string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("target.eds"), std::string::npos) << r.output;
  EXPECT_EQ(read_bytes(p), messy);
  EXPECT_TRUE(fs::is_directory(dir_ / "target.eds"));
  EXPECT_TRUE(fs::is_empty(dir_ / "target.eds"));
  expect_listing({"dev.eds", "target.eds"});
}

TEST_F(SafeWrite, EditOntoADirectoryLeavesNothing) {
  const auto p = file("dev.eds", good_eds);
  fs::create_directory(dir_ / "out");
  const auto r = run_edsc({"edit", p.string(), "--set", "Device.MajRev=2", "-o", (dir_ / "out").string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(read_bytes(p), good_eds);
  expect_listing({"dev.eds", "out"});
}

TEST_F(SafeWrite, ReadOnlyTargetDirectory) {
  const auto ro = dir_ / "ro";
  fs::create_directory(ro);
  const auto p = ro / "dev.eds";
  write_bytes(p, messy);
  // As root, edsc runs as nobody (reliability_support.hpp), who owns the
  // folder and the file: only the folder's missing write bit stops it.
  fs::permissions(dir_, fs::perms::owner_all | fs::perms::others_exec);
  give_to_runner(ro);
  give_to_runner(p);
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
  const auto r = run_edsc_unprivileged({"fmt", "--in-place", p.string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("cannot create a temporary file"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Permission denied"), std::string::npos) << r.output;
  fs::permissions(ro, fs::perms::owner_all);  // so TearDown can remove it
  EXPECT_EQ(read_bytes(p), messy);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(ro)) names.push_back(e.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"dev.eds"});
}

TEST_F(SafeWrite, OutputOntoTheInputIsRefused) {
  const auto p = file("dev.eds", messy);
  fs::create_hard_link(p, dir_ / "alias.eds");
  for (const auto& target : {p, dir_ / "alias.eds", dir_ / "." / "dev.eds"}) {
    for (const char* cmd : {"fmt", "fix"}) {
      const auto r = run_edsc({cmd, p.string(), "-o", target.string()});
      EXPECT_EQ(r.status, 2) << cmd << " " << target << "\n" << r.output;
      EXPECT_NE(r.output.find("refusing to overwrite the input"), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("; use --in-place to edit it"), std::string::npos) << r.output;
    }
    const auto r = run_edsc({"edit", p.string(), "--set", "Device.MajRev=2", "-o", target.string()});
    EXPECT_EQ(r.status, 2) << r.output;
  }
  EXPECT_EQ(read_bytes(p), messy);
  expect_listing({"alias.eds", "dev.eds"});
}

TEST_F(SafeWrite, RefusedEditLeavesTheOriginal) {
  // An edit that introduces an error is not written, in place or elsewhere.
  const auto p = file("dev.eds", good_eds);
  const auto r = run_edsc({"edit", p.string(), "--in-place", "--set", "Device.VendCode=999999999"});
  EXPECT_TRUE(r.status == 1 || r.status == 2) << r.output;
  EXPECT_EQ(read_bytes(p), good_eds);
  expect_listing({"dev.eds"});
}

}  // namespace
}  // namespace edsc::reliability_test
