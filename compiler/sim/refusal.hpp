#pragma once
// Internal to the simulator's Connection Manager: why a Forward_Open is
// refused. What the EDS alone decides is connections::check_fit; this adds
// what the simulator holds now.
#include <optional>

#include "cip/request.hpp"
#include "connections/forward_open_fit.hpp"
#include "sim/state.hpp"

namespace edsc::sim {

using connections::check_key;
using connections::ext;
using connections::path_words;
using connections::refusal;

// Why `fo` cannot open `p`: connections::check_fit, then the simulator's
// limit on open connections, an output already owned, a listen-only
// connection to an input nobody produces.
[[nodiscard]] std::optional<refusal> check_point(const state& s, const connection_point& p,
                                                 const cip::forward_open_request& fo,
                                                 std::optional<cip::byte_view> config);

}  // namespace edsc::sim
