#pragma once
// Network files written into a scratch folder beside copies of the project's
// EDS files, checked through the library (exact diagnostics) or the binary.
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"
#include "network/layout.hpp"
#include "network/plan.hpp"
#include "test_paths.hpp"

namespace edsc::net_test {

using namespace edsc::cli_test;

inline const fs::path project_eds = fs::path(EDSC_PROJECT_DIR) / "eds";
inline const fs::path thesis = project_eds / "networks" / "thesis.toml";

inline network::checked_network check_text(const fs::path& path, const std::string& text) {
  return network::check_network(std::make_unique<source_file>(path.string(), text), {});
}

inline std::vector<std::string> ids(const diagnostics& ds) {
  std::vector<std::string> out;
  for (const auto& d : ds) out.emplace_back(rule_of(d.id).name);
  return out;
}

// "line:col" of a diagnostic in its file.
inline std::string at(const source_file& src, const diagnostic& d) {
  const auto p = src.position(d.where.begin);
  return std::to_string(p.line) + ":" + std::to_string(p.column);
}

// "mac:offset+size" per block of an Automap image, in image order.
inline std::vector<std::string> blocks(const network::plan& p, const network::image_layout& im) {
  std::vector<std::string> out;
  for (const auto& b : im.blocks)
    out.push_back(std::to_string(p.nodes[b.node].mac) + ":" + std::to_string(b.offset) + "+" + std::to_string(b.size));
  return out;
}

// A network file header with the project's scanner; nodes are appended.
inline std::string header(const std::string& extra_scanner = "") {
  return "[network]\nkind = \"devicenet\"\nname = \"t\"\nbaud = 125\n\n[scanner]\nprofile = \"1769-SDN\"\nmac = 0\n"
         "slot = 5\n" +
         extra_scanner + "\n";
}

// Scratch folder holding the network files of a test; EDS paths point into the project.
class Net : public Cli {
 protected:
  network::checked_network check(const std::string& text) { return check_text(dir_ / "net.toml", text); }
  static std::string eds(const char* name) { return (project_eds / name).string(); }
  static std::string node(unsigned mac, const std::string& name, const std::string& body) {
    return "[[node]]\nmac = " + std::to_string(mac) + "\nname = \"" + name + "\"\n" + body + "\n";
  }
};

}  // namespace edsc::net_test
