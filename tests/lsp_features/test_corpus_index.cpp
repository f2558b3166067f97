// The reference index reads the tree by the schema; on every corpus file it
// must find each reference the model holds, with the same kind and number.
#include <filesystem>

#include "corpus_dirs.hpp"
#include "lsp/ref_index.hpp"
#include "lsp_support.hpp"
#include "model/visit.hpp"
#include "test_paths.hpp"

namespace edsc::test {
namespace {

namespace fs = std::filesystem;

void check_dir(const std::string& dir) {
  std::size_t files = 0, refs = 0;
  for (const auto& path : corpora::sample_of(dir)) {
    const fs::directory_entry e(path);
    auto a = analyze_path(e.path().string());
    if (!a) continue;
    ++files;
    const lsp::ref_index idx(*a);
    model::for_each_value(a->dev, [&](const model::value& v) {
      const auto* r = v.as_ref();
      if (!r || v.kind != model::value_kind::reference) return;
      ++refs;
      const auto* s = idx.at(v.from.where.begin);
      ASSERT_NE(s, nullptr) << e.path() << " " << a->dev.raw(v);
      EXPECT_EQ(s->kind, r->kind) << e.path() << " " << a->dev.raw(v);
      EXPECT_EQ(s->number, r->number) << e.path() << " " << a->dev.raw(v);
      // site_at reads the one entry and agrees with the index.
      const auto local = lsp::site_at(*a, v.from.where.begin);
      ASSERT_TRUE(local.has_value());
      EXPECT_EQ(local->name, s->name);
    });
  }
  EXPECT_GE(files, 8u);
  // Over a whole corpus more than 100 references; the sanitizer build's
  // sample of the Rockwell files (few references each) holds a handful.
  EXPECT_GT(refs, corpora::sample_stride() == 1 ? 100u : 0u);
}

TEST(LspIndexCorpus, EveryModelReferenceIsASite) { check_dir(EDSC_CORPUS_DIR); }
TEST(LspIndexCorpus, EveryModelReferenceIsASiteRockwell) { check_dir(EDSC_CORPUS_ROCKWELL_DIR); }

}  // namespace
}  // namespace edsc::test
