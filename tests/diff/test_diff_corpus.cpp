// Every corpus file against its own `edsc fmt` output: layout only, so the
// diff must find nothing. Both corpora, the vendor dialects included. And so
// that "nothing" is not all compare() can say: the same formatted text with
// ProdCode raised by one must give exactly that one difference, with the
// numbers worked out here from the text.
#include <regex>

#include "corpus_dirs.hpp"
#include "diff_support.hpp"
#include "edit/format.hpp"
#include "test_paths.hpp"

using namespace diff_test;

namespace {

// `text` with its decimal ProdCode raised by one (lowered at 65535); nullopt
// when the file writes none. Sets `was` and `now` to the two numbers.
std::optional<std::string> other_product_code(const std::string& text, unsigned& was, unsigned& now) {
  static const std::regex entry(R"((\n[ \t]*ProdCode[ \t]*=[ \t]*)([0-9]+)([ \t]*;))", std::regex::icase);
  std::smatch m;
  if (!std::regex_search(text, m, entry)) return std::nullopt;
  was = static_cast<unsigned>(std::stoul(m[2].str()));
  now = was == 65535 ? was - 1 : was + 1;
  return m.prefix().str() + m[1].str() + std::to_string(now) + m[3].str() + m.suffix().str();
}

// Diffs each file against its formatted text; returns how many were compared.
std::size_t against_fmt(const fs::path& dir) {
  std::size_t compared = 0, changed = 0;
  for (const auto& p : edsc::corpora::sample_of(dir)) {
    const auto text = read_bytes(p);
    const auto a = edsc::edit::analyze(p.string(), text);
    if (a->has_syntax_errors()) continue;  // diff refuses those (exit 2), as fmt does
    const auto formatted = edsc::edit::format(a->tree, {});
    if (!formatted) continue;
    const auto b = edsc::edit::analyze(p.string(), *formatted);
    const auto r = edsc::diff::compare(*a, *b);
    EXPECT_TRUE(r.differences.empty()) << p.filename() << ":\n" << edsc::diff::render_text(r, *a, *b, {});
    // And the file against itself.
    EXPECT_TRUE(edsc::diff::compare(*a, *a).differences.empty()) << p.filename();
    ++compared;
    unsigned was = 0, now = 0;
    if (const auto other = other_product_code(*formatted, was, now)) {
      const auto c = edsc::edit::analyze(p.string(), *other);
      const auto r = edsc::diff::compare(*a, *c);
      EXPECT_EQ(r.differences.size(), 1u) << p.filename() << ":\n" << edsc::diff::render_text(r, *a, *c, {});
      if (r.differences.size() != 1) continue;
      const auto& d = r.differences[0];
      EXPECT_EQ(d.kind, "identity-product");
      EXPECT_EQ(d.level, impact::breaking);
      EXPECT_EQ(d.message,
                "product code (ProdCode) changed from " + std::to_string(was) + " to " + std::to_string(now));
      EXPECT_EQ(r.keys.before.product_code, was);
      EXPECT_EQ(r.keys.after.product_code, now);
      EXPECT_FALSE(r.keys.exact_match);
      EXPECT_FALSE(r.keys.compatible_match);
      ++changed;
    }
  }
  // Nearly every file writes its ProdCode in decimal.
  EXPECT_GE(changed * 10, compared * 8) << changed << " of " << compared;
  return compared;
}

}  // namespace

TEST(DiffCorpus, EveryFileEqualsItsFormattedSelf) {
  const auto n = against_fmt(EDSC_CORPUS_DIR);
  // All but the two files with syntax errors (of the sample under ASan).
  EXPECT_EQ(n, edsc::corpora::sample_of(EDSC_CORPUS_DIR).size() - 2) << "too few corpus files compared";
}

TEST(DiffCorpus, EveryRockwellFileEqualsItsFormattedSelf) {
  const auto n = against_fmt(EDSC_CORPUS_ROCKWELL_DIR);
  EXPECT_EQ(n, edsc::corpora::sample_of(EDSC_CORPUS_ROCKWELL_DIR).size()) << "too few Rockwell corpus files compared";
}
