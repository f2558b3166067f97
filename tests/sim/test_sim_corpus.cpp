// Every EtherNet/IP file of both corpora with connections, served by `edsc
// sim` in a test namespace and checked by `edsc verify --live --connections`:
// each passes, except the reviewed list in corpus_not_served.txt (which must
// stay true both ways). Several namespaces and the simulator restarted per
// file keep the run time bounded.
#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <thread>

#include "corpus_dirs.hpp"
#include "sim_network.hpp"
#include "test_paths.hpp"
#include "time_scale.hpp"

namespace edsc::sim_test {
namespace {

namespace fs = std::filesystem;

std::map<std::string, std::string> not_served() {
  std::map<std::string, std::string> out;
  std::ifstream in(std::string(EDSC_TESTS_DIR) + "/sim/corpus_not_served.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(".eds:");
    if (colon != std::string::npos) out[line.substr(0, colon + 4)] = line.substr(colon + 5);
  }
  return out;
}

// Files with at least one ConnectionN (EtherNet/IP I/O), in name order.
std::vector<fs::path> files_with_connections(const std::string& dir) {
  std::vector<fs::path> out;
  const std::regex connection(R"(^\s*Connection[0-9]+\s*=)", std::regex::multiline);
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".eds") continue;
    std::ifstream in(e.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (std::regex_search(text, connection)) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  // Every file in Release; under ASan every N-th, as the other corpus-wide
  // tests do (tests/corpus_dirs.hpp), so the sweep's time stays bounded.
  std::vector<fs::path> sampled;
  for (std::size_t i = 0; i < out.size(); i += edsc::corpora::sample_stride()) sampled.push_back(out[i]);
  return sampled;
}

// One file: served in `net`, verified from the host; the exit status of
// `edsc verify --live --connections` and what it printed.
std::pair<int, std::string> serve_and_verify(test_network& net, const fs::path& f) {
  std::string why;
  const auto pid = start_sim(net, f.string(), why);
  if (pid <= 0) return {-1, why};
  // Each answer gets the command's own 3 s (times the build's scale): the
  // simulator answers every request, so the bound costs nothing but ends a
  // hang, and a busy machine's slow answer is no failure.
  const auto r = run_edsc("verify --live " + net.device_ip + " " + quoted(f.string()) + " --connections --timeout " +
                              std::to_string(3 * edsc::test_time::scale) + " --color never",
                          edsc::test_time::scaled(120));
  net.stop(pid, SIGTERM);
  return {r.status, r.output};
}

// Files run in parallel, each worker with a namespace of its own: verifying
// waits on the network most of the time (300 ms of I/O watched per
// connection, and some files have 95 connections), so the sweep's time stays
// bounded.
constexpr std::size_t workers = 6;

void sweep(const std::string& dir) {
  std::string why;
  std::vector<std::unique_ptr<test_network>> nets;
  for (std::size_t i = 0; i < workers; ++i) {
    auto net = make_sim_network(why);
    if (!net) break;
    nets.push_back(std::move(net));
  }
  if (nets.empty()) GTEST_SKIP() << why;
  const auto reviewed = not_served();
  const auto files = files_with_connections(dir);
  std::vector<std::pair<int, std::string>> results(files.size());
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> threads;
  for (auto& net : nets)
    threads.emplace_back([&, n = net.get()] {
      for (auto i = next++; i < files.size(); i = next++) results[i] = serve_and_verify(*n, files[i]);
    });
  for (auto& t : threads) t.join();
  unsigned served = 0, listed = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const auto name = files[i].filename().string();
    const auto& [status, output] = results[i];
    if (reviewed.count(name) > 0) {
      ++listed;
      EXPECT_NE(status, 0) << name << " is listed in corpus_not_served.txt (" << reviewed.at(name)
                           << ") but now passes: remove it from the list";
    } else {
      EXPECT_EQ(status, 0) << name << " is not served:\n" << output;
      served += status == 0;
    }
  }
  std::printf("%s: %u files served and verified, %u listed as not served (%zu namespaces)\n", dir.c_str(), served,
              listed, nets.size());
}

TEST(sim_corpus, every_connection_file_of_the_corpus_is_served) { sweep(EDSC_CORPUS_DIR); }
TEST(sim_corpus, every_connection_file_of_the_rockwell_corpus_is_served) { sweep(EDSC_CORPUS_ROCKWELL_DIR); }

}  // namespace
}  // namespace edsc::sim_test
