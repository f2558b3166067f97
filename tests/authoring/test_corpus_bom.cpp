// Every real EDS file again behind a UTF-8 byte-order mark, as Windows
// editors save them: the same findings at the same lines and columns, shown
// the same way, and fmt, fix and edit write the mark back followed by what
// they write for the file without it.
#include "authoring_support.hpp"
#include "diag/render_text.hpp"
#include "edit/analyze.hpp"
#include "edit/editor.hpp"
#include "edit/fix.hpp"
#include "edit/format.hpp"
#include "edit/locate.hpp"

namespace authoring {
namespace {

using namespace edsc;

const std::string bom = "\xEF\xBB\xBF";

std::string rendered(const analysis& a) {
  std::string out;
  for (const auto& d : a.diags) render_text(*a.source, d, {}, out);
  return out;
}

std::string applied(const edit::fix_result& r) {
  std::string out;
  for (const auto& f : r.applied) out += f.where + " " + f.change + " " + f.rule + "\n";
  return out;
}

// The edit operations every file can take: the first section removed (the
// mark stays in front of what follows), a section added, a value set.
std::string edited(const std::string& path, const std::string& bytes, std::string& log) {
  edit::editor ed(path, bytes);
  const auto a = edit::analyze(path, bytes);
  // The first refusal stops the sequence, as `edsc edit` stops at it.
  auto r = a->tree.sections.empty() ? edit::edited{} : ed.remove_section(a->tree.text(a->tree.sections[0].name));
  if (r) r = ed.add_section("Byte Order Mark Test");
  if (r) r = ed.set("Device.ProdName=\"marked\"");
  if (!r) log += std::string("refused: ") + r.error().what() + "\n";
  for (const auto& line : ed.log()) log += line + "\n";
  return ed.text();
}

TEST(CorpusByteOrderMark, ChangesNoFindingAndIsKeptByEveryWriter) {
  std::size_t n = 0;
  for (const auto& p : corpus_files()) {
    SCOPED_TRACE(p.filename().string());
    const auto path = p.string();
    const auto bytes = read_bytes(p);
    const auto marked = bom + bytes;
    const auto a = edit::analyze(path, bytes);
    const auto b = edit::analyze(path, marked);
    // Rendered text holds each finding's rule, line, column, message, quoted
    // line, caret, fix-its and notes: all of them must be the same.
    EXPECT_EQ(rendered(*b), rendered(*a));
    EXPECT_EQ(b->has_syntax_errors(), a->has_syntax_errors());

    const auto fa = edit::format(a->tree, {});
    const auto fb = edit::format(b->tree, {});
    ASSERT_EQ(fb.has_value(), fa.has_value()) << (fa ? "" : fa.error().why) << " / " << (fb ? "" : fb.error().why);
    if (fa) {
      EXPECT_TRUE(*fb == bom + *fa) << "fmt";
    }

    const auto xa = edit::fix_text(path, bytes, {});
    const auto xb = edit::fix_text(path, marked, {});
    EXPECT_TRUE(xb.text == bom + xa.text) << "fix";
    EXPECT_EQ(applied(xb), applied(xa));

    std::string log_a, log_b;
    const auto ea = edited(path, bytes, log_a);
    const auto eb = edited(path, marked, log_b);
    EXPECT_TRUE(eb == bom + ea) << "edit";
    EXPECT_EQ(log_b, log_a);
    EXPECT_TRUE(edit::editor(path, marked).text() == marked);
    ++n;
  }
  EXPECT_GE(n, edsc::corpora::sample_size());
}

}  // namespace
}  // namespace authoring
