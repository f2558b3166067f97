// Every corpus file against its own `edsc fmt` output: layout only, so the
// diff must find nothing. Both corpora, the vendor dialects included.
#include "diff_support.hpp"
#include "edit/format.hpp"

using namespace diff_test;

namespace {

std::vector<fs::path> eds_files(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir)) {
    auto ext = e.path().extension().string();
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == ".eds") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Diffs each file against its formatted text; returns how many were compared.
std::size_t against_fmt(const fs::path& dir) {
  std::size_t compared = 0;
  for (const auto& p : eds_files(dir)) {
    const auto text = read_bytes(p);
    const auto a = edsc::edit::analyze(p.string(), text);
    if (a->has_syntax_errors()) continue;  // diff refuses those (exit 2), as fmt does
    std::string why;
    const auto formatted = edsc::edit::format(a->tree, {}, why);
    if (!formatted) continue;
    const auto b = edsc::edit::analyze(p.string(), *formatted);
    const auto r = edsc::diff::compare(*a, *b);
    EXPECT_TRUE(r.differences.empty()) << p.filename() << ":\n" << edsc::diff::render_text(r, *a, *b, {});
    // And the file against itself.
    EXPECT_TRUE(edsc::diff::compare(*a, *a).differences.empty()) << p.filename();
    ++compared;
  }
  return compared;
}

}  // namespace

TEST(DiffCorpus, EveryFileEqualsItsFormattedSelf) {
  const auto n = against_fmt(EDSC_CORPUS_DIR);
  EXPECT_GT(n, 100u) << "too few corpus files compared";
}

TEST(DiffCorpus, EveryRockwellFileEqualsItsFormattedSelf) {
  const auto dir = fs::path(EDSC_CORPUS_DIR).parent_path() / "eds-corpus-rockwell";
  if (!fs::is_directory(dir)) GTEST_SKIP() << dir << " is absent";
  const auto n = against_fmt(dir);
  EXPECT_GT(n, 50u) << "too few Rockwell corpus files compared";
}
