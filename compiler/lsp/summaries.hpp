#pragma once
// One sentence on what each section and keyword of an EDS is for, shown by
// hover and completion. The schema says how entries are laid out; this says
// what they mean to the person writing the file (EDS_FORMAT.md §3).
#include <string_view>

#include "schema/schema.hpp"

namespace edsc::lsp {

[[nodiscard]] std::string_view summary_of(const schema::keyword_desc& k);
[[nodiscard]] std::string_view summary_of(const schema::section_desc& s);

}  // namespace edsc::lsp
