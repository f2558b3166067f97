#pragma once
// The codes of the wire as enums, each with its ODVA name or its words, all
// from cip/codes.def. Values read off the wire that the table lacks are
// still values of these enums (their underlying type holds any code); the
// name functions return an empty view for them.
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

namespace edsc::cip {

#define ENIP_COMMAND(sym, code, name) sym = code,
enum class command : std::uint16_t {
#include "cip/codes.def"
};
#undef ENIP_COMMAND

#define CPF_ITEM(sym, code, name) sym = code,
enum class item : std::uint16_t {
#include "cip/codes.def"
};
#undef CPF_ITEM

#define ENCAP_STATUS(sym, code, words) sym = code,
enum class encap_status : std::uint32_t {
#include "cip/codes.def"
};
#undef ENCAP_STATUS

#define CIP_CLASS(sym, code, name) sym = code,
enum class class_id : std::uint32_t {
#include "cip/codes.def"
};
#undef CIP_CLASS

#define CIP_SERVICE(sym, code, name) sym = code,
#define CIP_CLASS_SERVICE(sym, cls, code, name) sym = code,
enum class service : std::uint8_t {
#include "cip/codes.def"
};
#undef CIP_SERVICE
#undef CIP_CLASS_SERVICE

#define GENERAL_STATUS(sym, code, words, ...) sym = code,
enum class general_status : std::uint8_t {
#include "cip/codes.def"
};
#undef GENERAL_STATUS

#define EXTENDED_STATUS(sym, code, words, ...) sym = code,
enum class extended_status : std::uint16_t {
#include "cip/codes.def"
};
#undef EXTENDED_STATUS

#define IDENTITY_BIT(sym, mask, words) sym = mask,
enum class identity_bit : std::uint16_t {
#include "cip/codes.def"
};
#undef IDENTITY_BIT

#define DEVICE_STATE(sym, value, words) sym = value,
enum class device_state : std::uint8_t {
#include "cip/codes.def"
};
#undef DEVICE_STATE

// A reply's service is the request's with this bit set.
inline constexpr std::uint8_t reply_bit = 0x80;

template <class E>
[[nodiscard]] constexpr auto code(E e) {
  return static_cast<std::underlying_type_t<E>>(e);
}

// Names and words; empty when the table lacks the code.
[[nodiscard]] std::string_view name_of(command c);
[[nodiscard]] std::string_view name_of(item i);
[[nodiscard]] std::string_view name_of(class_id c);
[[nodiscard]] std::string_view words_of(encap_status s);
[[nodiscard]] std::string_view words_of(general_status s);
[[nodiscard]] std::string_view words_of(extended_status s);
[[nodiscard]] std::string_view words_of(identity_bit b);
[[nodiscard]] std::string_view words_of(device_state s);
// A service's name: the services every object has by code alone, the others
// (0x4B-0x63) only with the class they belong to.
[[nodiscard]] std::string_view name_of(service s, std::optional<class_id> cls = std::nullopt);

// The Identity status WORD's extended device status (bits 4-7) and the word
// with it set.
[[nodiscard]] constexpr device_state device_state_of(std::uint16_t status) {
  return static_cast<device_state>((status >> 4) & 0x0F);
}
[[nodiscard]] constexpr std::uint16_t with_device_state(std::uint16_t status, device_state s) {
  return static_cast<std::uint16_t>((status & ~0x00F0u) | (static_cast<unsigned>(s) << 4));
}

}  // namespace edsc::cip
