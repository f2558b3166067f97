// `edsc edit --resize Input1=3`: the DeviceNet job users come for. The new
// size goes into [IO_Info]; the data set it replaces is kept, byte for byte,
// as the same keyword in [Variant_IO_Info] (EDS_FORMAT.md §3.5: a
// configuration tool accepted the new size only with the variant present).
#include <fmt/format.h>

#include "edit/editor.hpp"
#include "edit/locate.hpp"
#include "model/decode.hpp"
#include "schema/text.hpp"

namespace edsc::edit {

namespace {

struct resize_spec {
  std::string keyword;
  std::uint32_t size = 0;
  bool bits_given = false;
  std::uint32_t bits = 0;
};

resize_spec parse_spec(std::string_view spec) {
  const auto eq = spec.find('=');
  resize_spec r;
  const auto kw = spec.substr(0, eq);
  const auto parts = schema::split_number(kw);
  const bool io_keyword = schema::iequals(parts.stem, "Input") || schema::iequals(parts.stem, "Output");
  std::uint32_t n = 0;
  if (eq == std::string_view::npos || !io_keyword || !schema::parse_u32(parts.digits, n))
    throw edit_error(
        fmt::format("'{}' is not a resize; write InputN=bytes or OutputN=bytes[:significant bits], "
                    "e.g. Input1=3",
                    spec));
  r.keyword = fmt::format("{}{}", schema::iequals(parts.stem, "Input") ? "Input" : "Output", n);
  auto rhs = spec.substr(eq + 1);
  const auto colon = rhs.find(':');
  if (!schema::parse_u32(rhs.substr(0, colon), r.size) || r.size > 0xFFFF)
    throw edit_error(fmt::format("'{}': the size must be a number of bytes, 0 to 65535", spec));
  if (colon != std::string_view::npos) {
    r.bits_given = true;
    if (!schema::parse_u32(rhs.substr(colon + 1), r.bits) || r.bits > 8u * r.size)
      throw edit_error(
          fmt::format("'{}': significant bits must be 0 (all) to {} for {} bytes", spec, 8u * r.size, r.size));
  }
  return r;
}

std::uint64_t integer_of(std::string_view text, std::string_view what) {
  model::value v;
  if (!model::decode::integer(text, v) || v.negative)
    throw edit_error(fmt::format("the {} '{}' is not a number; fix it before resizing", what, text));
  return v.magnitude;
}

// What the significant-bits field should say for the new size, and why.
std::pair<std::uint32_t, std::string> adjust_bits(std::uint64_t old_size, std::uint64_t old_bits, std::uint32_t size) {
  if (old_bits == 0) return {0, "significant bits stay 0 (every bit significant)"};
  if (old_bits == 8 * old_size)
    return {8 * size,
            fmt::format("significant bits {} -> {}: every bit of the data stays significant", old_bits, 8 * size)};
  if (old_bits <= 8ull * size && (size == 0 || old_bits > 8ull * (size - 1)))
    return {static_cast<std::uint32_t>(old_bits),
            fmt::format("significant bits stay {}: they still end in the last byte", old_bits)};
  return {
      8 * size,
      fmt::format("significant bits {} -> {}: {} bits described the old {}-byte layout and would leave bytes of the "
                  "new one unused; narrow it with --resize {{}}={}:N if some bits carry nothing",
                  old_bits, 8 * size, old_bits, old_size, size)};
}

}  // namespace

void editor::do_resize(std::string_view spec) {
  const auto r = parse_spec(spec);
  const auto io = find_section(tree_, "IO_Info");
  if (io == cst::npos) throw edit_error("--resize needs an [IO_Info] section (DeviceNet I/O); the file has none");
  const auto ei = find_entry(tree_, io, r.keyword);
  if (ei == cst::npos) throw edit_error(fmt::format("[IO_Info] has no {} to resize", r.keyword));
  const auto& e = tree_.entries[ei];
  if (e.fields_count < 2)
    throw edit_error(fmt::format("{} has no significant-bits field to keep consistent", r.keyword));
  const auto old_size = integer_of(tree_.text(tree_.field_of(e, 0).where), "size");
  const auto old_bits = integer_of(tree_.text(tree_.field_of(e, 1).where), "significant bits");
  if (old_size == r.size) throw edit_error(fmt::format("{} is already {} bytes", r.keyword, r.size));

  auto [bits, why] = adjust_bits(old_size, old_bits, r.size);
  if (r.bits_given) {
    bits = r.bits;
    why = fmt::format("significant bits {} -> {} as requested", old_bits, bits);
  }
  why = fmt::format(fmt::runtime(why), r.keyword);

  std::vector<replacement> changes;
  changes.push_back(field_change(ei, 0, std::to_string(r.size)));
  if (bits != old_bits) changes.push_back(field_change(ei, 1, std::to_string(bits)));

  // The old data set, exactly as written (comments and layout included).
  const std::string old_entry(tree_.text(e.where));
  const auto variant = find_section(tree_, "Variant_IO_Info");
  std::string where;
  if (variant == cst::npos) {
    changes.push_back(new_section("Variant_IO_Info", old_entry));
    where = "a new [Variant_IO_Info] section";
  } else {
    const auto twin = find_entry(tree_, variant, r.keyword);
    if (twin != cst::npos && tree_.text(tree_.entries[twin].where) != old_entry)
      throw edit_error(
          fmt::format("[Variant_IO_Info] already holds another {}; remove it first with "
                      "--remove-entry Variant_IO_Info.{}",
                      r.keyword, r.keyword));
    if (twin == cst::npos) {
      const auto at = end_of_section_content(variant);
      changes.push_back({{at, at}, eol_ + entry_indent(variant) + old_entry});
    }
    where = "[Variant_IO_Info]";
  }
  log_.push_back(fmt::format("resize IO_Info.{}: {} -> {} bytes", r.keyword, old_size, r.size));
  log_.push_back(fmt::format("  {}", why));
  log_.push_back(fmt::format("  the previous data set ({} byte{}, {} significant bits) is kept as {} in {}", old_size,
                             old_size == 1 ? "" : "s", old_bits, r.keyword, where));
  commit(std::move(changes));
}

}  // namespace edsc::edit
