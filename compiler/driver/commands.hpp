#pragma once
#include <functional>

#include <CLI/CLI.hpp>

#include "driver/cli_model.hpp"

namespace edsc::driver {

// Exit status shared by every command: what CI scripts rely on.
enum exit_code : int { exit_ok = 0, exit_findings = 1, exit_failure = 2 };

// Each command registers its subcommand - with what every option takes and
// its examples (cli_model.hpp) - and stores the action to run once the
// command line has been parsed successfully.
using command_action = std::function<int()>;

void register_check(CLI::App& app, command_action& run);
void register_edit(CLI::App& app, command_action& run);
void register_dump(CLI::App& app, command_action& run);
void register_header(CLI::App& app, command_action& run);
void register_rules(CLI::App& app, command_action& run);
void register_fix(CLI::App& app, command_action& run);
void register_fmt(CLI::App& app, command_action& run);
void register_new(CLI::App& app, command_action& run);
void register_verify(CLI::App& app, command_action& run);
void register_lsp(CLI::App& app, command_action& run);
void register_net(CLI::App& app, command_action& run);
void register_doc(CLI::App& app, command_action& run);
void register_diff(CLI::App& app, command_action& run);
void register_probe(CLI::App& app, command_action& run);
void register_sim(CLI::App& app, command_action& run);
void register_explain(CLI::App& app, command_action& run);
void register_completions(CLI::App& app, command_action& run);
void register_connection(CLI::App& app, command_action& run);

}  // namespace edsc::driver
