#pragma once
// Options that take one of a few words: `--help` shows them as the user types
// them (`--color auto|always|never`), not as the parser's internal mapping,
// and a wrong word is a usage error naming the choices.
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "driver/cli_model.hpp"

namespace edsc::driver {

namespace detail {

[[nodiscard]] inline bool same_word(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

}  // namespace detail

// Adds `name` taking one of `choices` (case-insensitive; the last one given
// wins), stored in `value`. The words are listed in the order given.
template <typename T>
CLI::Option* add_choice(CLI::App* cmd, const std::string& name, T& value,
                        std::vector<std::pair<std::string, T>> choices, const std::string& help) {
  std::string words;
  for (const auto& c : choices) words += (words.empty() ? "" : "|") + c.first;
  auto find = [choices](const std::string& word) -> const T* {
    for (const auto& c : choices) {
      if (detail::same_word(c.first, word)) return &c.second;
    }
    return nullptr;
  };
  // Unbound, so CLI11 never converts the word itself: `each` stores it.
  return takes(cmd->add_option(name, help), arg_kind::word)
      ->type_name(words)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
      ->check(CLI::Validator(
          [find, words](std::string& word) {
            return find(word) != nullptr ? std::string() : fmt::format("'{}' is not one of {}", word, words);
          },
          "", "choice"))
      ->each([&value, find](const std::string& word) { value = *find(word); });
}

// The same for a word kept as it is written (lower case).
inline CLI::Option* add_choice(CLI::App* cmd, const std::string& name, std::string& value,
                               const std::vector<std::string>& words, const std::string& help) {
  std::vector<std::pair<std::string, std::string>> choices;
  for (const auto& w : words) choices.emplace_back(w, w);
  return add_choice(cmd, name, value, std::move(choices), help);
}

}  // namespace edsc::driver
