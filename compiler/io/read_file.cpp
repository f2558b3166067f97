#include "io/read_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "io/pipe.hpp"

namespace edsc::io {

namespace {

struct fd_guard {
  int fd;
  ~fd_guard() {
    if (fd >= 0) ::close(fd);
  }
};

io_error errno_error(const std::string& path, const char* what) {
  return io_error{fmt::format("{}: cannot {}: {}", path, what, std::strerror(errno))};
}

io_error over_limit(const std::string& path, std::uint64_t size, std::uint64_t max_bytes, const char* at_least) {
  return io_error{
      fmt::format("{}: file is {}{} bytes, over the input limit of {} bytes", path, at_least, size, max_bytes)};
}

// Reads into buf[0, len) until it is full or the file ends: the bytes read,
// or -1 (errno set) on a read error.
ssize_t read_into(int fd, char* buf, std::size_t len) {
  std::size_t done = 0;
  while (done < len) {
    const ssize_t n = ::read(fd, buf + done, len - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return -1;
    }
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  return static_cast<ssize_t>(done);
}

// Appends what `fd` yields until end of file or `limit` bytes; false (errno
// set) on a read error.
bool read_to_end(int fd, std::string& text, std::uint64_t limit) {
  std::size_t done = text.size();
  for (;;) {
    text.resize(std::min<std::uint64_t>(limit, std::max<std::size_t>({done * 2, 65536, text.capacity()})));
    if (done == text.size()) break;  // the limit is reached
    const ssize_t n = read_into(fd, text.data() + done, text.size() - done);
    if (n < 0) return false;
    done += static_cast<std::size_t>(n);
    if (done < text.size()) break;  // the end of the file came first
  }
  text.resize(done);
  return true;
}

}  // namespace

read_result read_source(const std::string& path, std::uint64_t max_bytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno_error(path, "open file");
  fd_guard guard{fd};

  struct stat st {};
  if (::fstat(fd, &st) != 0) return errno_error(path, "stat file");
  if (S_ISDIR(st.st_mode)) return io_error{fmt::format("{}: is a directory, not an EDS file", path)};
  if (!S_ISREG(st.st_mode)) return io_error{fmt::format("{}: not a regular file", path)};
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size > max_bytes) return over_limit(path, size, max_bytes, "");

  // Read into storage that is not zero-filled first (a std::string would be):
  // on large files that pass cost 2.5 % of a whole check. Up to the size
  // stat reported: a file that grows meanwhile is cut there, one that
  // shrinks ends early.
  std::unique_ptr<char[]> bytes(new char[size + 1]);
  const ssize_t done = read_into(fd, bytes.get(), size);
  if (done < 0) return errno_error(path, "read file");
  bytes[done] = '\0';
  return std::make_unique<source_file>(path, std::move(bytes), static_cast<std::size_t>(done));
}

read_result read_stdin(const std::string& name, std::uint64_t max_bytes) {
  const std::string display_name = name.empty() ? default_stdin_name : name;
  std::string text;
  widen_pipe(STDIN_FILENO);  // an editor piping a large buffer waits less
  // One byte past the limit tells "exactly at the limit" from "over it".
  if (!read_to_end(STDIN_FILENO, text, max_bytes + 1)) return errno_error(display_name, "read standard input");
  if (text.size() > max_bytes) return over_limit(display_name, text.size(), max_bytes, "at least ");
  return std::make_unique<source_file>(display_name, std::move(text));
}

}  // namespace edsc::io
