#include "announced_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "announced_open.hpp"
#include "corpus_dirs.hpp"
#include "netns/live_support.hpp"
#include "netns/run_edsc.hpp"
#include "test_paths.hpp"

namespace edsc::scanner_test {

namespace {

using live_test::quoted;
using live_test::shell;

bool ends_with(const bytes& whole, const bytes& tail) {
  return whole.size() >= tail.size() && std::equal(tail.begin(), tail.end(), whole.end() - tail.size());
}

// Why `c` cannot be opened before anything is sent, or "".
std::string before_opening(const announced_connection& c, const std::vector<announced_connection>& all) {
  // The pieces a scanner is told to send must be the path of the request edsc announces.
  if (!ends_with(c.request, scanner_path(c)))
    return "the key, path and configuration data do not make the announced request's connection path";
  if (c.kind == "listen only" && owner_of(c, all) == nullptr)
    return "a listen-only connection the JSON names no owner of";
  return {};
}

// A line `ConnectionN =` (any spaces around): cheaper than a regex, as
// every process of this folder's tests lists the corpus files at start.
bool names_a_connection(const std::string& line) {
  auto at = line.find_first_not_of(" \t");
  if (at == std::string::npos || line.compare(at, 10, "Connection") != 0) return false;
  at += 10;
  const auto digits = at;
  while (at < line.size() && std::isdigit(static_cast<unsigned char>(line[at]))) ++at;
  if (at == digits) return false;
  at = line.find_first_not_of(" \t", at);
  return at != std::string::npos && line[at] == '=';
}

}  // namespace

const announced_connection* owner_of(const announced_connection& c, const std::vector<announced_connection>& all) {
  for (const auto n : c.owners)
    for (const auto& o : all)
      if (o.number == n && o.expressible) return &o;
  return nullptr;
}

std::vector<std::filesystem::path> files_with_connections() {
  std::vector<std::filesystem::path> out;
  for (const auto& f : corpora::sample()) {
    std::ifstream in(f);
    for (std::string line; std::getline(in, line);)
      if (names_a_connection(line)) {
        out.push_back(f);
        break;
      }
  }
  return out;
}

std::vector<announced_connection> announce(const std::string& file, std::string& error) {
  const auto cmd = quoted(EDSC_BINARY) + " connection " + quoted(file) + " --format json";
  const auto r = shell(cmd + " 2>/dev/null");
  if (r.status != 0) {
    error = "`edsc connection --format json` exits " + std::to_string(r.status) + ": " + shell(cmd + " 2>&1").out;
    return {};
  }
  return read_announced(r.out, error);
}

reviewed not_opened(const std::string& name) {
  reviewed out;
  std::ifstream in(std::string(EDSC_TESTS_DIR) + "/eipscanner/" + name);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(": ");
    if (colon != std::string::npos) out[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return out;
}

file_outcome open_every_connection(const std::string& file, const std::vector<announced_connection>& all,
                                   const std::string& ip, const std::string& sim_log, const reviewed& listed) {
  file_outcome out;
  const auto name = std::filesystem::path(file).filename().string();
  for (const auto& c : all) {
    if (!c.expressible || std::find(c.classes.begin(), c.classes.end(), 1u) == c.classes.end()) continue;
    const auto key = name + ":" + std::to_string(c.number);
    auto failure = before_opening(c, all);
    if (failure.empty())
      failure = open_announced(ip, c, c.kind == "listen only" ? owner_of(c, all) : nullptr, sim_log).failure;
    const auto reason = listed.find(key);
    if (reason != listed.end()) {
      if (failure.empty())
        out.failures.push_back(key + " is listed as not opened (" + reason->second +
                               ") but opens: remove it from the list");
      else
        ++out.listed;
    } else if (!failure.empty()) {
      out.failures.push_back(key + ": " + failure);
    } else {
      ++out.opened;
    }
  }
  return out;
}

}  // namespace edsc::scanner_test
