#include "schema/cip_types.hpp"

#include <array>
#include <limits>

#include "schema/text.hpp"

namespace edsc::schema {

namespace {

constexpr std::int64_t i64min = std::numeric_limits<std::int64_t>::min();
constexpr std::uint64_t u64max = std::numeric_limits<std::uint64_t>::max();
constexpr std::uint64_t i64max = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());

using tc = type_class;

// EDS_FORMAT.md §4.1, in code order so lookup is an index.
constexpr std::array<cip_type_info, 32> types{{
    {0xC0, "UTIME", 8, tc::other, 0, u64max},
    {0xC1, "BOOL", 1, tc::unsigned_int, 0, 1},
    {0xC2, "SINT", 1, tc::signed_int, -128, 127},
    {0xC3, "INT", 2, tc::signed_int, -32768, 32767},
    {0xC4, "DINT", 4, tc::signed_int, -2147483648LL, 2147483647ULL},
    {0xC5, "LINT", 8, tc::signed_int, i64min, i64max},
    {0xC6, "USINT", 1, tc::unsigned_int, 0, 0xFF},
    {0xC7, "UINT", 2, tc::unsigned_int, 0, 0xFFFF},
    {0xC8, "UDINT", 4, tc::unsigned_int, 0, 0xFFFFFFFFULL},
    {0xC9, "ULINT", 8, tc::unsigned_int, 0, u64max},
    {0xCA, "REAL", 4, tc::real, 0, 0},
    {0xCB, "LREAL", 8, tc::real, 0, 0},
    {0xCC, "STIME", 4, tc::signed_int, -2147483648LL, 2147483647ULL},
    {0xCD, "DATE", 2, tc::unsigned_int, 0, 0xFFFF},
    {0xCE, "TIME_OF_DAY", 4, tc::unsigned_int, 0, 0xFFFFFFFFULL},
    {0xCF, "DATE_AND_TIME", 6, tc::unsigned_int, 0, 0xFFFFFFFFFFFFULL},
    {0xD0, "STRING", 0, tc::string, 0, 0},
    {0xD1, "BYTE", 1, tc::bit_string, 0, 0xFF},
    {0xD2, "WORD", 2, tc::bit_string, 0, 0xFFFF},
    {0xD3, "DWORD", 4, tc::bit_string, 0, 0xFFFFFFFFULL},
    {0xD4, "LWORD", 8, tc::bit_string, 0, u64max},
    {0xD5, "STRING2", 0, tc::string, 0, 0},
    {0xD6, "FTIME", 4, tc::signed_int, -2147483648LL, 2147483647ULL},
    {0xD7, "LTIME", 8, tc::signed_int, i64min, i64max},
    {0xD8, "ITIME", 2, tc::signed_int, -32768, 32767},
    {0xD9, "STRINGN", 0, tc::string, 0, 0},
    {0xDA, "SHORT_STRING", 0, tc::string, 0, 0},
    {0xDB, "TIME", 4, tc::signed_int, -2147483648LL, 2147483647ULL},
    {0xDC, "EPATH", 0, tc::epath, 0, 0},
    {0xDD, "ENGUNIT", 2, tc::unsigned_int, 0, 0xFFFF},
    {0xDE, "STRINGI", 0, tc::stringi, 0, 0},
    {0xDF, "NTIME", 8, tc::other, 0, u64max},
}};

struct legacy_row {
  std::uint8_t legacy;
  std::uint8_t code;
  bool confirmed;
};

// §4.2: 1,2,3,5,6,8,9,11,23,24,25 are confirmed; the rest follows the
// obvious order of the old Parameter Object table and is a guess.
constexpr std::array<legacy_row, 15> legacy{{
    {1, code::WORD, true},
    {2, code::UINT, true},
    {3, code::INT, true},
    {4, code::BOOL, false},
    {5, code::SINT, true},
    {6, code::DINT, true},
    {7, code::LINT, false},
    {8, code::USINT, true},
    {9, code::UDINT, true},
    {10, code::ULINT, false},
    {11, code::REAL, true},
    {12, code::LREAL, false},
    {23, code::SHORT_STRING, true},
    {24, code::BYTE, true},
    {25, code::DWORD, true},
}};

}  // namespace

const cip_type_info* find_type(std::uint32_t c) {
  if (c < 0xC0 || c > 0xDF) return nullptr;
  return &types[c - 0xC0];
}

const cip_type_info* find_type_by_name(std::string_view name) {
  for (const auto& t : types)
    if (iequals(t.name, name)) return &t;
  return nullptr;
}

legacy_mapping map_legacy_type(std::uint32_t legacy_code) {
  for (const auto& r : legacy)
    if (r.legacy == legacy_code) return {r.code, r.confirmed};
  return {};
}

const cip_type_info* resolve_param_type(std::uint64_t c, bool* was_legacy) {
  if (was_legacy) *was_legacy = false;
  if (c > 0xFF) return nullptr;
  if (const auto* t = find_type(static_cast<std::uint32_t>(c))) return t;
  const auto m = map_legacy_type(static_cast<std::uint32_t>(c));
  if (m.code == 0) return nullptr;
  if (was_legacy) *was_legacy = true;
  return find_type(m.code);
}

}  // namespace edsc::schema
