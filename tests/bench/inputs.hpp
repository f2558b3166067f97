#pragma once
// The inputs the benchmark measures: the shared corpus, its largest file and
// the synthetic files scripts/gen-synthetic-eds writes into the build folder.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "model/device.hpp"
#include "parse/parser.hpp"
#include "source/source_file.hpp"

namespace edsc::bench {

struct input_set {
  std::string name;                // "corpus", "largest", "synthetic_10MB"...
  std::vector<std::string> paths;  // files, in a fixed order
  std::uint64_t bytes = 0;         // their total size
};

// Finds the input sets present on this machine; missing folders or files are
// skipped (the 100 MB file only exists after `ninja edsc_bench_data_100mb`).
[[nodiscard]] std::vector<input_set> find_inputs(const std::string& corpus_dir, const std::string& data_dir);

// One file taken through the front end once, so each stage can be timed on
// exactly the input it sees in the real pipeline. Heap-held: the tree and the
// model point at the source and the tree.
struct prepared_file {
  std::unique_ptr<source_file> src;
  parse_result parsed;
  model::device dev;
  diagnostics lower_diags;
};

// The prepared files of one input set, built on first use and kept until a
// benchmark of another set asks (so only one large set is in memory at once).
[[nodiscard]] const std::vector<std::unique_ptr<prepared_file>>& prepared(const input_set& set);

}  // namespace edsc::bench
