// What the output policy and the reader do when the file system is not what
// it was a moment ago, or descriptors are not where programs expect them:
// cases that need the race won or a descriptor closed, so they are driven
// directly rather than through the command line.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/output_target.hpp"
#include "io/read_file.hpp"
#include "reliability/reliability_support.hpp"

namespace edsc::reliability_test {
namespace {

class OutputRaces : public Cli {};

// write_output saw a FIFO or a device at `path`; by the time it opens the
// path a regular file stands there. Writing through it would overwrite the
// file from its start without truncating: nothing may be written.
TEST_F(OutputRaces, APathSwappedForARegularFileIsNotWrittenThrough) {
  const auto p = file("swapped.eds", "the user's file, longer than what edsc writes\n");
  const auto w = io::detail::write_through(p.string(), "EDSC");
  ASSERT_FALSE(w.ok());
  EXPECT_NE(w.error().message.find("changed while being written; nothing written"), std::string::npos)
      << w.error().message;
  EXPECT_EQ(read_bytes(p), "the user's file, longer than what edsc writes\n");
}

TEST_F(OutputRaces, AFifoStillThereIsWrittenThrough) {
  const auto p = dir_ / "fifo";
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
  const int reader = ::open(p.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  const auto w = io::detail::write_through(p.string(), "EDSC");
  EXPECT_TRUE(w.ok()) << w.error().message;
  char got[8] = {};
  EXPECT_EQ(::read(reader, got, sizeof got), 4);
  EXPECT_EQ(std::string(got, 4), "EDSC");
  ::close(reader);
}

// A program started with standard input closed gets descriptor 0 from its
// first open(): that is a file like any other, not a failure.
TEST_F(OutputRaces, AFileOpenedAsDescriptorZeroIsRead) {
  const auto p = file("dev.eds", good_eds);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::close(STDIN_FILENO);
    const auto r = io::read_source(p.string());
    const auto* f = (r ? &r.value() : nullptr);
    ::_exit(f != nullptr && *f != nullptr && (*f)->text() == good_eds ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace edsc::reliability_test
