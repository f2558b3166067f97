// Every class 1 connection of every EtherNet/IP file of both corpora,
// opened by EIPScanner from `edsc connection FILE --format json` alone on
// `edsc sim` of the same file (announced_file.hpp). Files run on several
// test networks at once, each worker thread in its own scanner namespace
// (EIPScanner binds UDP 2222 on every address of its host), the simulator
// restarted per file. Label `eipscanner` (tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "announced_file.hpp"
#include "corpus_dirs.hpp"
#include "scanner_support.hpp"

namespace edsc::scanner_test {
namespace {

namespace fs = std::filesystem;

bool has_syntax_errors(const fs::path& f) {
  return std::find(std::begin(corpora::broken), std::end(corpora::broken), f.filename().string()) !=
         std::end(corpora::broken);
}

// One file on `net`: announced, served, every connection opened.
file_outcome run_file(live_test::test_network& net, const fs::path& f, const reviewed& listed) {
  file_outcome out;
  std::string error;
  const auto all = announce(f.string(), error);
  if (!error.empty()) {
    // A file with syntax errors is not read for settings (docs/connection.md), nor served.
    if (!has_syntax_errors(f)) out.failures.push_back(f.filename().string() + ": " + error);
    return out;
  }
  const auto pid = net.start_device(
      {EDSC_BINARY, "sim", f.string(), "--address", net.device_ip, "--serial", "123456789"}, "sim", error);
  if (pid <= 0) {
    out.failures.push_back(f.filename().string() + ": " + error);
    return out;
  }
  {
    live_test::thread_in_namespace inside(net.scanner_ns);
    out = open_every_connection(f.string(), all, net.device_ip, net.dir + "/sim.log", listed);
  }
  net.stop(pid, SIGTERM);
  return out;
}

// The entries of `listed` whose file is one of `files` (under the
// sanitizers, a sample of the corpora).
std::size_t listed_in(const reviewed& listed, const std::vector<fs::path>& files) {
  std::size_t n = 0;
  for (const auto& [key, why] : listed)
    n += std::any_of(files.begin(), files.end(),
                     [&](const fs::path& f) { return key.starts_with(f.filename().string() + ":"); });
  return n;
}

// EIPScanner waits on RPIs most of the time: a few networks at once.
constexpr std::size_t workers = 4;

TEST(eipscanner_announced_corpus, every_class_1_connection_of_both_corpora_opens_from_the_json) {
  const auto start = std::chrono::steady_clock::now();
  std::string why;
  std::vector<std::unique_ptr<live_test::test_network>> nets;
  for (std::size_t i = 0; i < workers; ++i)
    if (auto net = live_test::test_network::make(why, scanner_net())) nets.push_back(std::move(net));
  if (nets.empty()) GTEST_SKIP() << why;
  eipScanner::utils::Logger::setLogLevel(eipScanner::utils::LogLevel::ERROR);
  const auto listed = not_opened();
  const auto files = files_with_connections();
  std::vector<file_outcome> results(files.size());
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> threads;
  for (auto& net : nets)
    threads.emplace_back([&, n = net.get()] {
      for (auto i = next++; i < files.size(); i = next++) results[i] = run_file(*n, files[i], listed);
    });
  for (auto& t : threads) t.join();
  unsigned opened = 0;
  std::size_t still_listed = 0;
  for (const auto& r : results) {
    for (const auto& f : r.failures) ADD_FAILURE() << f;
    opened += r.opened;
    still_listed += r.listed;
  }
  EXPECT_EQ(still_listed, listed_in(listed, files)) << "a connection of announced_not_opened.txt was not tried";
  const auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%zu files, %u connections opened from the JSON, %zu listed as not opened, %.1f s on %zu networks\n",
              files.size(), opened, still_listed, seconds, nets.size());
}

}  // namespace
}  // namespace edsc::scanner_test
