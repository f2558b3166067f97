#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "driver/suggest.hpp"
#include "driver/usage_error.hpp"
#include "edsc_version.hpp"

namespace {

using namespace edsc::driver;

using registrar = void (*)(CLI::App&, command_action&);
struct command_entry {
  std::string_view name;
  registrar add;
};
// In the order `edsc --help` lists them.
constexpr command_entry commands[] = {
    {"check", register_check},     {"edit", register_edit},
    {"dump", register_dump},       {"header", register_header},
    {"rules", register_rules},     {"fix", register_fix},
    {"fmt", register_fmt},         {"new", register_new},
    {"verify", register_verify},   {"lsp", register_lsp},
    {"net", register_net},         {"doc", register_doc},
    {"diff", register_diff},       {"probe", register_probe},
    {"sim", register_sim},         {"connection", register_connection},
    {"explain", register_explain}, {"completions", register_completions},
};

// Building every command's options costs more than the rest of a small run,
// so only the command named is built when nothing else could tell: its name
// is the first argument and no other argument names a command (CLI11 would
// otherwise consider the sibling). `--version` alone needs none; help,
// completions and anything unusual get the whole table.
void register_commands(CLI::App& app, command_action& run, const std::vector<const char*>& args) {
  if (args.size() == 2 && std::string_view(args[1]) == "--version") return;
  const command_entry* named = nullptr;
  int words_naming_commands = 0;
  for (std::size_t i = 1; i < args.size(); ++i)
    for (const auto& c : commands)
      if (std::string_view(args[i]) == c.name) {
        ++words_naming_commands;
        if (i == 1) named = &c;
      }
  if (named != nullptr && words_naming_commands == 1 && named->name != "completions") {
    named->add(app, run);
    return;
  }
  for (const auto& c : commands) c.add(app, run);
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
  auto args = expand_help(argc, argv);
  register_commands(app, run, args);
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
    print_error(usage_message(e, app, n, args.data()));
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
