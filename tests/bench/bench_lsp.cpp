// edsc_bench_lsp: what typing costs in the language server. Each iteration
// is one keystroke: a textDocument/didChange (a blank inserted at the start
// of a line in the middle of the file, then removed, alternately) and the
// server's reanalysis up to the textDocument/publishDiagnostics it sends,
// JSON included. Measured in memory (no pipe), on the largest file of each
// corpus and on the 1 MB synthetic file; p50/p95/max of the iterations are
// reported as counters, in wall time and in this thread's CPU time (target:
// p95 <= 10 ms on the largest real file).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "io/read_file.hpp"
#include "lsp/server.hpp"

namespace {

namespace fs = std::filesystem;
using edsc::lsp::json;

std::string largest_in(const std::string& dir) {
  std::string best;
  std::uintmax_t best_size = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (!e.is_regular_file() || e.path().extension() != ".eds") continue;
    if (e.file_size() > best_size) best_size = e.file_size(), best = e.path().string();
  }
  return best;
}

std::string message(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

void typing(benchmark::State& state, const std::string& path) {
  auto r = edsc::io::read_source(path);
  auto* src = (r ? &r.value() : nullptr);
  if (path.empty() || !src) {
    state.SkipWithError(("no input " + path).c_str());
    return;
  }
  // The editor holds UTF-8: what the file's bytes become once sent as JSON.
  const auto text = json::parse(message(json(std::string((*src)->text()))), nullptr, false).get<std::string>();
  std::size_t published = 0;
  edsc::lsp::server srv({}, [&](const std::string& body) {
    published += body.find("textDocument/publishDiagnostics") != std::string::npos ? 1 : 0;
  });
  const std::string uri = "file:///bench.eds";
  srv.handle(message(
      {{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}, {"params", {{"capabilities", json::object()}}}}));
  srv.handle(message({{"jsonrpc", "2.0"}, {"method", "initialized"}, {"params", json::object()}}));
  srv.handle(
      message({{"jsonrpc", "2.0"},
               {"method", "textDocument/didOpen"},
               {"params", {{"textDocument", {{"uri", uri}, {"languageId", "eds"}, {"version", 1}, {"text", text}}}}}}));
  srv.idle();
  const auto line = std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(text.size() / 2), '\n');
  auto change = [&](int version) {
    const bool insert = version % 2 == 0;
    json c{{"range",
            {{"start", {{"line", line}, {"character", 0}}}, {"end", {{"line", line}, {"character", insert ? 0 : 1}}}}},
           {"text", insert ? " " : ""}};
    return message(
        {{"jsonrpc", "2.0"},
         {"method", "textDocument/didChange"},
         {"params", {{"textDocument", {{"uri", uri}, {"version", version}}}, {"contentChanges", json::array({c})}}}});
  };
  // Wall time is what the user waits; CPU time of this thread is the same
  // work without the other processes of a shared machine.
  auto cpu_now = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) / 1e6;
  };
  std::vector<double> ms, cpu_ms;
  int version = 1;
  for (auto _ : state) {
    state.PauseTiming();
    const auto body = change(++version);
    const auto before = published;
    state.ResumeTiming();
    const auto t0 = std::chrono::steady_clock::now();
    const auto c0 = cpu_now();
    srv.handle(body);
    srv.idle();
    cpu_ms.push_back(cpu_now() - c0);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (published != before + 1) state.SkipWithError("no publishDiagnostics after didChange");
  }
  auto pct = [](std::vector<double>& v, double p) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())))];
  };
  state.counters["p50_ms"] = pct(ms, 0.50);
  state.counters["p95_ms"] = pct(ms, 0.95);
  state.counters["max_ms"] = pct(ms, 1.0);
  state.counters["cpu_p50_ms"] = pct(cpu_ms, 0.50);
  state.counters["cpu_p95_ms"] = pct(cpu_ms, 0.95);
  state.counters["bytes"] = static_cast<double>(text.size());
}

}  // namespace

int main(int argc, char** argv) {
  const std::pair<const char*, std::string> inputs[] = {
      {"largest_corpus", largest_in(EDSC_BENCH_CORPUS_DIR)},
      {"largest_rockwell", largest_in(EDSC_BENCH_ROCKWELL_DIR)},
      {"synthetic_1MB", std::string(EDSC_BENCH_DATA_DIR) + "/synthetic_1MB.eds"},
  };
  for (const auto& [name, path] : inputs) {
    benchmark::RegisterBenchmark((std::string("didChange_to_publishDiagnostics/") + name).c_str(),
                                 [path = path](benchmark::State& s) { typing(s, path); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(200);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
