#pragma once
// The fact collectors split by family, and the numbers a connection or an
// assembly states, for whoever needs them without the whole header_facts.
#include <vector>

#include "facts/c_text.hpp"
#include "facts/header_view.hpp"

namespace edsc::emit {

[[nodiscard]] std::vector<eip_connection_facts> collect_connections(const model::device& dev,
                                                                    std::vector<header_issue>& issues);
[[nodiscard]] std::vector<param_facts> collect_params(const model::device& dev);

// The integer a value states, following a ParamN reference to its default;
// nullopt when neither gives a non-negative integer.
[[nodiscard]] std::optional<std::uint64_t> number_or_param_default(const model::device& dev, const model::value& v);
// The number an EPATH segment carries; a [ParamN] placeholder stands for its
// default, and a word the tool fills in (`SLOT`) for nothing.
[[nodiscard]] std::optional<std::uint64_t> segment_number(const model::device& dev, const model::epath_segment& s);
// The assembly a connection's format field names, or null.
[[nodiscard]] const model::assembly* assembly_of(const model::device& dev, const model::value& format);
// Bytes of an assembly: its size field, else the sum of its members' bits.
[[nodiscard]] std::uint32_t assembly_size(const model::device& dev, const model::assembly* a);

}  // namespace edsc::emit
