#pragma once
#include <optional>
#include <string_view>

#include "diag/diagnostic.hpp"

namespace edsc {

// Recognises input that is not EDS text at all — a UTF-16 or UTF-32 file, a
// NUL byte, an executable or archive — so the parser can say so once instead
// of reporting every byte of it as a syntax error. Returns the one input
// diagnostic, or nothing for 8-bit text (ASCII, Latin-1, UTF-8).
[[nodiscard]] std::optional<diagnostic> not_text(std::string_view bytes);

}  // namespace edsc
