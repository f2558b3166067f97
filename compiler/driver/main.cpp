#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "driver/suggest.hpp"
#include "edsc_version.hpp"

namespace {

using namespace edsc::driver;

void register_all(CLI::App& app, command_action& run) {
  register_check(app, run);
  register_edit(app, run);
  register_dump(app, run);
  register_header(app, run);
  register_rules(app, run);
  register_fix(app, run);
  register_fmt(app, run);
  register_new(app, run);
  register_verify(app, run);
  register_lsp(app, run);
  register_net(app, run);
  register_doc(app, run);
  register_diff(app, run);
  register_probe(app, run);
  register_sim(app, run);
  register_completions(app, run);
}

// `edsc help [COMMAND...]` is `edsc [COMMAND...] --help`, as in git and cargo.
std::vector<const char*> expand_help(int argc, char** argv) {
  std::vector<const char*> args(argv, argv + argc);
  if (argc >= 2 && std::string_view(argv[1]) == "help") {
    args.erase(args.begin() + 1);
    args.push_back("--help");
  }
  return args;
}

int run_main(int argc, char** argv) {
  CLI::App app{"edsc: a compiler for ODVA CIP Electronic Data Sheets (EDS)"};
  app.name("edsc");
  app.set_version_flag("--version", "edsc " EDSC_VERSION_STRING);
  app.require_subcommand(1);
  app.footer("edsc help COMMAND (or edsc COMMAND --help) describes one command; docs/cli.md all of them.");
  command_action run;
  register_all(app, run);
  auto args = expand_help(argc, argv);
  const int n = static_cast<int>(args.size());
  if (auto err = unknown_command(app, n, args.data())) {
    print_error(*err);
    return exit_failure;
  }
  try {
    // CLI11 wants the words in reverse order when given a vector.
    std::vector<std::string> words(args.rbegin(), args.rend() - 1);
    app.parse(words);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One shape for every error, CLI11's included: "edsc: error: ...".
    if (auto hint = option_hint(app, n, args.data())) print_error(*hint);
    else print_error(e.what());
    return exit_failure;
  }
  return run ? run() : exit_failure;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run_main(argc, argv);
  } catch (const std::exception& e) {
    // Last line of defence: a bug must still end with a message and status 2.
    std::fprintf(stderr, "edsc: error: internal error: %s\n", e.what());
    return exit_failure;
  }
}
