#pragma once
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "model/assembly.hpp"
#include "model/capacity.hpp"
#include "model/connection.hpp"
#include "model/epath.hpp"
#include "model/identity.hpp"
#include "model/io_info.hpp"
#include "model/params.hpp"
#include "model/port.hpp"
#include "model/value.hpp"
#include "schema/schema.hpp"

namespace edsc::model {

// Key -> index, for the reference targets: one flat open-addressing table
// (linear probing, at most half full) instead of a node per entry, since a
// large file has a hundred thousand targets and is looked up once per
// reference. Keys are device::key values, which never equal `empty_key`.
class ref_index {
 public:
  // Forgets everything; room for `expected` keys before the first growth.
  void reset(std::size_t expected) {
    std::size_t cap = 64;
    while (cap < expected * 2) cap *= 2;
    slots_.assign(cap, slot{});
    size_ = 0;
  }
  // Adds key -> value unless the key is present (the first one wins).
  void try_emplace(std::uint64_t key, std::uint32_t value) {
    if ((size_ + 1) * 2 > slots_.size()) grow();
    slot& s = slots_[position(key)];
    if (s.key == key) return;
    s = {key, value};
    ++size_;
  }
  [[nodiscard]] std::uint32_t find(std::uint64_t key) const {
    if (slots_.empty()) return 0xFFFFFFFFu;
    const slot& s = slots_[position(key)];
    return s.key == key ? s.value : 0xFFFFFFFFu;
  }
  [[nodiscard]] std::size_t size() const { return size_; }

 private:
  static constexpr std::uint64_t empty_key = ~std::uint64_t{0};
  struct slot {
    std::uint64_t key = empty_key;
    std::uint32_t value = 0;
  };
  // The slot holding `key`, or the empty slot where it would go.
  [[nodiscard]] std::size_t position(std::uint64_t key) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask;
    while (slots_[i].key != key && slots_[i].key != empty_key) i = (i + 1) & mask;
    return i;
  }
  void grow() {
    std::vector<slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 64 : old.size() * 2, slot{});
    for (const slot& s : old)
      if (s.key != empty_key) slots_[position(s.key)] = s;
  }
  std::vector<slot> slots_;
  std::size_t size_ = 0;
};

}  // namespace edsc::model

namespace edsc::cst {
struct tree;
}

namespace edsc::model {

// Object-class sections (§3.15) and the common keywords of [Assembly],
// [Connection Manager] and [Port].
struct object_class {
  std::uint32_t section = none;
  std::string_view name;         // as written
  std::uint32_t class_code = 0;  // from the section name; 0 when unknown
  std::vector<setting> settings;
};

// Every section in file order, with what the schema made of it.
struct section_info {
  std::uint32_t section = none;
  std::string_view name;                       // as written
  const schema::section_desc* desc = nullptr;  // nullptr: unknown
  bool vendor_specific = false;                // `1_LEOSUPPORT`
  bool canonical_spelling = true;              // false for `[variant_io_info]`
};

enum class raw_reason : std::uint8_t {
  unknown_section,  // any entry of a section the schema does not know
  vendor_section,   // any entry of a vendor-specific section (`[1_LEOSUPPORT]`)
  unknown_keyword,  // a keyword the section's schema does not know
  vendor_keyword,   // `1_RSNetWorx_DNetTool` inside a standard section
  duplicate,        // a single-valued keyword written again (the first one is in the model)
  extra_fields,     // a single-valued keyword with more fields than its layout
  outside_section,  // an entry before the first section header
};

// An entry outside the schema (or beyond what it can hold). Kept whole, with
// its fields typed by the schema when known, else by syntax only.
struct raw_entry {
  std::uint32_t entry = none;
  std::uint32_t section = none;  // CST section index
  std::string_view keyword;      // as written
  raw_reason reason = raw_reason::unknown_keyword;
  std::vector<value> fields;
};

// The typed model of one EDS file. Text views point into the source_file
// (which must outlive the model) or into `strings`.
struct device {
  const cst::tree* tree = nullptr;
  bool incomplete = false;  // lowering stopped early (out of memory)

  file_info file;
  device_info identity;
  classification classes;
  io_info io, variant_io;
  param_class parameter_class;
  std::vector<param> params;  // ParamN and proxy variants, in file order
  std::vector<param_enum> enums;
  std::vector<enum_par> enum_pars;
  std::vector<group> groups;
  std::vector<assembly> assemblies;  // AssemN, AssemExaN and proxy variants
  std::vector<variant> variants;
  std::vector<array> arrays;
  std::vector<connection> connections;
  std::vector<connection> proxy_connections;  // ProxyConnectN / ProxiedConnectN, apart: no rule reads them as real
  std::vector<setting> connection_settings;   // PITNS, safety keywords
  std::vector<port> ports;
  capacity cap;
  modular mod;
  std::vector<object_class> objects;
  std::vector<section_info> sections;
  std::vector<raw_entry> unknown;

  std::vector<epath> paths;         // value::path indexes here
  std::deque<std::string> strings;  // decoded text that is not a plain view of the source

  // Reference targets: (kind, N) -> index in the vector holding that kind.
  // The first definition wins when a keyword is duplicated.
  ref_index index;

  [[nodiscard]] std::uint32_t find(schema::ref_kind k, std::uint32_t n) const { return index.find(key(k, n)); }
  [[nodiscard]] const param* find_param(std::uint32_t n) const {
    const auto i = find(schema::ref_kind::param, n);
    return i == none ? nullptr : &params[i];
  }
  [[nodiscard]] const epath* path_of(const value& v) const {
    return v.kind == value_kind::epath ? &paths[v.path] : nullptr;
  }
  // The field exactly as written (strings: all pieces, quotes included).
  [[nodiscard]] std::string_view raw(const value& v) const;
  [[nodiscard]] static std::uint64_t key(schema::ref_kind k, std::uint32_t n) {
    return (static_cast<std::uint64_t>(k) << 32) | n;
  }
};

}  // namespace edsc::model
