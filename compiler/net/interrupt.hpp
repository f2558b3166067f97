#pragma once
// Ctrl-C (SIGINT) or SIGTERM during a live run. The handler only notes the
// signal; the run looks at it between requests and while it watches I/O,
// so it still closes every connection it opened (a device would otherwise
// keep its outputs owned until the connection times out), reports what it
// found, and then ends.
namespace edsc::net {

// Installs the handler for SIGINT and SIGTERM (without SA_RESTART: a wait
// wakes up), unless the signal was ignored when edsc started.
void catch_interrupts();
// The signal caught since, or 0.
[[nodiscard]] int interruption();

}  // namespace edsc::net
