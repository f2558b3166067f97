#include "live/interrupt.hpp"

#include <csignal>

namespace edsc::live {

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
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
}

int interruption() { return caught; }

}  // namespace edsc::live
