#include "io/map_file.hpp"

#include <atomic>
#include <csignal>
#include <cstdint>
#include <mutex>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

namespace edsc::io {

namespace {

// Below this a read costs a few page faults at most, no more than mapping.
constexpr std::uint64_t min_mapped_bytes = 16 * 1024;

// The live mappings, for the SIGBUS handler: fixed storage and atomics only,
// as a signal handler may read nothing else. One per file being read at once
// (`check -j N` reads N); when all are taken, files are read instead.
struct slot {
  std::atomic<bool> used{false};
  std::atomic<std::uintptr_t> begin{0};  // 0: nothing mapped here
  std::atomic<std::size_t> length{0};
  std::atomic<bool> changed{false};
};
constexpr std::size_t slot_count = 256;
slot slots[slot_count];

struct sigaction previous_sigbus {};
std::once_flag handler_installed;

void on_sigbus(int sig, siginfo_t* info, void* context) {
  const auto address = reinterpret_cast<std::uintptr_t>(info->si_addr);
  for (auto& s : slots) {
    const auto begin = s.begin.load(std::memory_order_acquire);
    const auto length = s.length.load(std::memory_order_acquire);
    if (begin == 0 || address - begin >= length) continue;
    // The file shrank under its mapping: zero pages in its place, and the
    // access that faulted reads a zero when the handler returns.
    if (::mmap(reinterpret_cast<void*>(begin), length, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) !=
        MAP_FAILED) {
      s.changed.store(true, std::memory_order_release);
      return;
    }
    break;
  }
  // Not a mapped input: what SIGBUS did before (a sanitizer's report, or
  // the default action: raised again, it is delivered on return).
  if ((previous_sigbus.sa_flags & SA_SIGINFO) != 0 && previous_sigbus.sa_sigaction != nullptr) {
    previous_sigbus.sa_sigaction(sig, info, context);
    return;
  }
  if ((previous_sigbus.sa_flags & SA_SIGINFO) == 0 && previous_sigbus.sa_handler != SIG_DFL &&
      previous_sigbus.sa_handler != SIG_IGN) {
    previous_sigbus.sa_handler(sig);
    return;
  }
  ::signal(SIGBUS, SIG_DFL);
  ::raise(sig);
}

bool install_handler() {
  static bool ok = false;
  std::call_once(handler_installed, [] {
    struct sigaction act {};
    act.sa_sigaction = on_sigbus;
    act.sa_flags = SA_SIGINFO;
    sigemptyset(&act.sa_mask);
    ok = ::sigaction(SIGBUS, &act, &previous_sigbus) == 0;
  });
  return ok;
}

slot* claim_slot() {
  for (auto& s : slots) {
    bool expected = false;
    if (s.used.compare_exchange_strong(expected, true, std::memory_order_acq_rel)) return &s;
  }
  return nullptr;
}

struct fd_guard {
  int fd;
  ~fd_guard() {
    if (fd >= 0) ::close(fd);
  }
};

// Unmaps and gives the slot back when the last source using it goes.
struct mapping {
  void* base;
  std::size_t length;
  slot* s;
  mapping(void* b, std::size_t l, slot* owner) : base(b), length(l), s(owner) {}
  mapping(const mapping&) = delete;
  mapping& operator=(const mapping&) = delete;
  ~mapping() {
    // Unlisted before unmapping: nothing reads these bytes any more.
    s->begin.store(0, std::memory_order_release);
    ::munmap(base, length);
    s->used.store(false, std::memory_order_release);
  }
};

}  // namespace

io_error changed_while_read(const std::string& path) {
  return io_error{fmt::format("{}: cannot read file: it shrank while it was being read; try again", path)};
}

read_result map_source(const std::string& path, std::uint64_t max_bytes) {
  const auto read_instead = [&] { return read_source(path, max_bytes); };
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return read_instead();  // read_source words the error
  fd_guard guard{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return read_instead();
  const auto size = static_cast<std::uint64_t>(st.st_size);
  const auto page = static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  // The bytes are followed by a NUL, as a read source's are: the rest of the
  // last page is zeros, unless the file ends on a page boundary.
  if (size < min_mapped_bytes || size > max_bytes || size % page == 0 || !install_handler()) return read_instead();
  slot* s = claim_slot();
  if (s == nullptr) return read_instead();
  const auto length = static_cast<std::size_t>((size + page - 1) / page * page);
  void* base = ::mmap(nullptr, length, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
  if (base == MAP_FAILED) {
    s->used.store(false, std::memory_order_release);
    return read_instead();
  }
  s->changed.store(false, std::memory_order_relaxed);
  s->length.store(length, std::memory_order_release);
  s->begin.store(reinterpret_cast<std::uintptr_t>(base), std::memory_order_release);
  auto owner = std::make_shared<const mapping>(base, length, s);
  const std::string_view bytes(static_cast<const char*>(base), static_cast<std::size_t>(size));
  return std::make_unique<source_file>(path, std::move(owner), bytes, &s->changed);
}

}  // namespace edsc::io
