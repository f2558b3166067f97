#pragma once
// What the network files' readers share (docs/network.md): TOML values read
// with the span of what was written, and located diagnostics for a key
// missing, of the wrong type or unknown. toml++ counts columns in code
// points; spans count bytes.
#include <array>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "diag/diagnostic.hpp"
#include "network/network.hpp"
#include "source/source_file.hpp"

namespace edsc::network {

class toml_reader {
 public:
  explicit toml_reader(const source_file& src) : src_(src) {
    const auto text = src.text();
    line_starts_.push_back(0);
    for (std::uint32_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') line_starts_.push_back(i + 1);
  }

 protected:
  std::uint32_t offset(const toml::source_position& p) const {
    if (p.line == 0 || p.line > line_starts_.size()) return src_.size();
    const auto text = src_.text();
    std::uint32_t at = line_starts_[p.line - 1];
    for (std::uint32_t col = 1; col < p.column && at < text.size() && text[at] != '\n'; ++col) {
      ++at;
      while (at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) ++at;
    }
    return at;
  }
  span region(const toml::source_region& r) const {
    const auto b = offset(r.begin);
    const auto e = offset(r.end);
    return {b, e > b ? e : b};
  }

  void add(diag_id id, span where, std::string message) {
    diags_.push_back(make_diagnostic(id, where, std::move(message)));
  }

  void expect_keys(const toml::table& t, std::initializer_list<std::string_view> known, std::string_view where = {}) {
    for (auto&& [k, v] : t) {
      bool ok = false;
      for (const auto name : known) ok = ok || k.str() == name;
      if (!ok)
        add(diag_id::net_key_unknown, region(k.source()),
            where.empty() ? fmt::format("unknown key '{}' is ignored", k.str())
                          : fmt::format("unknown key '{}' in {} is ignored", k.str(), where));
    }
  }

  const toml::node* find(const toml::table& t, std::string_view key, span& key_where) const {
    for (auto&& [k, v] : t)
      if (k.str() == key) {
        key_where = region(k.source());
        return &v;
      }
    return nullptr;
  }

  void missing(const toml::table& t, std::string_view key, std::string_view in) {
    add(diag_id::net_key_missing, region(t.source()), fmt::format("{} needs '{}'", in, key));
  }

  bool read_uint(const toml::table& t, std::string_view key, located<std::uint32_t>& out, std::int64_t max,
                 std::string_view in = {}) {
    span k;
    const auto* n = find(t, key, k);
    if (n == nullptr) {
      if (!in.empty()) missing(t, key, in);
      return false;
    }
    const auto where = region(n->source());
    const auto* i = n->as_integer();
    if (i == nullptr || i->get() < 0 || i->get() > max) {
      add(diag_id::net_key_type, where,
          i == nullptr ? fmt::format("'{}' must be an integer", key)
                       : fmt::format("'{}' = {} is outside 0-{}", key, i->get(), max));
      return false;
    }
    out = {static_cast<std::uint32_t>(i->get()), where, true};
    return true;
  }

  void read_string(const toml::table& t, std::string_view key, located<std::string>& out, bool required,
                   std::string_view in = "[network]") {
    span k;
    const auto* n = find(t, key, k);
    if (n == nullptr) {
      if (required) missing(t, key, in);
      return;
    }
    const auto* s = n->as_string();
    if (s == nullptr) return add(diag_id::net_key_type, region(n->source()), fmt::format("'{}' must be a string", key));
    // Names end up in terminals, tags and file paths: no control characters.
    for (const char c : s->get())
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
        return add(diag_id::net_key_type, region(n->source()), fmt::format("'{}' holds a control character", key));
    out = {s->get(), region(n->source()), true};
  }

  void read_length(const toml::table& t, std::string_view key, located<double>& out) {
    span k;
    const auto* n = find(t, key, k);
    if (n == nullptr) return;
    double v = -1;
    if (const auto* i = n->as_integer()) v = static_cast<double>(i->get());
    if (const auto* f = n->as_floating_point()) v = f->get();
    if (!(v >= 0 && v < 1e9))
      return add(diag_id::net_key_type, region(n->source()),
                 fmt::format("'{}' must be a length in metres (a number, 0 or more)", key));
    out = {v, region(n->source()), true};
  }

  // A string that must be one of `words`; returns its index.
  template <typename E, std::size_t N>
  void read_word(const toml::table& t, std::string_view key, const std::array<std::pair<std::string_view, E>, N>& words,
                 located<E>& out) {
    span k;
    const auto* n = find(t, key, k);
    if (n == nullptr) return;
    const auto where = region(n->source());
    std::string list;
    for (const auto& [w, e] : words) list += fmt::format("{}\"{}\"", list.empty() ? "" : ", ", w);
    const auto* s = n->as_string();
    if (s != nullptr)
      for (const auto& [w, e] : words)
        if (s->get() == w) {
          out = {e, where, true};
          return;
        }
    add(diag_id::net_key_type, where, fmt::format("'{}' must be one of {}", key, list));
  }

  const source_file& src_;
  std::vector<std::uint32_t> line_starts_;
  diagnostics diags_;
};

}  // namespace edsc::network
