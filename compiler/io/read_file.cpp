#include "io/read_file.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

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
  if (size > max_bytes) {
    return io_error{fmt::format("{}: file is {} bytes, over the input limit of {} bytes", path,
                                size, max_bytes)};
  }

  std::string text(size, '\0');
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd, text.data() + done, size - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno_error(path, "read file");
    }
    if (n == 0) break;  // shrank while reading
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  return std::make_unique<source_file>(path, std::move(text));
}

}  // namespace edsc::io
