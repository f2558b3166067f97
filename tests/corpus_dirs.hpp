#pragma once
// The real EDS files the tests walk: the general corpus and the Rockwell one
// (modular, proxy and POINT I/O files, EDS_FORMAT.md §3.18). Every test that
// walks a corpus walks both.
#include <algorithm>
#include <filesystem>
#include <vector>

namespace edsc::corpora {

inline constexpr const char* dirs[] = {EDSC_CORPUS_DIR, EDSC_CORPUS_ROCKWELL_DIR};
inline constexpr std::size_t file_count = 117 + 60;

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

}  // namespace edsc::corpora
