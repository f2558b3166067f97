// `edsc completions bash|zsh|fish` prints a shell's completion script;
// `edsc _man DIR` (hidden, for the build) writes the man pages; `edsc
// _model` (hidden, for the tests) prints the command line model as JSON.
// All read the command definitions themselves, so they say what --help says.
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "driver/choice.hpp"
#include "driver/cli_model.hpp"
#include "driver/commands.hpp"
#include "driver/completion.hpp"
#include "driver/manpage.hpp"
#include "driver/output.hpp"
#include "edsc_version.hpp"

namespace edsc::driver {

namespace {

struct completions_cli {
  std::string shell, man_dir;
};

}  // namespace

void register_completions(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<completions_cli>();
  auto* cmd = app.add_subcommand("completions", "Print the shell completion script for bash, zsh or fish");
  add_choice(cmd, "shell", cli->shell, {"bash", "zsh", "fish"}, "The shell: bash, zsh or fish")->required();
  add_example(cmd, "edsc completions bash > ~/.local/share/bash-completion/completions/edsc", "install bash's");
  cmd->callback([&run, &app, cli] {
    run = [&app, cli] { return write_result("-", *completion_script(describe(app), cli->shell)); };
  });

  auto* model = app.add_subcommand("_model", "");
  model->group("");  // what the tests walk to reach every writer and every number
  model->callback([&run, &app] { run = [&app] { return write_result("-", to_json(describe(app))); }; });

  auto* man = app.add_subcommand("_man", "");
  man->group("");  // a build step, not a command for users
  man->add_option("dir", cli->man_dir)->required();
  man->callback([&run, &app, cli] {
    run = [&app, cli] {
      std::error_code ec;
      std::filesystem::create_directories(cli->man_dir, ec);
      for (const auto& [name, text] : man_pages(describe(app), EDSC_VERSION_STRING))
        if (write_result((std::filesystem::path(cli->man_dir) / name).string(), text) != exit_ok) return exit_failure;
      return exit_ok;
    };
  });
}

}  // namespace edsc::driver
