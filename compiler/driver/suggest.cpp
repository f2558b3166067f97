#include "driver/suggest.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace edsc::driver {

namespace {

std::size_t distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::vector<const CLI::App*> subcommands_of(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App*) { return true; });
}

const CLI::App* subcommand_named(const CLI::App& app, std::string_view name) {
  for (const auto* sub : subcommands_of(app))
    if (sub->get_name() == name) return sub;
  return nullptr;
}

// The commands a user may be told about (not the hidden build steps).
std::vector<std::string> names_of(const CLI::App& app) {
  std::vector<std::string> out;
  for (const auto* sub : subcommands_of(app))
    if (!sub->get_group().empty()) out.push_back(sub->get_name());
  return out;
}

}  // namespace

const CLI::App& command_named(const CLI::App& app, int argc, const char* const* argv) {
  const CLI::App* at = &app;
  for (int i = 1; i < argc; ++i) {
    const std::string_view w = argv[i];
    if (w.starts_with("-")) continue;
    if (const auto* sub = subcommand_named(*at, w)) at = sub;
  }
  return *at;
}

std::optional<std::string> nearest(std::string_view word, const std::vector<std::string>& choices) {
  std::optional<std::string> best;
  std::size_t best_d = 0;
  for (const auto& c : choices) {
    const auto d = distance(word, c);
    if (!best || d < best_d) {
      best = c;
      best_d = d;
    }
  }
  // A third of the word, at least one edit and at most three: "chek" finds
  // "check", "foo" finds nothing.
  const std::size_t limit = std::clamp<std::size_t>(word.size() / 3, 1, 3);
  if (!best || best_d > limit) return std::nullopt;
  return best;
}

std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv) {
  // A command that has commands (edsc, edsc net) takes only flags, so its
  // first word is one of them.
  const CLI::App* at = &app;
  std::string path;
  for (int i = 1; i < argc && !subcommands_of(*at).empty(); ++i) {
    const std::string_view w = argv[i];
    if (w.starts_with("-")) continue;
    if (at == &app && w == "help") return std::nullopt;
    const std::string prefix = path.empty() ? "" : path + " ";
    if (const auto* sub = subcommand_named(*at, w)) {
      at = sub;
      path = prefix + std::string(w);
      continue;
    }
    std::string msg = fmt::format("unknown command '{}{}'", prefix, w);
    if (const auto near = nearest(w, names_of(*at))) msg += fmt::format("; did you mean '{}{}'?", prefix, *near);
    return msg + fmt::format(" (edsc {}--help lists the commands)", prefix);
  }
  return std::nullopt;
}

std::optional<std::string> option_hint(const CLI::App& app, int argc, const char* const* argv) {
  const auto& cmd = command_named(app, argc, argv);
  std::vector<std::string> longs, known;
  for (const auto* opt : cmd.get_options())
    for (const auto& n : opt->get_lnames()) {
      known.push_back("--" + n);
      if (!opt->get_group().empty()) longs.push_back("--" + n);  // hidden spellings are not suggested
    }
  for (int i = 1; i < argc; ++i) {
    std::string_view w = argv[i];
    if (!w.starts_with("--") || w == "--") continue;
    w = w.substr(0, w.find('='));
    if (std::find(known.begin(), known.end(), w) != known.end()) continue;
    if (const auto near = nearest(w, longs)) return fmt::format("unknown option '{}'; did you mean '{}'?", w, *near);
    std::string path;
    for (const auto* c = &cmd; c != nullptr; c = c->get_parent())
      path = path.empty() ? c->get_name() : c->get_name() + " " + path;
    return fmt::format("unknown option '{}' ({} --help lists the options)", w, path);
  }
  return std::nullopt;
}

}  // namespace edsc::driver
