#include "io/output_target.hpp"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

namespace edsc::io {

namespace {

// The one write loop of the atomic and the written-through outputs: all of
// `bytes`, retrying short writes and EINTR; false (errno set) on an error.
bool write_fully(int fd, std::string_view bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// The raw atomic write: a temporary file in the same directory, fsync, then
// rename over the target; on failure the target is untouched and no
// temporary file remains. Internal to the policy, which alone knows when a
// path may be replaced (write_output below): nothing else can reach it.
written write_atomically(const std::string& path, std::string_view bytes) {
  const std::string dir = directory_of(path);
  std::string tmpl = path + ".edsc-XXXXXX";
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) {
    return io_error{fmt::format("{}: cannot create a temporary file in '{}': {}", path, dir, std::strerror(errno))};
  }
  auto fail = [&](const char* what) {
    const int saved = errno;
    ::close(fd);
    ::unlink(name.data());
    return io_error{fmt::format("{}: cannot {}: {}", path, what, std::strerror(saved))};
  };

  if (!write_fully(fd, bytes)) return fail("write");
  // Keep the permissions of a file being replaced; new files get the usual 0666 & ~umask.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    ::fchmod(fd, st.st_mode & 07777);
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
  }
  if (::fsync(fd) != 0) return fail("sync");
  if (::close(fd) != 0) {
    const int saved = errno;
    ::unlink(name.data());
    return io_error{fmt::format("{}: cannot close: {}", path, std::strerror(saved))};
  }
  if (::rename(name.data(), path.c_str()) != 0) {
    const int saved = errno;
    ::unlink(name.data());
    return io_error{fmt::format("{}: cannot replace: {}", path, std::strerror(saved))};
  }
  // Make the rename itself durable.
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return {};
}

written write_fd(int fd, const std::string& path, std::string_view bytes) {
  if (write_fully(fd, bytes)) return {};
  return io_error{fmt::format("{}: cannot write: {}", path, std::strerror(errno))};
}

// The descriptor a name of an already open stream stands for: writing there
// keeps the stream's offset and append mode, where reopening the name would
// not (and renaming over what it points to would replace the user's file).
std::optional<int> open_stream_name(std::string_view path) {
  if (path == "-" || path == "/dev/stdout") return STDOUT_FILENO;
  if (path == "/dev/stderr") return STDERR_FILENO;
  for (const std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    if (!path.starts_with(prefix)) continue;
    const auto digits = path.substr(prefix.size());
    if (digits.empty() || digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string_view::npos)
      return std::nullopt;
    return std::atoi(std::string(digits).c_str());
  }
  return std::nullopt;
}

std::string kind_word(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISBLK(mode)) return "a block device";
  return "not a regular file, device or pipe";
}

}  // namespace

namespace detail {

// A character device or FIFO: opened without O_CREAT or O_TRUNC and written.
// fstat after open makes sure it is still one, so a path swapped for a
// regular file meanwhile is never written over from its start.
written write_through(const std::string& path, std::string_view bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return io_error{fmt::format("{}: cannot open for writing: {}", path, std::strerror(errno))};
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !(S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))) {
    ::close(fd);
    return io_error{fmt::format("{}: changed while being written; nothing written", path)};
  }
  auto done = write_fd(fd, path, bytes);
  if (::close(fd) != 0 && done) return io_error{fmt::format("{}: cannot close: {}", path, std::strerror(errno))};
  return done;
}

}  // namespace detail

void input_set::add(const std::string& path) {
  if (path == "-") return;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;
  files_.push_back({st.st_dev, st.st_ino, path});
}

std::optional<std::string> input_set::input_named_by(const std::string& path) const {
  if (is_stdout(path) || open_stream_name(path)) return std::nullopt;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  for (const auto& f : files_)
    if (f.dev == st.st_dev && f.ino == st.st_ino) return f.path;
  return std::nullopt;
}

written input_set::refuse_as_output(const std::string& output, std::string_view in_place) const {
  const auto input = input_named_by(output);
  if (!input) return {};
  const std::string same = *input == output ? "" : fmt::format(" ({})", *input);
  if (!in_place.empty())
    return io_error{fmt::format("{}: refusing to overwrite the input{}; use {} to edit it", output, same, in_place)};
  return io_error{fmt::format("{}: refusing to overwrite the input{}; name another output file", output, same)};
}

written write_output(const std::string& path, std::string_view bytes) {
  if (const auto fd = open_stream_name(path)) {
    if (::fcntl(*fd, F_GETFD) < 0) return io_error{fmt::format("{}: no such open stream", path)};
    return write_fd(*fd, path, bytes);
  }
  struct stat lst {};
  if (::lstat(path.c_str(), &lst) != 0) {
    if (errno != ENOENT) return io_error{fmt::format("{}: cannot write: {}", path, std::strerror(errno))};
    const std::string dir = directory_of(path);
    struct stat dst {};
    if (::stat(dir.c_str(), &dst) != 0 || !S_ISDIR(dst.st_mode))
      return io_error{fmt::format("{}: the folder '{}' does not exist", path, dir)};
    return write_atomically(path, bytes);
  }
  std::string target = path;
  struct stat st = lst;
  if (S_ISLNK(lst.st_mode)) {
    if (::stat(path.c_str(), &st) != 0)
      return io_error{
          fmt::format("{}: a symbolic link to nothing ({}); refusing to replace the link", path, std::strerror(errno))};
    if (S_ISREG(st.st_mode)) {
      // Replaced beside the file the link names, so the link stays and
      // leads to the new content.
      std::unique_ptr<char, decltype(&std::free)> real(::realpath(path.c_str(), nullptr), &std::free);
      if (!real) return io_error{fmt::format("{}: cannot resolve the link: {}", path, std::strerror(errno))};
      target = real.get();
    }
  }
  if (S_ISREG(st.st_mode)) return write_atomically(target, bytes);
  if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return detail::write_through(path, bytes);
  return io_error{fmt::format("{}: is {}; refusing to write over it", path, kind_word(st.st_mode))};
}

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

}  // namespace edsc::io
