#pragma once
// Field values spelled out for a reader, as Markdown: bit masks as the names
// of their set bits, type codes as CIP names, EPATHs as their segments. The
// decoding itself is the model's (model::decode_*, schema::find_type); this
// only words it.
#include <cstdint>
#include <string>

#include "cst/cst.hpp"
#include "model/device.hpp"

namespace edsc::lsp {

[[nodiscard]] std::string describe_param_descriptor(std::uint64_t v);
[[nodiscard]] std::string describe_io_mask(std::uint64_t v);
[[nodiscard]] std::string describe_trigger(std::uint32_t v);
[[nodiscard]] std::string describe_connection_params(std::uint32_t v);
// `0xC7` -> "UINT (unsigned 16-bit integer, 2 bytes)"; legacy DeviceNet codes mapped.
[[nodiscard]] std::string describe_type_code(std::uint64_t code);
// One line per segment: class, instance, attribute, connection point...
// `dev` resolves [ParamN] placeholders to their names.
[[nodiscard]] std::string describe_epath(const model::epath& p, const model::device& dev);
// "4 bytes (32 bits)" / "12 bits (1 byte and 4 bits)" / "3 bits"
[[nodiscard]] std::string bytes_and_bits(std::uint64_t bytes);
[[nodiscard]] std::string bits_and_bytes(std::uint64_t bits);
// Bits set beyond `known`, as "bits 7, 12".
[[nodiscard]] std::string other_bits(std::uint64_t v, std::uint64_t known);
// The body of a quoted field (pieces joined, escapes kept as written).
[[nodiscard]] std::string string_text(const cst::tree& t, const cst::field& f);
// An entry's name string, when its layout has a field called `name`.
[[nodiscard]] std::string entry_name(const cst::tree& t, const cst::entry& e, const schema::keyword_desc* k);
// A ConnectionN as `edsc connection` says it (connections/summary.hpp),
// one list item a setting; empty when the file gives it no settings (a
// repeated number).
[[nodiscard]] std::string describe_connection(const model::device& dev, const model::connection& c);
// A parameter in one line: `"Speed"` UINT, 0..3000, default 1500 rpm.
[[nodiscard]] std::string param_line(const model::device& dev, const model::param& p);

}  // namespace edsc::lsp
