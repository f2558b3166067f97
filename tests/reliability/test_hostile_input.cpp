// Hostile inputs (docs/reliability.md): each gives a clear diagnostic and exit
// 1 or 2 within a bounded time, and no command crashes on them.
#include "reliability/reliability_support.hpp"

namespace edsc::reliability_test {
namespace {

class Hostile : public Cli {
 protected:
  // `check` rejects the file clearly; dump, fmt and header survive it.
  void expect_survives(const fs::path& p, const std::string& mention) {
    expect_clear_rejection(run_edsc({"check", p.string()}, time_limit), mention);
    expect_no_crash(run_edsc({"dump", p.string()}, time_limit));
    expect_no_crash(run_edsc({"fmt", p.string()}, time_limit));
    expect_no_crash(run_edsc({"header", p.string(), "-o", (dir_ / "out.h").string()}, time_limit));
    expect_no_crash(run_edsc({"edit", p.string(), "--set", "Device.MajRev=2"}, time_limit));
  }
};

TEST_F(Hostile, EmptyFile) {
  const auto p = file("empty.eds", "");
  expect_survives(p, "empty.eds");
}

TEST_F(Hostile, BinaryGarbage) {
  std::mt19937 rng(42);
  std::string bytes(64 * 1024, '\0');
  for (auto& c : bytes) c = static_cast<char>(rng());
  const auto p = file("garbage.eds", bytes);
  expect_survives(p, "garbage.eds");
}

TEST_F(Hostile, DirectoryAsFile) {
  // Named as a file to the commands that take exactly one EDS file.
  fs::create_directory(dir_ / "dir.eds");
  const auto p = (dir_ / "dir.eds").string();
  for (const char* cmd : {"dump", "fmt"}) {
    const auto r = run_edsc({cmd, p}, time_limit);
    expect_clear_rejection(r, "is a directory");
  }
  // `check` searches a directory for *.eds files: an empty one is an error too.
  expect_clear_rejection(run_edsc({"check", p}, time_limit), "dir.eds");
}

TEST_F(Hostile, UnreadableFile) {
  // As root, edsc runs as nobody (reliability_support.hpp), who owns the file
  // and may enter the folder: only the file's mode 000 stops the read.
  fs::permissions(dir_, fs::perms::owner_all | fs::perms::others_exec);
  const auto p = file("secret.eds", good_eds);
  give_to_runner(p);
  // Readable, the same file passes: the mode is what the rejection is about.
  EXPECT_EQ(run_edsc_unprivileged({"check", p.string()}).status, 0);
  fs::permissions(p, fs::perms::none);
  expect_clear_rejection(run_edsc_unprivileged({"check", p.string()}), "Permission denied");
  expect_clear_rejection(run_edsc_unprivileged({"dump", p.string()}), "Permission denied");
}

TEST_F(Hostile, MissingPath) {
  const auto p = (dir_ / "no-such.eds").string();
  for (const char* cmd : {"check", "dump", "fmt"})
    expect_clear_rejection(run_edsc({cmd, p}, time_limit), "no-such.eds");
}

TEST_F(Hostile, UnterminatedStringAtEnd) {
  const auto p = file("open.eds", good_eds + "[Params]\n        Param1 = \"never closed");
  expect_survives(p, "open.eds");
}

TEST_F(Hostile, MillionFieldsInOneEntry) {
  std::string text = good_eds + "[Params]\n        Param1 = 0";
  const int fields = edsc::test_time::shrunk(1'000'000);
  text.reserve(text.size() + 2 * static_cast<std::size_t>(fields) + 10);
  for (int i = 1; i < fields; ++i) text += ",0";
  text += ";\n";
  const auto p = file("wide.eds", text);
  expect_survives(p, "wide.eds");
}

TEST_F(Hostile, HundredThousandSections) {
  // The same section again and again: each repeat is a duplicate-section
  // error, so the report itself is 10^5 diagnostics long.
  std::string text = good_eds;
  for (int i = 0; i < edsc::test_time::shrunk(100'000); ++i) text += "[Params]\n";
  const auto p = file("many.eds", text);
  expect_survives(p, "many.eds");
}

TEST_F(Hostile, NestingFarPastTheLimit) {
  // The grammar allows 16 levels; 100000 must neither recurse the stack away
  // nor be accepted.
  const std::string deep = std::string(100'000, '{') + std::string(100'000, '}');
  const auto p = file("deep.eds", good_eds + "[Params]\n        Param1 = " + deep + ";\n");
  expect_survives(p, "deep.eds");
  const auto unclosed = file("unclosed.eds", good_eds + "[Params]\n        Param1 = " + std::string(100'000, '{'));
  expect_survives(unclosed, "unclosed.eds");
}

TEST_F(Hostile, SparseFileOverTheSizeLimit) {
  // A terabyte of holes: no disk used, and the size limit must refuse it
  // before a byte is read. Reading it would take far longer than the limit
  // that ends a hung run, so the verdict is the refusal, not a stopwatch.
  const auto p = dir_ / "huge.eds";
  const int fd = ::open(p.c_str(), O_CREAT | O_WRONLY | O_CLOEXEC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, off_t{1} << 40), 0);
  ::close(fd);
  for (const char* cmd : {"check", "dump", "fmt"}) {
    const auto r = run_edsc({cmd, p.string()}, time_limit);
    EXPECT_EQ(r.status, 2) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("1099511627776 bytes, over the input limit of 268435456 bytes"), std::string::npos)
        << r.output;
  }
}

TEST_F(Hostile, NulBytes) {
  std::string text = good_eds;
  text.insert(text.find("[Device]"), std::string("\0\0\0", 3));
  const auto p = file("nul.eds", text);
  expect_survives(p, "NUL byte");
}

// A text saved as UTF-16 (as some Windows editors do): one diagnostic that
// names the encoding and the conversion, not an error per stray byte.
TEST_F(Hostile, Utf16FileIsOneClearDiagnostic) {
  std::string wide = "\xFF\xFE";
  for (const char c : good_eds) {
    wide += c;
    wide += '\0';
  }
  const auto p = file("wide.eds", wide);
  const auto r = run_edsc({"check", p.string()}, time_limit);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("wide.eds:1:1: error: this file is UTF-16LE"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("iconv -f UTF-16 -t UTF-8"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("[input-utf16]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1 file checked: 1 error, 0 warnings, 0 notes"), std::string::npos) << r.output;
  // The commands that report no diagnostics of their own stop on it too.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"dump", p.string()}, {"header", p.string(), "-o", (dir_ / "out.h").string()}}) {
    const auto d = run_edsc(args, time_limit);
    EXPECT_EQ(d.status, 1) << args[0] << "\n" << d.output;
    EXPECT_NE(d.output.find("[input-utf16]"), std::string::npos) << d.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out.h"));
}

TEST_F(Hostile, ZipArchiveIsNamed) {
  const auto p = file("library.eds", std::string("PK\x03\x04\x14\0\0\0\x08\0", 10) + std::string(200, 'z'));
  const auto r = run_edsc({"check", p.string()}, time_limit);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("this is a ZIP archive"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1 file checked: 1 error,"), std::string::npos) << r.output;
}

TEST_F(Hostile, InvalidUtf8) {
  std::string text = good_eds;
  const auto at = text.find("Test Device");
  text.replace(at, 4, "\xff\xfe\xc3\x28");  // stray bytes and a broken sequence
  text += "$ comment \x80\x81\n[Params]\n        Param1 = \"\xed\xa0\x80\";\n";
  const auto p = file("utf8.eds", text);
  const auto r = run_edsc({"check", "--format", "json", p.string()}, time_limit);
  expect_no_crash(r);
  expect_no_crash(run_edsc({"check", "--format", "sarif", p.string()}, time_limit));
  expect_survives(p, "utf8.eds");
}

}  // namespace
}  // namespace edsc::reliability_test
