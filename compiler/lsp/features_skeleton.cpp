// Placeholder answers so the server links while the features are written;
// each function moves to its own file as it is implemented.
#include "lsp/features.hpp"

namespace edsc::lsp {

std::optional<span> prepare_rename(const analysis&, std::uint32_t) { return std::nullopt; }
rename_result rename(const analysis&, std::uint32_t, std::string_view) { return {}; }

}  // namespace edsc::lsp
