#include "io/pipe.hpp"

#include <fcntl.h>
#include <sys/stat.h>

namespace edsc::io {

void widen_pipe(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISFIFO(st.st_mode)) return;
  const int current = ::fcntl(fd, F_GETPIPE_SZ);
  // Halving on refusal: a lowered fs/pipe-max-size still gets what it allows.
  for (int size = 1 << 20; size > current && size >= 65536; size /= 2)
    if (::fcntl(fd, F_SETPIPE_SZ, size) >= 0) return;
}

}  // namespace edsc::io
