// io::map_source: mapped where that pays, read otherwise, the same bytes and
// errors as read_source either way; and a file that shrinks under its
// mapping is noticed, never a crash.
#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "check/check_file.hpp"
#include "io/map_file.hpp"

namespace edsc {
namespace {

struct temp_file {
  std::string path;
  explicit temp_file(const std::string& bytes) {
    char name[] = "/tmp/edsc-map-XXXXXX";
    const int fd = ::mkstemp(name);
    path = name;
    EXPECT_EQ(::write(fd, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
    ::close(fd);
  }
  ~temp_file() { ::unlink(path.c_str()); }
};

// An EDS file of about `size` bytes with one certain error (VendCode out of range).
std::string eds_text(std::size_t size) {
  std::string text =
      "[File]\nDescText = \"map\";\nCreateDate = 01-02-2024;\nCreateTime = 10:00:00;\nRevision = 1.1;\n"
      "[Device]\nVendCode = 70000;\nProdName = \"x\";\n";
  while (text.size() < size) text += "$ filler comment line that only makes the file longer\n";
  text.resize(size);
  return text;
}

// Whether the source's bytes are a mapping: it starts on a page, a buffer
// from malloc after the allocator's header.
bool is_mapped(const source_file& src) { return reinterpret_cast<std::uintptr_t>(src.text().data()) % 4096 == 0; }

std::unique_ptr<source_file> map_ok(const std::string& path) {
  auto r = io::map_source(path);
  if (!r) {
    ADD_FAILURE() << r.error().message;
    return std::make_unique<source_file>(path, std::string{});
  }
  return std::move(r.value());
}

TEST(MapSource, LargeFilesAreMappedWithTheirBytesAndANul) {
  const auto text = eds_text(40000);
  temp_file f(text);
  const auto m = map_ok(f.path);
  EXPECT_TRUE(is_mapped(*m));
  EXPECT_EQ(m->text(), text);
  EXPECT_EQ(m->text().data()[text.size()], '\0');
  EXPECT_EQ(m->path(), f.path);
  EXPECT_FALSE(m->changed());
}

TEST(MapSource, SmallFilesAndWholePagesAreRead) {
  for (const std::size_t size : {0u, 100u, 16383u, 8192u, 65536u}) {
    const auto text = eds_text(size);
    temp_file f(text);
    const auto m = map_ok(f.path);
    EXPECT_FALSE(is_mapped(*m)) << size;  // no room for the NUL, or not worth a mapping
    EXPECT_EQ(m->text(), text) << size;
    EXPECT_EQ(m->text().data()[text.size()], '\0') << size;
  }
}

TEST(MapSource, ErrorsAreReadSourcesErrors) {
  for (const std::string path : {"/nonexistent/edsc-map.eds", "/tmp"}) {
    auto mapped = io::map_source(path);
    auto read = io::read_source(path);
    ASSERT_TRUE(!mapped.ok()) << path;
    ASSERT_TRUE(!read.ok()) << path;
    EXPECT_EQ(mapped.error().message, read.error().message);
  }
  temp_file big(eds_text(40000));
  auto over = io::map_source(big.path, 30000);
  ASSERT_TRUE(!over.ok());
  EXPECT_NE(over.error().message.find("over the input limit of 30000 bytes"), std::string::npos);
}

// More files than there are slots for the signal handler, one after another:
// each mapping gives its slot back.
TEST(MapSource, MappingsAreReleased) {
  temp_file f(eds_text(20000));
  for (int i = 0; i < 600; ++i) {
    const auto m = map_ok(f.path);
    ASSERT_TRUE(is_mapped(*m)) << i;
  }
}

TEST(MapSource, AFileThatShrinksUnderItsMappingIsNoticed) {
  const auto text = eds_text(5 * 4096 + 100);
  temp_file f(text);
  const auto m = map_ok(f.path);
  ASSERT_TRUE(is_mapped(*m));
  EXPECT_FALSE(m->changed());
  ASSERT_EQ(::truncate(f.path.c_str(), 10), 0);
  // Touching the vanished pages would be SIGBUS: it reads zeros instead.
  unsigned sum = 0;
  for (const char c : m->text().substr(4096)) sum += static_cast<unsigned char>(c);
  EXPECT_EQ(sum, 0u);
  EXPECT_TRUE(m->changed());
}

TEST(MapSource, CheckReportsAShrunkFileAndNothingElse) {
  const auto text = eds_text(5 * 4096 + 7);
  temp_file f(text);
  {
    const auto whole = check_file(f.path, check_options{});
    ASSERT_FALSE(whole.io_error) << *whole.io_error;
    EXPECT_FALSE(whole.report.diags.empty());  // VendCode = 70000
  }
  auto m = map_ok(f.path);
  ASSERT_TRUE(is_mapped(*m));
  ASSERT_EQ(::truncate(f.path.c_str(), 0), 0);
  const auto out = check_source(std::move(m), check_options{});
  ASSERT_TRUE(out.io_error);
  EXPECT_EQ(*out.io_error, f.path + ": cannot read file: it shrank while it was being read; try again");
  EXPECT_TRUE(out.report.diags.empty());
}

// The handler takes only faults in mapped inputs; any other SIGBUS does what
// it did without it.
TEST(MapSourceDeathTest, OtherBusErrorsStillEndTheProcess) {
  temp_file f(eds_text(20000));
  EXPECT_DEATH(
      {
        const auto m = map_ok(f.path);
        if (is_mapped(*m)) std::raise(SIGBUS);
      },
      "");
}

}  // namespace
}  // namespace edsc
