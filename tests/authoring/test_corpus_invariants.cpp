// The three promises of the authoring tools on every real EDS file: edit
// without operations gives the bytes back, fmt is idempotent and keeps the
// model, fix is idempotent. Run in-process so all 117 files stay fast.
#include <unistd.h>

#include "authoring_support.hpp"
#include "edit/analyze.hpp"
#include "edit/editor.hpp"
#include "edit/fingerprint.hpp"
#include "edit/fix.hpp"
#include "edit/format.hpp"

namespace authoring {
namespace {

using namespace edsc;

bool has_syntax_errors(const fs::path& p) {
  const auto name = p.filename().string();
  return name == kh_ko || name == fanuc;
}

TEST(CorpusInvariants, EditWithoutOperationsIsByteIdentical) {
  std::size_t n = 0;
  for (const auto& p : corpus_files()) {
    SCOPED_TRACE(p.filename().string());
    const auto bytes = read_bytes(p);
    edit::editor ed(p.string(), bytes);
    EXPECT_TRUE(ed.text() == bytes);
    ++n;
  }
  EXPECT_GE(n, edsc::corpora::sample_size());
}

TEST(CorpusInvariants, FmtIsIdempotentAndKeepsTheModel) {
  std::size_t formatted = 0, refused = 0;
  for (const auto& p : corpus_files()) {
    SCOPED_TRACE(p.filename().string());
    const auto bytes = read_bytes(p);
    const auto a = edit::analyze(p.string(), bytes);
    const auto once = edit::format(a->tree, {});
    if (a->has_syntax_errors()) {
      // Refused by the command; the library may still lay out what parsed.
      EXPECT_TRUE(has_syntax_errors(p)) << "unexpected syntax errors";
      ++refused;
      continue;
    }
    ASSERT_TRUE(once.has_value()) << once.error().why;
    EXPECT_EQ(edit::model_fingerprint(p.string(), *once), edit::model_fingerprint(p.string(), bytes))
        << "fmt changed the model";
    const auto b = edit::analyze(p.string(), *once);
    const auto twice = edit::format(b->tree, {});
    ASSERT_TRUE(twice.has_value()) << twice.error().why;
    EXPECT_TRUE(*twice == *once) << "fmt is not idempotent";
    // The line ending of the input is kept.
    EXPECT_EQ(edit::dominant_eol(*once), edit::dominant_eol(bytes));
    ++formatted;
  }
  EXPECT_EQ(refused, 2u);
  EXPECT_GE(formatted, edsc::corpora::sample_size() - 2);
}

TEST(CorpusInvariants, FmtWithEolChangesOnlyLineEndings) {
  for (const auto& p : corpus_files()) {
    if (has_syntax_errors(p)) continue;
    SCOPED_TRACE(p.filename().string());
    const auto bytes = read_bytes(p);
    const auto a = edit::analyze(p.string(), bytes);
    const auto lf = edit::format(a->tree, {"\n"});
    const auto crlf = edit::format(a->tree, {"\r\n"});
    ASSERT_TRUE(lf && crlf);
    EXPECT_EQ(lf->find('\r'), std::string::npos);
    EXPECT_TRUE(edit::with_eol(*lf, "\r\n") == *crlf);
  }
}

TEST(CorpusInvariants, FixIsIdempotent) {
  std::size_t repaired = 0;
  for (const auto& p : corpus_files()) {
    SCOPED_TRACE(p.filename().string());
    const auto bytes = read_bytes(p);
    const auto once = edit::fix_text(p.string(), bytes, {});
    EXPECT_TRUE(once.converged);
    const auto twice = edit::fix_text(p.string(), once.text, {});
    EXPECT_TRUE(twice.applied.empty()) << twice.applied.front().where << " " << twice.applied.front().message;
    EXPECT_TRUE(twice.text == once.text);
    // Nothing left that carries a fix-it.
    // Named: a range-for over `analyze(...)->diags` would destroy the analysis
    // before the loop body reads it (found by ASan).
    const auto after = edit::analyze(p.string(), once.text);
    for (const auto& d : after->diags) EXPECT_TRUE(d.fixits.empty()) << d.message;
    repaired += once.applied.empty() ? 0 : 1;
    if (once.applied.empty()) {
      EXPECT_TRUE(once.text == bytes);
    }
  }
  EXPECT_GE(repaired, 1u);  // kh-ko's missing semicolons at least
}

}  // namespace
}  // namespace authoring
