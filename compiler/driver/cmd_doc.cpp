// `edsc doc FILE -o device.html` and `edsc doc DIR -o site/`: datasheets a
// person can read (docs/doc.md).
#include <algorithm>
#include <filesystem>
#include <memory>
#include <thread>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "doc/site.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "io/collect_inputs.hpp"
#include "io/output_target.hpp"

namespace edsc::driver {

namespace {

namespace fs = std::filesystem;

struct doc_cli {
  std::string input, output;
  doc::page_format format = doc::page_format::html;
  unsigned jobs = 0;  // 0: one per core
};

int status_of(const std::vector<doc::library_entry>& entries, bool failed) {
  if (failed) return exit_failure;
  for (const auto& e : entries)
    if (e.unreadable) return exit_failure;
  for (const auto& e : entries)
    if (e.sum.errors > 0) return exit_findings;
  return exit_ok;
}

int run_one(const doc_cli& cli) {
  const bool to_stdout = io::is_stdout(cli.output);
  if (to_stdout && cli.format == doc::page_format::markdown) {
    print_error("--format=md writes SVG files beside the page: give -o a file name");
    return exit_failure;
  }
  if (refuse_input_as_output(cli.output, {cli.input}) != exit_ok) return exit_failure;
  const auto stem = fs::path(cli.output).stem().string();
  auto page = doc::render_file(cli.input, cli.format, stem, {});
  if (page.entry.unreadable) {
    print_error(page.entry.problem);
    return exit_failure;
  }
  bool failed = false;
  const auto dir = fs::path(cli.output).parent_path();
  for (const auto& [name, content] : page.files) {
    const auto side = (dir / name).string();
    failed = failed || refuse_input_as_output(side, {cli.input}) != exit_ok || write_result(side, content) != exit_ok;
  }
  if (failed || write_result(cli.output, page.text) != exit_ok) return exit_failure;
  return status_of({page.entry}, false);
}

int run_site(const doc_cli& cli) {
  const auto inputs = io::collect_inputs({cli.input});
  for (const auto& e : inputs.errors) print_error(e.message);
  if (inputs.files.empty()) return exit_failure;
  const unsigned jobs = cli.jobs > 0 ? cli.jobs : std::max(1u, std::thread::hardware_concurrency());
  const auto site = doc::build_site(inputs.files, cli.input, cli.output, cli.format, jobs);
  for (const auto& e : site.entries)
    if (e.unreadable) print_error(e.problem);
  for (const auto& f : site.failures) print_error(f);
  std::size_t errors = 0, warnings = 0;
  for (const auto& e : site.entries) {
    errors += e.sum.errors;
    warnings += e.sum.warnings;
  }
  const auto collisions = doc::identity_collisions(site.entries);
  // Pages, not inputs: an unreadable file or a page that could not be written is not one.
  const auto written = static_cast<std::size_t>(
      std::count_if(site.entries.begin(), site.entries.end(), [](const auto& e) { return !e.page.empty(); }));
  write_all(stderr, fmt::format("{} written to {} ({}, {}{})\n", plural(written, "page"), cli.output,
                                plural(errors, "error"), plural(warnings, "warning"),
                                collisions.empty() ? "" : ", " + plural(collisions.size(), "identity collision")));
  return status_of(site.entries, !site.failures.empty() || !inputs.errors.empty());
}

int run_doc(const doc_cli& cli) {
  std::error_code ec;
  if (fs::is_directory(cli.input, ec)) {
    if (io::is_stdout(cli.output)) {
      print_error("a folder gives a site of pages: give -o a folder");
      return exit_failure;
    }
    // Pages beside the EDS files would mix the site into the library (and
    // its index.html over a file of the same name).
    if (io::same_file(cli.input, cli.output)) {
      print_error(
          fmt::format("{}: the site cannot go into the folder it documents; name another folder "
                      "(a new one inside it is fine)",
                      cli.output));
      return exit_failure;
    }
    if (fs::exists(cli.output, ec) && !fs::is_directory(cli.output, ec)) {
      print_error(fmt::format("{}: is not a folder; a folder of EDS files gives a site of pages", cli.output));
      return exit_failure;
    }
    return run_site(cli);
  }
  return run_one(cli);
}

}  // namespace

void register_doc(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<doc_cli>();
  auto* cmd =
      app.add_subcommand("doc", "Write a readable datasheet of an EDS file, or a site for a folder (docs/doc.md)");
  takes(cmd->add_option("input", cli->input, "The EDS file, or a folder searched recursively for *.eds"), arg_kind::eds)
      ->required();
  takes(
      cmd->add_option("-o,--output", cli->output, "The page to write ('-' for standard output), or the site's folder"),
      arg_kind::output)
      ->required();
  add_choice(cmd, "--format", cli->format, {{"html", doc::page_format::html}, {"md", doc::page_format::markdown}},
             "html (the default) or md (Markdown, bit maps as SVG files beside it)");
  add_number(cmd, "-j,--jobs", cli->jobs, 0u, 1024u, "Files documented in parallel (0, the default: one per core)");
  add_example(cmd, "edsc doc device.eds -o device.html", "a datasheet");
  add_example(cmd, "edsc doc library/ -o site/", "a site for a library");
  cmd->callback([&run, cli] { run = [cli] { return run_doc(*cli); }; });
}

}  // namespace edsc::driver
