#pragma once
// The real EDS files the tests walk: the general corpus and the Rockwell one
// (modular, proxy and POINT I/O files, EDS_FORMAT.md §3.18). Every test that
// walks a corpus walks both.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>
#include "test_paths.hpp"

// Every N-th file of each corpus is what a corpus-wide test walks (see
// sample() below). The build sets it: 1 (every file) normally, more under the
// sanitizers (CMake's EDSC_CORPUS_SAMPLE, docs/testing.md).
#ifndef EDSC_CORPUS_SAMPLE
#define EDSC_CORPUS_SAMPLE 1
#endif

namespace edsc::corpora {

inline const char* const dirs[] = {EDSC_CORPUS_DIR, EDSC_CORPUS_ROCKWELL_DIR};
inline constexpr std::size_t counts[] = {117, 60};  // files per folder of dirs
inline constexpr std::size_t file_count = counts[0] + counts[1];
// The two files of the general corpus with syntax errors.
inline constexpr const char* broken[] = {"kh-ko__NVM__eds_sample.txt.eds",
                                         "rossmann-engineering__EEIP.NET__fanucrobot0202.eds"};

// Every `.eds` file of both corpora, sorted per folder.
inline std::vector<std::filesystem::path> all_files() {
  std::vector<std::filesystem::path> out;
  for (const char* dir : dirs) {
    std::vector<std::filesystem::path> here;
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.is_regular_file() && e.path().extension() == ".eds") here.push_back(e.path());
    std::sort(here.begin(), here.end());
    out.insert(out.end(), here.begin(), here.end());
  }
  return out;
}

// The stride of the sample: the environment's EDSC_CORPUS_SAMPLE when set to
// a positive number, else the build's. 1 means every file.
inline std::size_t sample_stride() {
  if (const char* env = std::getenv("EDSC_CORPUS_SAMPLE")) {
    try {
      const long n = std::stol(env);
      if (n > 0) return static_cast<std::size_t>(n);
    } catch (...) {}
  }
  return EDSC_CORPUS_SAMPLE > 0 ? EDSC_CORPUS_SAMPLE : 1;
}

// The files a corpus-wide test runs its engine over: every file of both
// corpora in the Release build, a fixed deterministic sample under ASan (the
// first file of each corpus and every N-th after it, in sorted order, plus
// the two files with syntax errors, whose paths the tests name), so the
// sanitizers still see every engine on real files and no verdict depends on
// how slow the instrumented build is. Tests that count files compare against
// sample_size(), never against file_count.
inline std::vector<std::filesystem::path> sample() {
  const std::size_t stride = sample_stride();
  std::vector<std::filesystem::path> out;
  std::size_t i = 0;
  std::filesystem::path folder;
  for (const auto& f : all_files()) {
    if (f.parent_path() != folder) {
      folder = f.parent_path();
      i = 0;
    }
    const auto name = f.filename().string();
    if (i++ % stride == 0 || std::find(std::begin(broken), std::end(broken), name) != std::end(broken))
      out.push_back(f);
  }
  return out;
}

// The part of sample() that lies in `dir` (one of dirs).
inline std::vector<std::filesystem::path> sample_of(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  for (auto& f : sample())
    if (f.parent_path() == dir) out.push_back(std::move(f));
  return out;
}

// At least this many files are in sample() when both corpora are complete.
inline std::size_t sample_size() {
  const std::size_t stride = sample_stride();
  std::size_t n = 0;
  for (const std::size_t c : counts) n += (c + stride - 1) / stride;
  return n;
}

}  // namespace edsc::corpora
