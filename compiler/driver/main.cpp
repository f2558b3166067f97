#include <cstdio>
#include <exception>

#include <fmt/format.h>

#include "driver/commands.hpp"
#include "edsc_version.hpp"

int main(int argc, char** argv) {
  using namespace edsc::driver;
  try {
    CLI::App app{"edsc: a compiler for ODVA CIP Electronic Data Sheets (EDS)"};
    app.name("edsc");
    app.set_version_flag("--version", "edsc " EDSC_VERSION_STRING);
    app.require_subcommand(1);
    command_action run;
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
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      app.exit(e);
      return exit_failure;
    }
    return run ? run() : exit_failure;
  } catch (const std::exception& e) {
    // Last line of defence: a bug must still end with a message and status 2.
    std::fprintf(stderr, "edsc: internal error: %s\n", e.what());
    return exit_failure;
  }
}
