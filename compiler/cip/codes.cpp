// The names and words of cip/codes.def, looked up by code: one table of
// every code, each row tagged with the enum it belongs to.
#include "cip/codes.hpp"

namespace edsc::cip {

namespace {

enum class table : std::uint8_t { command, item, encap_status, class_id, service, general, extended, bit, state };

struct row {
  table in;
  std::uint32_t code;
  std::string_view text;
  std::uint32_t cls = 0;  // a class-specific service's class; 0 for the others
  bool class_specific = false;
};

#define ENIP_COMMAND(sym, code, name) {table::command, code, name},
#define CPF_ITEM(sym, code, name) {table::item, code, name},
#define ENCAP_STATUS(sym, code, words) {table::encap_status, code, words},
#define CIP_CLASS(sym, code, name) {table::class_id, code, name},
#define CIP_SERVICE(sym, code, name) {table::service, code, name},
#define CIP_CLASS_SERVICE(sym, c, n, name) {table::service, n, name, code(class_id::c), true},
#define GENERAL_STATUS(sym, code, words, ...) {table::general, code, words},
#define EXTENDED_STATUS(sym, code, words, ...) {table::extended, code, words},
#define IDENTITY_BIT(sym, mask, words) {table::bit, mask, words},
#define DEVICE_STATE(sym, value, words) {table::state, value, words},
constexpr row rows[] = {
#include "cip/codes.def"
};

std::string_view look_up(table in, std::uint32_t c, std::optional<std::uint32_t> cls = std::nullopt) {
  for (const auto& r : rows)
    if (r.in == in && r.code == c && (!r.class_specific || r.cls == cls)) return r.text;
  return {};
}

}  // namespace

std::string_view name_of(command c) { return look_up(table::command, code(c)); }
std::string_view name_of(item i) { return look_up(table::item, code(i)); }
std::string_view name_of(class_id c) { return look_up(table::class_id, code(c)); }
std::string_view words_of(encap_status s) { return look_up(table::encap_status, code(s)); }
std::string_view words_of(general_status s) { return look_up(table::general, code(s)); }
std::string_view words_of(extended_status s) { return look_up(table::extended, code(s)); }
std::string_view words_of(identity_bit b) { return look_up(table::bit, code(b)); }
std::string_view words_of(device_state s) { return look_up(table::state, code(s)); }

std::string_view name_of(service s, std::optional<class_id> cls) {
  return look_up(table::service, code(s), cls ? std::optional<std::uint32_t>(code(*cls)) : std::nullopt);
}

}  // namespace edsc::cip
