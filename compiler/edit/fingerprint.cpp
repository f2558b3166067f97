#include "edit/fingerprint.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "edit/analyze.hpp"
#include "emit/emit_json.hpp"

namespace edsc::edit {

namespace {

// `"a"\n   "b"` -> `"a" "b"`: only the quoted pieces count.
std::string pieces_only(const std::string& raw) {
  std::string out;
  std::size_t i = 0;
  while (i < raw.size()) {
    const char c = raw[i];
    if (c == '"' || (c == 'L' && i + 1 < raw.size() && raw[i + 1] == '"')) {
      if (!out.empty()) out.push_back(' ');
      const auto start = i;
      i += c == 'L' ? 2 : 1;
      while (i < raw.size() && raw[i] != '"') i += raw[i] == '\\' ? 2 : 1;
      out.append(raw, start, ++i - start);
    } else if (c == '$') {
      while (i < raw.size() && raw[i] != '\n' && raw[i] != '\r') ++i;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      ++i;
    } else {
      return raw;  // not a string sequence: keep as written
    }
  }
  return out;
}

void to_lower(nlohmann::ordered_json& item, const char* key) {
  if (const auto it = item.find(key); it != item.end() && it->is_string()) {
    auto& text = it->get_ref<std::string&>();
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  }
}

void normalise(nlohmann::ordered_json& j) {
  if (j.is_object()) {
    j.erase("line");
    j.erase("column");
    if (auto it = j.find("raw"); it != j.end() && it->is_string()) *it = pieces_only(it->get<std::string>());
    // Keywords and section names match case-insensitively, and fmt respells
    // known ones.
    to_lower(j, "keyword");
    to_lower(j, "section");
    for (auto& [k, v] : j.items()) normalise(v);
  } else if (j.is_array()) {
    for (auto& v : j) normalise(v);
  }
}

// Where `fmt` puts a section: [File], [Device], [Device Classification] first
// (edit/format.cpp), every other section in its original order. `item` is a
// section of the dump (`name`) or an entry kept raw (`section`).
int section_rank(const nlohmann::ordered_json& item, const char* key) {
  const auto it = item.find(key);
  if (it == item.end() || !it->is_string()) return 3;
  const auto& name = it->get_ref<const std::string&>();  // lower case: see order_like_fmt
  if (name == "file") return 0;
  if (name == "device") return 1;
  if (name == "device classification") return 2;
  return 3;
}

// Puts the items of `array` in the order fmt gives their sections.
// Section names are compared in lower case: they match case-insensitively,
// and fmt writes known ones in the schema's spelling.
void order_like_fmt(nlohmann::ordered_json& j, const char* array, const char* key) {
  const auto it = j.find(array);
  if (it == j.end() || !it->is_array()) return;
  for (auto& item : *it) to_lower(item, key);
  std::stable_sort(it->begin(), it->end(),
                   [key](const auto& a, const auto& b) { return section_rank(a, key) < section_rank(b, key); });
}

}  // namespace

nlohmann::ordered_json meaning_of(const analysis& a) {
  auto j = emit::to_json(a.dev, *a.source);
  normalise(j);
  // Section order and case mean nothing in an EDS, but the dump lists
  // sections and the entries it keeps raw as written, and fmt moves the
  // identity sections to the top and respells known names: without this a file with [Device Classification] after
  // [Params] could never be formatted ("internal error: formatting would
  // change the file's meaning"). Found by fuzz_fmt.
  if (auto it = j.find("sections"); it != j.end() && it->is_array()) {
    for (auto& s : *it) s.erase("canonical");  // says only that the spelling differs
  }
  order_like_fmt(j, "sections", "name");
  order_like_fmt(j, "unknown_entries", "section");
  return j;
}

bool same_meaning(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b) {
  using kind = nlohmann::ordered_json::value_t;
  const auto integral = [](kind k) { return k == kind::number_integer || k == kind::number_unsigned; };
  if (integral(a.type()) && integral(b.type())) {
    // Written alike when equal: 5 as a signed or an unsigned number.
    if (a.is_number_unsigned() == b.is_number_unsigned()) return a == b;
    const auto& u = a.is_number_unsigned() ? a : b;
    const auto& s = a.is_number_unsigned() ? b : a;
    return s.get<std::int64_t>() >= 0 && static_cast<std::uint64_t>(s.get<std::int64_t>()) == u.get<std::uint64_t>();
  }
  // Any NaN is written null.
  const auto null_like = [](const nlohmann::ordered_json& j) {
    return j.is_null() || (j.is_number_float() && std::isnan(j.get<double>()));
  };
  if (null_like(a) || null_like(b)) return null_like(a) && null_like(b);
  if (a.type() != b.type()) return false;
  switch (a.type()) {
    case kind::object: {
      if (a.size() != b.size()) return false;
      for (auto x = a.begin(), y = b.begin(); x != a.end(); ++x, ++y)
        if (x.key() != y.key() || !same_meaning(x.value(), y.value())) return false;
      return true;
    }
    case kind::array: {
      if (a.size() != b.size()) return false;
      for (std::size_t i = 0; i < a.size(); ++i)
        if (!same_meaning(a[i], b[i])) return false;
      return true;
    }
    case kind::number_float: {
      // As serialised: -0.0 is not 0.0.
      const double x = a.get<double>(), y = b.get<double>();
      return x == y && std::signbit(x) == std::signbit(y);
    }
    default: return a == b;  // strings, booleans, null, binary
  }
}

bool means_the_same(const analysis& a, const std::string& path, const std::string& text) {
  return same_meaning(meaning_of(*analyze(path, text)), meaning_of(a));
}

std::string model_fingerprint(const std::string& path, const std::string& text) {
  return meaning_of(*analyze(path, text)).dump();
}

}  // namespace edsc::edit
