#include <malloc.h>  // mallopt (glibc)
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <memory>

#include "diag/policy.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "io/pipe.hpp"
#include "lsp/server.hpp"
#include "lsp/transport.hpp"

namespace edsc::driver {

namespace {

struct lsp_cli {
  std::vector<std::string> warning_flags;
  bool stdio = true;
};

std::size_t read_stdin(char* buf, std::size_t n) {
  for (;;) {
    const auto got = ::read(STDIN_FILENO, buf, n);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno != EINTR) return 0;
  }
}

bool write_stdout(std::string_view bytes) {
  while (!bytes.empty()) {
    const auto put = ::write(STDOUT_FILENO, bytes.data(), bytes.size());
    if (put < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(put));
  }
  return true;
}

// True when the client has sent more than what was read so far.
bool input_waiting() {
  pollfd p{STDIN_FILENO, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0;
}

int run_lsp(const lsp_cli& cli) {
  // Validate the command line's flags before speaking the protocol.
  diag_policy probe;
  for (const auto& flag : cli.warning_flags) {
    if (auto taken = probe.add_flag(flag); !taken) {
      print_error(taken.error());
      return exit_failure;
    }
  }
  // Every change re-analyses the document into arrays of the same sizes as
  // the last time. By default glibc hands the freed top of the heap back to
  // the kernel and maps large blocks afresh, so each change paid ~580 page
  // faults (1-1.5 ms) to touch the same amount of memory again; a server
  // keeps it instead. Blocks above 32 MB (documents of several MB) are still
  // mapped and unmapped one by one.
  ::mallopt(M_MMAP_THRESHOLD, 32 << 20);
  ::mallopt(M_TRIM_THRESHOLD, 256 << 20);
  // A client that goes away must end the server, not kill it with SIGPIPE mid-write.
  ::signal(SIGPIPE, SIG_IGN);
  // A full-text change carries the whole document: through the default
  // 64 kB pipe a 441 kB file took a dozen wake-ups of client and server
  // (scripts/bench-lsp medians 4.3-6.6 -> 3.4-4.4 ms a change,
  // docs/performance.md).
  io::widen_pipe(STDIN_FILENO);
  io::widen_pipe(STDOUT_FILENO);
  bool output_ok = true;
  lsp::server srv(
      lsp::server_options{cli.warning_flags},
      [&](const std::string& body) { output_ok = output_ok && write_stdout(lsp::frame_message(body)); },
      [](std::string_view line) { std::fprintf(stderr, "%.*s\n", static_cast<int>(line.size()), line.data()); });
  lsp::frame_reader reader(read_stdin);
  while (!srv.exited() && output_ok) {
    auto f = reader.next();
    if (f.what == lsp::frame::kind::end) break;
    if (f.what == lsp::frame::kind::bad_header) {
      std::fprintf(stderr, "edsc lsp: %s\n", f.error.c_str());
      continue;
    }
    srv.handle(f.body);
    // Diagnostics once the client pauses, so a burst of keystrokes is analysed once.
    if (!reader.buffered() && !input_waiting()) srv.idle();
  }
  return srv.exit_code();
}

}  // namespace

void register_lsp(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<lsp_cli>();
  auto* cmd = app.add_subcommand("lsp", "Run the language server (LSP over standard input and output)");
  takes(cmd->add_option("-W", cli->warning_flags, "Diagnostic policy, as for check (e.g. -Wpedantic)"),
        arg_kind::warning)
      ->allow_extra_args(false);
  cmd->add_flag("--stdio", cli->stdio, "Talk over standard input and output (the default and only transport)");
  add_example(cmd, "edsc lsp", "started by an editor, not by hand");
  cmd->callback([&run, cli] { run = [cli] { return run_lsp(*cli); }; });
}

}  // namespace edsc::driver
