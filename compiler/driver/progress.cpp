#include "driver/progress.hpp"

#include <signal.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <fmt/format.h>

namespace edsc::driver {

namespace {

constexpr auto shown_after = std::chrono::seconds(1);
constexpr auto every = std::chrono::milliseconds(200);

// The terminal's width, so the line never wraps (a wrapped line is not erased by \r).
std::size_t columns(std::FILE* stream) {
  winsize w{};
  if (::ioctl(::fileno(stream), TIOCGWINSZ, &w) == 0 && w.ws_col > 8) return w.ws_col;
  return 80;
}

}  // namespace

progress_line::progress_line(std::FILE* stream) : stream_(stream), start_(std::chrono::steady_clock::now()) {
  if (::isatty(::fileno(stream_)) == 0) return;
  // Signals stay with the thread that runs the command: its waits wake on them.
  sigset_t all, previous;
  sigfillset(&all);
  ::pthread_sigmask(SIG_BLOCK, &all, &previous);
  thread_ = std::thread([this] { refresh(); });
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

progress_line::~progress_line() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(m_);
    done_ = true;
  }
  wake_.notify_all();
  thread_.join();
  if (shown_) {
    std::fputs("\r\033[K", stream_);
    std::fflush(stream_);
  }
}

void progress_line::set(std::string what) {
  std::lock_guard<std::mutex> lock(m_);
  what_ = std::move(what);
}

void progress_line::refresh() {
  std::unique_lock<std::mutex> lock(m_);
  if (wake_.wait_for(lock, shown_after, [this] { return done_; })) return;
  std::string last;
  do {
    const auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    auto line = fmt::format("edsc: {} ({:.0f} s)", what_, seconds);
    const auto width = columns(stream_) - 1;
    if (line.size() > width) {
      auto cut = width;
      while (cut > 0 && (static_cast<unsigned char>(line[cut]) & 0xC0) == 0x80) --cut;  // not inside a character
      line.resize(cut);
    }
    if (line == last) continue;  // the terminal shows it already
    std::fputs("\r\033[K", stream_);
    std::fputs(line.c_str(), stream_);
    std::fflush(stream_);
    last = std::move(line);
    shown_ = true;
  } while (!wake_.wait_for(lock, every, [this] { return done_; }));
}

}  // namespace edsc::driver
