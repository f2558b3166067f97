#pragma once
// Internal to lowering: the state shared by the per-family lowerers.
#include <array>
#include <cstdint>
#include <vector>

#include "cst/cst.hpp"
#include "model/device.hpp"
#include "schema/cip_types.hpp"
#include "schema/schema.hpp"

namespace edsc::lowering {

struct context {
  const cst::tree& tree;
  model::device& dev;
  std::uint32_t section = model::none;  // CST index of the section being lowered
  // EnumN entries, lowered once all ParamN are known; their keyword match is
  // kept so that it is not looked up again.
  struct deferred_enum {
    std::uint32_t entry;
    schema::keyword_match match;
  };
  std::vector<deferred_enum> deferred_enums;

  [[nodiscard]] std::uint32_t field_count(std::uint32_t entry) const { return tree.entries[entry].fields_count; }
  [[nodiscard]] model::origin origin_of(std::uint32_t entry, std::uint32_t field) const;

  // Field `index` of `entry` typed by `desc` (nullptr: typed by syntax only).
  // Fields past the end of the entry come back absent, pointing at its end.
  [[nodiscard]] model::value field(std::uint32_t entry, std::uint32_t index, const schema::field_desc* desc) {
    model::value v;
    field_into(v, entry, index, desc);
    return v;
  }
  // The same, lowered in place into `v`, which must be as a default-constructed
  // value is (only the members the field sets are written): this runs once per
  // field of the file, and the model's slots are fresh when they are filled.
  void field_into(model::value& v, std::uint32_t entry, std::uint32_t index, const schema::field_desc* desc);
  // A value typed by a CIP type (ParamN min/max/default, EnumN values).
  // Without a type it is flagged unknown_type, unless `untyped` says the
  // format leaves the type out on purpose (proxy parameters, §3.18).
  [[nodiscard]] model::value typed(std::uint32_t entry, std::uint32_t index, const schema::cip_type_info* type,
                                   bool untyped = false) {
    model::value v;
    typed_into(v, entry, index, type, untyped);
    return v;
  }
  void typed_into(model::value& v, std::uint32_t entry, std::uint32_t index, const schema::cip_type_info* type,
                  bool untyped = false);

  // Fills the named slots [from, to) of a freshly constructed `obj` from the
  // entry's fields in schema order.
  template <class T, std::size_t N>
  void fill_slots(std::uint32_t entry, const schema::keyword_desc& k, T& obj,
                  const std::array<model::value T::*, N>& slots, std::uint32_t from, std::uint32_t to,
                  const schema::cip_type_info* typed_as = nullptr, bool untyped = false) {
    for (std::uint32_t i = from; i < to; ++i) {
      // The fixed fields inline; field_at for the repeating tail.
      const auto* d = i < k.fields.size() ? &k.fields[i] : schema::field_at(k, i);
      if (d && d->type == schema::value_type::typed)
        typed_into(obj.*slots[i], entry, i, typed_as, untyped);
      else
        field_into(obj.*slots[i], entry, i, d);
    }
  }
  // Fields beyond the N slots go to `extra`.
  void fill_extra(std::uint32_t entry, const schema::keyword_desc& k, std::uint32_t from,
                  std::vector<model::value>& extra) {
    for (std::uint32_t i = from; i < field_count(entry); ++i)
      field_into(extra.emplace_back(), entry, i, schema::field_at(k, i));
  }
  // Fills all the named slots of a freshly constructed `obj`; fields beyond
  // the slots go to `extra` (when given).
  template <class T, std::size_t N>
  void fill(std::uint32_t entry, const schema::keyword_desc& k, T& obj, const std::array<model::value T::*, N>& slots,
            std::vector<model::value>* extra, const schema::cip_type_info* typed_as = nullptr, bool untyped = false) {
    fill_slots(entry, k, obj, slots, 0, N, typed_as, untyped);
    if (extra) fill_extra(entry, k, N, *extra);
  }

  // Lowers an entity straight into a new element of `list`: entities hold
  // dozens of values, and built in a local they would be written twice. On
  // an exception (out of memory) the half-lowered element is taken out again.
  template <class T, class F>
  static void lower_into(std::vector<T>& list, F&& lower) {
    auto& obj = list.emplace_back();
    try {
      lower(obj);
    } catch (...) {
      list.pop_back();
      throw;
    }
  }

  // Keeps a whole entry in device::unknown.
  void keep_raw(std::uint32_t entry, model::raw_reason why, const schema::keyword_desc* k = nullptr) {
    dev.unknown.push_back(
        {entry, tree.entries[entry].section, tree.text(tree.entries[entry].keyword), why, all_fields(entry, k)});
  }

  // All fields of the entry, typed by the keyword's descriptors.
  [[nodiscard]] std::vector<model::value> all_fields(std::uint32_t entry, const schema::keyword_desc* k);
};

// Per-family lowerers: one call per entry the schema recognised.
void lower_identity(context& c, std::uint32_t entry, const schema::keyword_match& m);
void lower_io_info(context& c, model::io_info& io, std::uint32_t entry, const schema::keyword_match& m);
void lower_params(context& c, std::uint32_t entry, const schema::keyword_match& m);
void lower_enum(context& c, std::uint32_t entry, const schema::keyword_match& m);
void lower_assembly(context& c, std::uint32_t entry, const schema::keyword_match& m);
void lower_connection(context& c, std::uint32_t entry, const schema::keyword_match& m);
void lower_other(context& c, std::uint32_t entry, const schema::keyword_match& m);  // port, capacity, modular
void lower_object_setting(context& c, std::uint32_t entry, const schema::keyword_match& m);
[[nodiscard]] model::setting make_setting(context& c, std::uint32_t entry, const schema::keyword_match& m);

// Second pass: reference targets, networks.
void build_index(model::device& dev);
void resolve_references(model::device& dev);
void detect_networks(model::device& dev);

}  // namespace edsc::lowering
