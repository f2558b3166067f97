#include "net/interrupt.hpp"

#include <csignal>
#include <initializer_list>

namespace edsc::net {

namespace {

volatile std::sig_atomic_t caught = 0;

void note_signal(int sig) {
  if (caught == 0) caught = sig;
}

}  // namespace

void catch_interrupts() {
  struct sigaction sa {};
  sa.sa_handler = note_signal;
  sigemptyset(&sa.sa_mask);
  for (const int sig : {SIGINT, SIGTERM}) {
    // A signal ignored on entry stays ignored: a shell starts background
    // jobs so, that Ctrl-C at the terminal does not reach them.
    struct sigaction was {};
    if (::sigaction(sig, nullptr, &was) == 0 && was.sa_handler == SIG_IGN) continue;
    ::sigaction(sig, &sa, nullptr);
  }
}

int interruption() { return caught; }

}  // namespace edsc::net
