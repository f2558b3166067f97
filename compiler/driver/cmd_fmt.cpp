#include <memory>

#include <fmt/format.h>

#include "diag/render_text.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/destination.hpp"
#include "driver/fix_hint.hpp"
#include "driver/output.hpp"
#include "edit/analyze.hpp"
#include "edit/fingerprint.hpp"
#include "edit/format.hpp"
#include "io/read_file.hpp"

namespace edsc::driver {

namespace {

struct fmt_options {
  destination dest;
  bool check = false;
  std::string eol;  // lf | crlf | empty (keep)
};

int run_fmt(const fmt_options& opt) {
  if (const int rc = opt.dest.refuse_overwrite(); rc != exit_ok) return rc;
  const auto input_file = opt.dest.read();
  if (!input_file) return exit_failure;
  const auto& src = *input_file;
  const std::string input(src.text());
  const auto a = edit::analyze(src.path(), input);
  if (a->has_syntax_errors()) {
    std::string report;
    for (const auto& d : a->syntax)
      render_text(*a->source, d, text_style{use_color(color_mode::auto_detect, stderr)}, report);
    write_all(stderr, report);
    print_error(fmt::format("{}: not formatted: fix the syntax errors first{}", src.path(), fix_hint(a->syntax)));
    return exit_findings;
  }
  edit::format_options options;
  options.eol = opt.eol == "crlf" ? "\r\n" : opt.eol == "lf" ? "\n" : "";
  const auto out = edit::format(a->tree, options);
  if (!out) {
    print_error(fmt::format("{}: not formatted: {}", src.path(), out.error().why));
    return exit_findings;
  }
  // Layout only: a formatted file that means something else is a bug, and
  // is never written.
  if (*out != input && !edit::means_the_same(*a, src.path(), *out)) {
    print_error(
        fmt::format("{}: internal error: formatting would change the file's meaning; nothing written", src.path()));
    return exit_failure;
  }
  if (opt.check) {
    if (*out == input) return exit_ok;
    // The command that makes this same check pass: with its --eol.
    const auto eol = opt.eol.empty() ? std::string() : " --eol " + opt.eol;
    write_all(stderr, io::is_stdin(opt.dest.input)
                          ? fmt::format("{}: not formatted\n", src.path())
                          : fmt::format("{}: not formatted (edsc fmt --in-place{} {} formats it)\n", src.path(), eol,
                                        src.path()));
    return exit_findings;
  }
  return opt.dest.write(*out);
}

}  // namespace

void register_fmt(CLI::App& app, command_action& run) {
  auto opt = std::make_shared<fmt_options>();
  auto* cmd = app.add_subcommand("fmt", "Lay an EDS file out canonically without changing its meaning");
  opt->dest.add_options(*cmd, "The EDS file to format");
  cmd->add_flag("--check", opt->check, "Write nothing; exit 1 when the file is not formatted (for CI)");
  add_choice(cmd, "--eol", opt->eol, {"lf", "crlf"}, "Line endings of the output (default: keep the file's)");
  add_example(cmd, "edsc fmt --in-place device.eds", "lay the file out canonically");
  add_example(cmd, "edsc fmt --check device.eds", "fail when it is not (CI)");
  cmd->callback([&run, opt] { run = [opt] { return run_fmt(*opt); }; });
}

}  // namespace edsc::driver
