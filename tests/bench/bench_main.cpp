// edsc_bench: throughput of each pipeline stage on the corpus, its largest
// file and synthetic files of 1, 10 and 100 MB (docs/performance.md).
//
//   edsc_bench [--corpus=DIR] [--data=DIR] [Google Benchmark flags]
//
// Every benchmark reports MB/s (10^6 bytes of EDS input per second) and
// files/s, computed on CPU time so that other work on the machine inflates
// the figures less than wall time would.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <malloc.h>  // malloc_trim (glibc)

#include <benchmark/benchmark.h>

#include "check/check_file.hpp"
#include "check/context.hpp"
#include "cst/cst.hpp"
#include "diff/diff.hpp"
#include "emit/header.hpp"
#include "emit/opener_plan.hpp"
#include "inputs.hpp"
#include "io/read_file.hpp"
#include "lower/lower.hpp"

namespace edsc::bench {

namespace {

using files_t = std::vector<std::unique_ptr<prepared_file>>;

void sort_by_offset(diagnostics& ds) {
  std::stable_sort(ds.begin(), ds.end(),
                   [](const diagnostic& a, const diagnostic& b) { return a.where.begin < b.where.begin; });
}

// The check stage exactly as check_file runs it after lowering: the rules,
// then the sort of all findings by position.
void check_stage(const prepared_file& f, diagnostics& out) {
  out = f.parsed.diags;
  run_checks(check_context{f.parsed.tree, f.dev, f.dev.classes.networks, out});
  sort_by_offset(out);
}

// One benchmark = one stage over every file of one input set per iteration.
struct stage {
  const char* name;
  void (*run)(const input_set& set, const files_t& files);
};

const stage stages[] = {
    {"read",
     [](const input_set& set, const files_t&) {
       for (const auto& p : set.paths) benchmark::DoNotOptimize(io::read_source(p));
     }},
    {"parse",
     [](const input_set&, const files_t& files) {
       for (const auto& f : files) benchmark::DoNotOptimize(parse(*f->src));
     }},
    {"lower",
     [](const input_set&, const files_t& files) {
       for (const auto& f : files) {
         diagnostics d;
         benchmark::DoNotOptimize(lower(f->parsed.tree, d));
       }
     }},
    {"check",
     [](const input_set&, const files_t& files) {
       diagnostics out;
       for (const auto& f : files) {
         check_stage(*f, out);
         benchmark::DoNotOptimize(out.data());
       }
     }},
    // The target figure: everything after the bytes are in memory.
    {"parse_lower_check",
     [](const input_set&, const files_t& files) {
       for (const auto& f : files) {
         auto parsed = parse(*f->src);
         auto dev = lower(parsed.tree, parsed.diags);
         run_checks(check_context{parsed.tree, dev, dev.classes.networks, parsed.diags});
         sort_by_offset(parsed.diags);
         benchmark::DoNotOptimize(parsed.diags.data());
       }
     }},
    // What `edsc check` does per file, reading included.
    {"check_file",
     [](const input_set& set, const files_t&) {
       const check_options options;
       for (const auto& p : set.paths) benchmark::DoNotOptimize(check_file(p, options));
     }},
    {"emit_eds",
     [](const input_set&, const files_t& files) {
       for (const auto& f : files) benchmark::DoNotOptimize(cst::print(f->parsed.tree));
     }},
    // `edsc diff` of a file against itself: every entity matched and
    // compared, the worst case for a diff that finds nothing.
    {"diff_self",
     [](const input_set&, const files_t& files) {
       for (const auto& f : files) benchmark::DoNotOptimize(diff::compare(f->dev, f->dev).differences.size());
     }},
    {"emit_header",
     [](const input_set&, const files_t& files) {
       emit::header_options opt;
       for (const auto& f : files) benchmark::DoNotOptimize(emit::generate_header(f->dev, *f->src, opt));
     }},
    // `edsc header --stack opener` past the front end: the plan (with what
    // OpENer cannot serve) and the project's five files.
    {"emit_opener_stack",
     [](const input_set&, const files_t& files) {
       for (const auto& f : files) {
         diagnostics diags;
         std::vector<emit::header_issue> issues;
         benchmark::DoNotOptimize(emit::render_opener(emit::plan_opener(f->dev, *f->src, diags, issues)));
       }
     }},
};

// --memory=cold: before each iteration the allocator hands its free memory
// back to the kernel (untimed), so every iteration pays for fresh pages as
// one `edsc check` process does. With warm memory (the default) inputs whose
// arrays fit under glibc's 32 MB mmap threshold reuse pages across
// iterations while larger ones cannot, which flatters small inputs.
bool cold_memory = false;

void register_all(const std::vector<input_set>& sets) {
  for (const auto& set : sets) {
    for (const auto& st : stages) {
      auto* b = benchmark::RegisterBenchmark(
          (std::string(st.name) + "/" + set.name).c_str(), [set, run = st.run](benchmark::State& state) {
            const auto& files = prepared(set);
            for (auto _ : state) {
              if (cold_memory) {
                state.PauseTiming();
                malloc_trim(0);
                state.ResumeTiming();
              }
              run(set, files);
            }
            state.counters["MB/s"] =
                benchmark::Counter(static_cast<double>(set.bytes) / 1e6, benchmark::Counter::kIsIterationInvariantRate);
            state.counters["files/s"] = benchmark::Counter(static_cast<double>(set.paths.size()),
                                                           benchmark::Counter::kIsIterationInvariantRate);
          });
      b->Unit(benchmark::kMillisecond);
      // With --benchmark_repetitions=N, also the best run (the one least
      // disturbed by other processes on a shared machine): read the time
      // from the _min row and the rates from the _max row.
      b->ComputeStatistics("min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
      b->ComputeStatistics("max", [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); });
    }
  }
}

// Takes --name=VALUE out of argv, leaving the rest to Google Benchmark.
std::string take_flag(int& argc, char** argv, const char* name, std::string fallback) {
  const std::string prefix = std::string("--") + name + "=";
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], prefix.c_str(), prefix.size()) == 0) {
      fallback = argv[i] + prefix.size();
      std::copy(argv + i + 1, argv + argc, argv + i);
      --argc;
      --i;
    }
  }
  return fallback;
}

}  // namespace

}  // namespace edsc::bench

int main(int argc, char** argv) {
  using namespace edsc::bench;
  const auto corpus = take_flag(argc, argv, "corpus", EDSC_BENCH_CORPUS_DIR);
  const auto data = take_flag(argc, argv, "data", EDSC_BENCH_DATA_DIR);
  const auto memory = take_flag(argc, argv, "memory", "warm");
  if (memory != "warm" && memory != "cold") {
    std::fprintf(stderr, "edsc_bench: --memory is warm or cold, not '%s'\n", memory.c_str());
    return 1;
  }
  cold_memory = memory == "cold";
  register_all(find_inputs(corpus, data));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
