#pragma once
// Every place a file names a numbered entry: the entries themselves
// (`Param5 =`), references in fields (`Param5`, `5` in a number field such
// as a GroupN member), `[Param5]` inside EPATHs, and the keywords that
// belong to a parameter (`Enum5` in [Params], `Param5` in [EnumPar]).
// Read from the tree by the schema, as lowering reads it; navigation, rename and hover
// share it.
#include <cstdint>
#include <optional>
#include <vector>

#include "check/check_file.hpp"
#include "schema/schema.hpp"

namespace edsc::lsp {

struct ref_site {
  span name;    // `Param5`, `5`, or the `Param5` of `[Param5]`
  span digits;  // the number inside `name`: what a renumbering replaces
  std::uint32_t number = 0;
  schema::ref_kind kind = schema::ref_kind::param;
  bool declaration = false;  // the entry's own keyword
  std::uint32_t entry = cst::npos;  // CST entry the site is in
};

class ref_index {
 public:
  explicit ref_index(const analysis& a);

  // The site the cursor touches, or nullptr.
  [[nodiscard]] const ref_site* at(std::uint32_t offset) const;
  // Every site naming (kind, number), in file order.
  [[nodiscard]] std::vector<const ref_site*> of(schema::ref_kind kind, std::uint32_t number) const;
  [[nodiscard]] const std::vector<ref_site>& sites() const { return sites_; }

 private:
  std::vector<ref_site> sites_;  // sorted by position
};

// The site under the cursor, read from its entry alone (no index needed).
[[nodiscard]] std::optional<ref_site> site_at(const analysis& a, std::uint32_t offset);
// The sites of one entry, in order: its keyword, then its fields.
void entry_sites(const analysis& a, std::uint32_t entry, const schema::section_desc& sd, std::vector<ref_site>& out);

// The declaration of (kind, number): the keyword of its first definition,
// found through the model's index without building a ref_index.
[[nodiscard]] std::optional<span> declaration_of(const analysis& a, schema::ref_kind kind, std::uint32_t number);
// The CST entry defining (kind, number), or cst::npos.
[[nodiscard]] std::uint32_t defining_entry(const model::device& d, schema::ref_kind kind, std::uint32_t number);

// A numbered keyword of the schema that defines a reference target, with
// the kind it defines; false for other keywords.
[[nodiscard]] bool defines(const schema::keyword_desc& k, schema::ref_kind& kind);

}  // namespace edsc::lsp
