#pragma once
// Every place a file names a numbered entry: the entries themselves
// (`Param5 =`), references in fields (`Param5`, `5` in a number field such
// as a GroupN member), `[Param5]` inside EPATHs, and the keywords that
// belong to a parameter (`Enum5` in [Params], `Param5` in [EnumPar]).
// Read from the tree by the schema, as lowering reads it; navigation, rename and hover
// share it.
//
// InputN/OutputN are numbered per section: [IO_Info] and [Variant_IO_Info]
// each define their own Input1 (EDS_FORMAT.md §3.5), and the default of an
// xxxInfo entry names the InputN/OutputN of its own section. A target is
// therefore (kind, number, variant_io).
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
  bool declaration = false;         // the entry's own keyword
  bool variant_io = false;          // an InputN/OutputN site in [Variant_IO_Info]
  std::uint32_t entry = cst::npos;  // CST entry the site is in
};

class ref_index {
 public:
  explicit ref_index(const analysis& a);

  // The site the cursor touches, or nullptr.
  [[nodiscard]] const ref_site* at(std::uint32_t offset) const;
  // Every site naming (kind, number) in [Variant_IO_Info] or elsewhere, in file order.
  [[nodiscard]] std::vector<const ref_site*> of(schema::ref_kind kind, std::uint32_t number,
                                                bool variant_io = false) const;
  [[nodiscard]] const std::vector<ref_site>& sites() const { return sites_; }

 private:
  std::vector<ref_site> sites_;  // sorted by position
};

// The site under the cursor, read from its entry alone (no index needed).
[[nodiscard]] std::optional<ref_site> site_at(const analysis& a, std::uint32_t offset);
// The sites of one entry, in order: its keyword, then its fields.
void entry_sites(const analysis& a, std::uint32_t entry, const schema::section_desc& sd, std::vector<ref_site>& out);

// True when (kind) named in section `sd` is an InputN/OutputN of [Variant_IO_Info].
[[nodiscard]] bool variant_io_site(const schema::section_desc& sd, schema::ref_kind kind);

// Where (kind, number) is in the model's vector for its kind (d.params,
// d.io.inputs, d.variant_io.inputs...), or model::none. The first definition wins.
[[nodiscard]] std::uint32_t target_index(const model::device& d, schema::ref_kind kind, std::uint32_t number,
                                         bool variant_io = false);
// The declaration of (kind, number): the keyword of its first definition,
// found through the model without building a ref_index.
[[nodiscard]] std::optional<span> declaration_of(const analysis& a, schema::ref_kind kind, std::uint32_t number,
                                                 bool variant_io = false);
// The CST entry defining (kind, number), or cst::npos.
[[nodiscard]] std::uint32_t defining_entry(const model::device& d, schema::ref_kind kind, std::uint32_t number,
                                           bool variant_io = false);

// A numbered keyword of the schema that defines a reference target, with
// the kind it defines; false for other keywords.
[[nodiscard]] bool defines(const schema::keyword_desc& k, schema::ref_kind& kind);

}  // namespace edsc::lsp
