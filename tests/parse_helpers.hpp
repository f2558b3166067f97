#pragma once
// Shared by the grammar and corpus tests: parse a string in memory, check the
// invariants every parse must keep, and describe the result compactly so a test
// can compare it with one EXPECT_EQ.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "parse/parser.hpp"

namespace edsc::test {

// A source file and its parse; the tree points into the source, so both live here.
struct parsed {
  std::unique_ptr<source_file> src;
  parse_result result;

  [[nodiscard]] const cst::tree& tree() const { return result.tree; }
  [[nodiscard]] const diagnostics& diags() const { return result.diags; }
  [[nodiscard]] std::string_view text(span s) const { return src->text(s); }

  // The first entry with this keyword; fails the test when there is none.
  [[nodiscard]] const cst::entry& entry(std::string_view keyword) const {
    for (const auto& e : tree().entries) {
      if (text(e.keyword) == keyword) return e;
    }
    ADD_FAILURE() << "no entry '" << keyword << "'";
    static const cst::entry none{};
    return none;
  }
  [[nodiscard]] const cst::field& field(std::string_view keyword, std::uint32_t i) const {
    const auto& e = entry(keyword);
    if (i >= e.fields_count) {
      ADD_FAILURE() << "entry '" << keyword << "' has no field " << i;
      static const cst::field none{};
      return none;
    }
    return tree().field_of(e, i);
  }

  // The text of every field of an entry, in order ("" for empty fields).
  [[nodiscard]] std::vector<std::string> fields(std::string_view keyword) const {
    std::vector<std::string> out;
    const auto& e = entry(keyword);
    for (std::uint32_t i = 0; i < e.fields_count; ++i) out.emplace_back(text(tree().field_of(e, i).where));
    return out;
  }
  [[nodiscard]] std::vector<std::string> children(const cst::field& f) const {
    std::vector<std::string> out;
    for (std::uint32_t i = 0; i < f.children_count(); ++i) out.emplace_back(text(tree().child_of(f, i).where));
    return out;
  }
  [[nodiscard]] std::vector<std::string> pieces(const cst::field& f) const {
    std::vector<std::string> out;
    for (std::uint32_t i = 0; i < f.pieces_count(); ++i) out.emplace_back(tree().text(tree().piece_of(f, i)));
    return out;
  }
  [[nodiscard]] std::vector<std::string> keywords() const {
    std::vector<std::string> out;
    for (const auto& e : tree().entries) out.emplace_back(text(e.keyword));
    return out;
  }
  [[nodiscard]] std::vector<std::string> section_names() const {
    std::vector<std::string> out;
    for (const auto& s : tree().sections) out.emplace_back(text(s.name));
    return out;
  }
  // Tokens as "kind:text", e.g. "bare:0x0F".
  [[nodiscard]] std::vector<std::string> tokens() const {
    std::vector<std::string> out;
    for (const auto& t : tree().tokens) {
      out.push_back(std::string(cst::to_string(t.kind)) + ":" + std::string(tree().text(t)));
    }
    return out;
  }
  [[nodiscard]] std::size_t count(cst::token_kind k) const {
    std::size_t n = 0;
    for (const auto& t : tree().tokens) n += t.kind == k ? 1 : 0;
    return n;
  }
  // Diagnostics as "id@line:column", in the order the parser reports them.
  [[nodiscard]] std::vector<std::string> diag_list() const {
    std::vector<std::string> out;
    for (const auto& d : diags()) {
      const auto p = src->position(d.where.begin);
      out.push_back(std::string(rule_of(d.id).name) + "@" + std::to_string(p.line) + ":" + std::to_string(p.column));
    }
    return out;
  }
};

// Every parse in the tests goes through here: printing the tree must give the
// input back byte for byte, and the tree must tile and nest properly.
inline parsed parse_text(std::string text) {
  parsed p;
  p.src = std::make_unique<source_file>("t.eds", std::move(text));
  p.result = parse(*p.src);
  EXPECT_EQ(cst::print(p.result.tree), p.src->text()) << "the tree does not print its input back";
  EXPECT_EQ(cst::first_structure_violation(p.result.tree), cst::npos) << "the tree does not tile the input";
  return p;
}

using strings = std::vector<std::string>;

}  // namespace edsc::test
