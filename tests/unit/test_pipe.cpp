// io::widen_pipe: documents cross a pipe in one piece (LSP messages, `edsc
// check -`); anything that is not a pipe is left alone.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "io/pipe.hpp"
#include "io/read_file.hpp"

namespace edsc {
namespace {

int pipe_max_size() {
  int limit = 0;
  if (FILE* f = std::fopen("/proc/sys/fs/pipe-max-size", "r")) {
    if (std::fscanf(f, "%d", &limit) != 1) limit = 0;
    std::fclose(f);
  }
  return limit;
}

TEST(WidenPipe, EitherEndGrowsThePipeToOneMegabyte) {
  if (pipe_max_size() < (1 << 20)) GTEST_SKIP() << "fs/pipe-max-size is below 1 MB";
  for (int end = 0; end < 2; ++end) {
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    ASSERT_EQ(::fcntl(fds[0], F_GETPIPE_SZ), 65536);
    io::widen_pipe(fds[end]);
    EXPECT_EQ(::fcntl(fds[0], F_GETPIPE_SZ), 1 << 20);
    EXPECT_EQ(::fcntl(fds[1], F_GETPIPE_SZ), 1 << 20);
    ::close(fds[0]);
    ::close(fds[1]);
  }
}

TEST(WidenPipe, NeverShrinksALargerPipe) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  // 2 MB is beyond fs/pipe-max-size; only CAP_SYS_RESOURCE may ask for it.
  if (::fcntl(fds[1], F_SETPIPE_SZ, 2 << 20) < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    GTEST_SKIP() << "a 2 MB pipe needs CAP_SYS_RESOURCE, which this process lacks";
  }
  io::widen_pipe(fds[0]);
  EXPECT_EQ(::fcntl(fds[0], F_GETPIPE_SZ), 2 << 20);
  ::close(fds[0]);
  ::close(fds[1]);
}

TEST(WidenPipe, LeavesFilesAndBadDescriptorsAlone) {
  char path[] = "/tmp/edsc-widen-XXXXXX";
  const int fd = ::mkstemp(path);
  ASSERT_GE(fd, 0);
  io::widen_pipe(fd);  // F_SETPIPE_SZ would fail on a file; it is not tried
  EXPECT_EQ(::write(fd, "x", 1), 1);
  ::close(fd);
  ::unlink(path);
  io::widen_pipe(-1);
}

TEST(WidenPipe, ReadingStandardInputWidensItsPipe) {
  if (pipe_max_size() < (1 << 20)) GTEST_SKIP() << "fs/pipe-max-size is below 1 MB";
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const int saved = ::dup(STDIN_FILENO);
  ASSERT_GE(saved, 0);
  ASSERT_EQ(::dup2(fds[0], STDIN_FILENO), STDIN_FILENO);
  const std::string text = "[File]\nDescText = \"x\";\n";
  ASSERT_EQ(::write(fds[1], text.data(), text.size()), static_cast<ssize_t>(text.size()));
  const int writer = fds[1];
  ::close(fds[0]);
  const int capacity_before = ::fcntl(writer, F_GETPIPE_SZ);
  ::close(writer);  // end of input: the capacity was read before
  // The pipe is gone once both ends close; read the capacity through stdin.
  const auto r = io::read_stdin("");
  const int capacity_after = ::fcntl(STDIN_FILENO, F_GETPIPE_SZ);
  ::dup2(saved, STDIN_FILENO);
  ::close(saved);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value()->text(), text);
  EXPECT_EQ(capacity_before, 65536);
  EXPECT_EQ(capacity_after, 1 << 20);
}

}  // namespace
}  // namespace edsc
