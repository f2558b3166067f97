#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "check/check_file.hpp"
#include "diag/render_text.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "io/collect_inputs.hpp"
#include "model/identity.hpp"

namespace edsc::driver {

namespace {

struct check_cli {
  std::vector<std::string> inputs;
  std::vector<std::string> warning_flags;
  std::string stdin_name;  // --stdin-filename
  color_mode color = color_mode::auto_detect;
  report_format format = report_format::text;
  std::size_t max_errors = 0;  // 0: no limit
  unsigned jobs = 0;           // 0: one per core
  std::uint8_t networks = 0;   // --network; 0: detect per file
};

// Checks files on worker threads; hands results back in input order so the
// output is the same whatever the scheduling.
class ordered_checker {
 public:
  // `stdin_read` is what `-` among `files` read (at most one `-`).
  ordered_checker(const std::vector<std::string>& files, const check_options& options, unsigned jobs,
                  io::read_result stdin_read)
      : files_(files), options_(options), stdin_read_(std::move(stdin_read)), results_(files.size()) {
    // One worker is the calling thread itself (take() checks on demand): a
    // thread of its own would cost its start, and a malloc arena of its own
    // whose every page is faulted in afresh.
    const unsigned n = std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(files.size())));
    if (n > 1)
      for (unsigned i = 0; i < n; ++i) workers_.emplace_back([this] { work(); });
  }
  ~ordered_checker() {
    for (auto& w : workers_) w.join();
  }

  checked_file take(std::size_t i) {
    if (workers_.empty()) return check(i);
    std::unique_lock lock(mutex_);
    ready_.wait(lock, [&] { return results_[i].has_value(); });
    auto out = std::move(*results_[i]);
    results_[i].reset();
    return out;
  }

 private:
  void work() {
    for (std::size_t i = next_++; i < files_.size(); i = next_++) {
      auto result = check(i);
      {
        std::lock_guard lock(mutex_);
        results_[i] = std::move(result);
      }
      ready_.notify_all();
    }
  }

  checked_file check(std::size_t i) {
    return io::is_stdin(files_[i]) ? check_stdin() : check_file(files_[i], options_);
  }

  const std::vector<std::string>& files_;
  checked_file check_stdin() {
    if (!stdin_read_) return checked_file{{}, stdin_read_.error().message};
    return check_source(std::move(stdin_read_.value()), options_);
  }

  const check_options& options_;
  io::read_result stdin_read_;
  std::vector<std::optional<checked_file>> results_;
  std::atomic<std::size_t> next_{0};
  std::mutex mutex_;
  std::condition_variable ready_;
  std::vector<std::thread> workers_;
};

std::string summary_line(const report_totals& t, std::size_t hidden) {
  // Notes are counted as the JSON summary counts them.
  std::string line = fmt::format("{} checked: {}, {}, {}", plural(t.files, "file"), plural(t.errors, "error"),
                                 plural(t.warnings, "warning"), plural(t.notes, "note"));
  if (hidden > 0) line += fmt::format(" ({} not shown: --max-errors)", hidden);
  return line + "\n";
}

int run_check(const check_cli& cli) {
  check_options options;
  options.networks = cli.networks;
  for (const auto& flag : cli.warning_flags) {
    if (auto taken = options.policy.add_flag(flag); !taken) {
      print_error(taken.error());
      return exit_failure;
    }
  }
  const auto inputs = io::collect_inputs(cli.inputs);
  const auto stdin_args = std::count_if(inputs.files.begin(), inputs.files.end(), io::is_stdin);
  if (stdin_args > 1) {
    print_error("'-' (standard input) can be named only once");
    return exit_failure;
  }
  if (!stdin_filename_used(stdin_args > 0, cli.stdin_name)) return exit_failure;
  for (const auto& e : inputs.errors) print_error(e.message);
  bool io_failed = !inputs.errors.empty();
  // Read up front (by one thread); `-` is then checked in its place among
  // the inputs, and a read failure is reported like any unreadable file.
  io::read_result stdin_read;
  if (stdin_args > 0) stdin_read = io::read_stdin(cli.stdin_name);

  const unsigned jobs = cli.jobs > 0 ? cli.jobs : std::max(1u, std::thread::hardware_concurrency());
  const text_style style{cli.format == report_format::text && use_color(cli.color, stdout)};
  report_totals totals;
  std::size_t shown_errors = 0, hidden = 0;
  std::vector<file_report> kept;  // for the whole-run formats
  {
    ordered_checker checker(inputs.files, options, jobs, std::move(stdin_read));
    std::string out;
    for (std::size_t i = 0; i < inputs.files.size(); ++i) {
      auto result = checker.take(i);
      if (result.io_error) {
        print_error(*result.io_error);
        io_failed = true;
        continue;
      }
      auto& report = result.report;
      ++totals.files;
      totals.add(report.diags);
      if (cli.max_errors > 0) {
        std::erase_if(report.diags, [&](const diagnostic& d) {
          if (d.level != severity::error) return shown_errors >= cli.max_errors;
          if (shown_errors < cli.max_errors) {
            ++shown_errors;
            return false;
          }
          ++hidden;
          return true;
        });
      }
      if (cli.format == report_format::text) {
        out.clear();
        for (const auto& d : report.diags) render_text(*report.source, d, style, out);
        write_all(stdout, out);
      } else {
        kept.push_back(std::move(report));
      }
    }
  }
  switch (cli.format) {
    case report_format::text: write_all(stdout, summary_line(totals, hidden)); break;
    case report_format::json: write_all(stdout, render_json(kept, totals)); break;
    case report_format::sarif: write_all(stdout, render_sarif(kept)); break;
  }
  std::fflush(stdout);
  if (io_failed) return exit_failure;
  return totals.errors > 0 ? exit_findings : exit_ok;
}

}  // namespace

void register_check(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<check_cli>();
  auto* cmd = app.add_subcommand("check", "Parse and check EDS files, reporting problems like a compiler");
  takes(cmd->add_option("inputs", cli->inputs,
                        "EDS files, directories searched recursively for *.eds, or '-' for standard input"),
        arg_kind::eds)
      ->required();
  add_stdin_filename(cmd, cli->stdin_name);
  add_report_options(cmd, cli->color, cli->format, cli->warning_flags);
  add_number(cmd, "--max-errors", cli->max_errors, std::size_t{0}, std::size_t{1000000},
             "Show at most N errors (0: all)");
  add_choice(cmd, "--network", cli->networks,
             {{"devicenet", std::uint8_t{model::net_devicenet}},
              {"ethernetip", std::uint8_t{model::net_ethernetip}},
              {"controlnet", std::uint8_t{model::net_controlnet}}},
             "Check as this network instead of detecting it");
  add_number(cmd, "-j,--jobs", cli->jobs, 0u, 1024u, "Files checked in parallel (0, the default: one per core)");
  add_example(cmd, "edsc check device.eds", "check one file");
  add_example(cmd, "edsc check --format sarif library/ > edsc.sarif", "check a folder for code scanning in CI");
  add_example(cmd, "edsc check -Werror -Wno-error=io-info device.eds", "fail on warnings, except those of one group");
  cmd->callback([&run, cli] { run = [cli] { return run_check(*cli); }; });
}

}  // namespace edsc::driver
