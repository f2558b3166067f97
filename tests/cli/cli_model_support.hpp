#pragma once
// The command line model of the built edsc (`edsc _model`, driver/cli_model.hpp):
// the tests that must reach every command, every writer and every number walk
// it, so a command or option added later is covered without editing them.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_support.hpp"

namespace edsc::cli_test {

struct model_option {
  std::string command;  // "net map"
  nlohmann::json json;  // one entry of "options"

  [[nodiscard]] std::string kind() const { return json.at("kind").get<std::string>(); }
  [[nodiscard]] bool positional() const { return json.at("positional").get<bool>(); }
  [[nodiscard]] bool takes_value() const { return json.at("takes_value").get<bool>(); }
  // What a user types: the long name, else the short one; a positional's name.
  [[nodiscard]] std::string spelling() const {
    if (!json.at("longs").empty()) return json.at("longs").back().get<std::string>();
    if (!json.at("shorts").empty()) return json.at("shorts").front().get<std::string>();
    return json.at("name").get<std::string>();
  }
  [[nodiscard]] std::string where() const { return "edsc " + command + " " + spelling(); }
};

inline nlohmann::json cli_model() {
  const auto r = run_edsc({"_model"});
  EXPECT_EQ(r.status, 0) << r.output;
  return nlohmann::json::parse(r.output, nullptr, false);
}

// Every command that runs (the leaves: "check", "net map"), as its model.
inline void each_command(const nlohmann::json& c, const std::function<void(const nlohmann::json&)>& f) {
  if (c.at("subcommands").empty()) f(c);
  for (const auto& s : c.at("subcommands")) each_command(s, f);
}

inline std::vector<model_option> all_options(const nlohmann::json& top) {
  std::vector<model_option> out;
  each_command(top, [&](const nlohmann::json& c) {
    for (const auto& o : c.at("options")) out.push_back({c.at("path").get<std::string>(), o});
  });
  return out;
}

// "net map" as the words of a command line.
inline std::vector<std::string> words_of(const std::string& path) {
  std::vector<std::string> out;
  std::istringstream in(path);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace edsc::cli_test
