#include "inputs.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "io/read_file.hpp"
#include "lower/lower.hpp"

namespace edsc::bench {

namespace fs = std::filesystem;

namespace {

std::uint64_t total_size(const std::vector<std::string>& paths) {
  std::uint64_t n = 0;
  for (const auto& p : paths) n += fs::file_size(p);
  return n;
}

}  // namespace

std::vector<input_set> find_inputs(const std::string& corpus_dir, const std::string& data_dir) {
  std::vector<input_set> sets;
  std::error_code ec;
  if (fs::is_directory(corpus_dir, ec)) {
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(corpus_dir)) {
      auto ext = e.path().extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
      if (e.is_regular_file() && ext == ".eds") files.push_back(e.path().string());
    }
    std::sort(files.begin(), files.end());
    if (!files.empty()) {
      const auto largest = *std::max_element(
          files.begin(), files.end(), [](const auto& a, const auto& b) { return fs::file_size(a) < fs::file_size(b); });
      sets.push_back({"corpus", files, total_size(files)});
      sets.push_back({"largest", {largest}, total_size({largest})});
    }
  } else {
    std::fprintf(stderr, "edsc_bench: no corpus at %s (--corpus=DIR)\n", corpus_dir.c_str());
  }
  for (const char* size : {"1MB", "10MB", "100MB"}) {
    const auto path = fs::path(data_dir) / (std::string("synthetic_") + size + ".eds");
    if (fs::is_regular_file(path, ec)) {
      sets.push_back({std::string("synthetic_") + size, {path.string()}, total_size({path.string()})});
    }
  }
  return sets;
}

const std::vector<std::unique_ptr<prepared_file>>& prepared(const input_set& set) {
  static std::string current;
  static std::vector<std::unique_ptr<prepared_file>> files;
  if (current == set.name) return files;
  files.clear();
  current = set.name;
  for (const auto& path : set.paths) {
    auto read = io::read_source(path);
    if (!read) {
      std::fprintf(stderr, "edsc_bench: %s\n", read.error().message.c_str());
      std::exit(2);
    }
    auto f = std::make_unique<prepared_file>();
    f->src = std::move(read.value());
    f->parsed = parse(*f->src);
    f->dev = lower(f->parsed.tree, f->lower_diags);
    files.push_back(std::move(f));
  }
  return files;
}

}  // namespace edsc::bench
