#pragma once
#include <sys/types.h>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/read_file.hpp"

namespace edsc::io {

// The one output policy of every command that writes (docs/cli.md, "Output
// files"), and the only way to write a file: the raw atomic write is internal
// to it (a test finds any other writer in compiler/). `-` is standard output
// everywhere.
[[nodiscard]] inline bool is_stdout(std::string_view path) { return path == "-"; }

// The files a command reads, by device and inode, so that an output naming
// one of them is caught however it is spelt: `./x.eds`, a symbolic link, a
// hard link, a bind mount.
class input_set {
 public:
  // Remembers an input; `-` and paths that cannot be read are ignored (the
  // read itself reports those).
  void add(const std::string& path);
  // The input `path` names, or nothing.
  [[nodiscard]] std::optional<std::string> input_named_by(const std::string& path) const;
  // A usage error when `output` is one of the inputs; `in_place` names the
  // command's option for rewriting its input, empty where it has none.
  [[nodiscard]] written refuse_as_output(const std::string& output, std::string_view in_place) const;

 private:
  struct file_id {
    dev_t dev;
    ino_t ino;
    std::string path;
  };
  std::vector<file_id> files_;
};

// True when both paths name the same existing file (hard links and symlinks
// included).
[[nodiscard]] bool same_file(const std::string& a, const std::string& b);

// Writes `bytes` to what `path` names, never replacing anything but a regular
// file:
//   `-`, /dev/stdout, /dev/stderr, /dev/fd/N   that descriptor, as it is open
//   a missing path or a regular file           atomically: a temporary file
//                                              beside it, fsync, rename
//   a symbolic link to a regular file          atomically beside the file it
//                                              names; the link stays a link
//   a character device or FIFO (or a link to one)  opened and written through
//   a directory, socket, block device or dangling link  refused
// On failure a file at `path` is as it was.
[[nodiscard]] written write_output(const std::string& path, std::string_view bytes);

namespace detail {
// The written-through case of write_output: `path` was a character device or
// FIFO when looked at; when what open() finds is no longer one, nothing is
// written and the error says the path changed. Named here so the race it
// guards against can be tested without winning it.
[[nodiscard]] written write_through(const std::string& path, std::string_view bytes);
}  // namespace detail

}  // namespace edsc::io
