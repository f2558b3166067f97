#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

#include "model/value.hpp"

namespace edsc::model {

// A keyword with its fields, for entries whose meaning is "a named setting"
// ([Capacity] Max*, object-class keywords, safety keywords, RackN).
struct setting {
  std::string_view keyword;    // as written
  std::string_view canonical;  // schema spelling with N for numbered keywords' stem
  std::uint32_t number = 0;    // N of numbered keywords
  origin from;
  std::vector<value> fields;
  [[nodiscard]] const value* first() const { return fields.empty() ? nullptr : &fields[0]; }
};

// TSpecN (EDS_FORMAT.md §3.13).
struct tspec {
  std::uint32_t number = 0;
  origin from;
  value direction, size, rate;
  std::vector<value> extra;
};

struct capacity {
  std::uint32_t section = none;
  std::vector<tspec> tspecs;
  std::vector<setting> settings;  // ConnOverhead, MaxIOConnections, ...
  [[nodiscard]] const setting* find(std::string_view canonical) const;
};

// RackN in a module's [Modular] (EDS_FORMAT.md §3.18): the identity of a
// chassis the module fits, three reserved fields, then the slots it may take.
struct rack {
  std::uint32_t number = 0;
  origin from;
  value vendor, product_type, product_code, major_revision, minor_revision, reserved1, reserved2, reserved3;
  std::vector<value> slots;
};

// [Modular] (§3.14 for chassis files, §3.18 for module files).
struct modular {
  std::uint32_t section = none;
  value define_slots_in_rack, slot_display_rule, width, external_id;
  std::vector<rack> racks;
};

}  // namespace edsc::model
