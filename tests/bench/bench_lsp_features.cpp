// Latency of the language features (hover, definition, references, symbols,
// completion, rename) on the largest file of the corpora: each answers one
// keystroke or click, so each should take well under a millisecond.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>

#include "check/check_file.hpp"
#include "io/read_file.hpp"
#include "lsp/features.hpp"

namespace {

namespace fs = std::filesystem;

std::string largest_file() {
  std::string best;
  std::uintmax_t best_size = 0;
  for (const char* dir : {EDSC_BENCH_CORPUS_DIR, EDSC_BENCH_ROCKWELL_DIR}) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
      if (!e.is_regular_file() || e.path().extension() != ".eds") continue;
      if (e.file_size() > best_size) best_size = e.file_size(), best = e.path().string();
    }
  }
  return best;
}

struct fixture {
  std::unique_ptr<edsc::analysis> a;
  std::uint32_t param_ref = 0;   // a `ParamN` reference in a field, or a keyword
  std::uint32_t param_decl = 0;  // the keyword of a ParamN
  std::uint32_t field = 0;       // inside the descriptor of that parameter
  std::uint32_t blank_line = 0;  // start of an empty line in [Params]
};

const fixture& file() {
  static const fixture f = [] {
    fixture x;
    auto r = edsc::io::read_source(largest_file());
    auto* src = (r ? &r.value() : nullptr);
    if (!src) return x;
    x.a = edsc::analyze(std::move(*src), edsc::check_options{});
    const auto text = x.a->text();
    // The middle parameter of the file, so nothing is found by luck early.
    const auto mid = text.find("Param", text.find("[Params]") + text.size() / 3);
    x.param_decl = static_cast<std::uint32_t>(mid);
    x.field = static_cast<std::uint32_t>(text.find("0x", mid) + 1);
    const auto ref =
        text.find("Param", text.find("[Assembly]") == std::string_view::npos ? mid + 1 : text.find("[Assembly]"));
    x.param_ref = static_cast<std::uint32_t>(ref == std::string_view::npos ? mid : ref);
    x.blank_line = static_cast<std::uint32_t>(text.find(";\n", mid) + 2);  // between two entries
    return x;
  }();
  return f;
}

// How much an answer holds, so a benchmark that found nothing shows it.
template <class T>
std::size_t count(const std::vector<T>& v) {
  return v.size();
}
template <class T>
std::size_t count(const std::optional<T>& v) {
  return v ? 1 : 0;
}
std::size_t count(const edsc::lsp::rename_result& r) { return r.edits.size(); }

template <class F>
void run(benchmark::State& state, F f) {
  const auto& x = file();
  if (!x.a) {
    state.SkipWithError("no corpus file");
    return;
  }
  state.SetLabel(x.a->source->path().substr(x.a->source->path().rfind('/') + 1));
  for (auto _ : state) benchmark::DoNotOptimize(f(*x.a, x));
  state.counters["answers"] = static_cast<double>(count(f(*x.a, x)));
}

void hover_field(benchmark::State& s) {
  run(s, [](auto& a, auto& x) { return edsc::lsp::hover(a, x.field); });
}
void hover_reference(benchmark::State& s) {
  run(s, [](auto& a, auto& x) { return edsc::lsp::hover(a, x.param_ref); });
}
void definition(benchmark::State& s) {
  run(s, [](auto& a, auto& x) { return edsc::lsp::definition(a, x.param_ref); });
}
void references(benchmark::State& s) {
  run(s, [](auto& a, auto& x) { return edsc::lsp::references(a, x.param_decl, true); });
}
void symbols(benchmark::State& s) {
  run(s, [](auto& a, auto&) { return edsc::lsp::document_symbols(a); });
}
void complete_keyword(benchmark::State& s) {
  run(s, [](auto& a, auto& x) { return edsc::lsp::complete(a, x.blank_line); });
}
void prepare_rename(benchmark::State& s) {
  run(s, [](auto& a, auto& x) { return edsc::lsp::prepare_rename(a, x.param_decl); });
}
void rename(benchmark::State& s) {
  run(s, [](auto& a, auto& x) { return edsc::lsp::rename(a, x.param_decl, "Param60000"); });
}

BENCHMARK(hover_field)->Unit(benchmark::kMicrosecond);
BENCHMARK(hover_reference)->Unit(benchmark::kMicrosecond);
BENCHMARK(definition)->Unit(benchmark::kMicrosecond);
BENCHMARK(references)->Unit(benchmark::kMicrosecond);
BENCHMARK(symbols)->Unit(benchmark::kMicrosecond);
BENCHMARK(complete_keyword)->Unit(benchmark::kMicrosecond);
BENCHMARK(prepare_rename)->Unit(benchmark::kMicrosecond);
BENCHMARK(rename)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
