#pragma once
// Internal to the simulator: a CIP object as a table (its class id, the
// attributes of its class and of its instances, its other services) and the
// one generic server of Get_Attribute_Single, Get_Attribute_All and
// Set_Attribute_Single over such tables. How to add an object: objects.cpp.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "cip/request.hpp"
#include "sim/state.hpp"

namespace edsc::sim {

// What a request reaching an object carries, and what it may act on.
struct object_call {
  state& s;
  const link& l;
  const cip::request& q;
  const cip::object_address& a;
  clock::time_point now;
};

// Appends the attribute of `instance` (0: the class) in its wire encoding.
using attribute_getter = std::function<void(const state&, std::uint32_t instance, cip::bytes&)>;

struct attribute {
  attribute(std::uint32_t n, attribute_getter g, bool all = true) : number(n), get(std::move(g)), in_all(all) {}

  std::uint32_t number = 0;
  attribute_getter get;
  bool in_all = true;  // part of what Get_Attribute_All returns
  // Settable: `set` stores data already `size` bytes long and returns the
  // status (a value out of its limits: invalid_attribute_value); null: read
  // only. `settable` says when an instance's attribute is read only for now
  // (an input assembly, a read-only parameter); null: always settable.
  std::function<cip::general_status(state&, std::uint32_t instance, cip::byte_view data)> set;
  std::function<bool(const state&, std::uint32_t instance)> settable;
  std::function<std::size_t(const state&, std::uint32_t instance)> size;
};

// The class (instance 0) or its instances.
struct attribute_level {
  std::vector<attribute> attributes;  // in number order: Get_Attribute_All returns them so
  bool get_all = false;               // Get_Attribute_All served
  bool set = false;                   // Set_Attribute_Single served (read-only attributes refused as not settable)
};

struct object_service {
  cip::service code{};
  std::function<cip::bytes(object_call&)> serve;
};

struct object_table {
  std::uint16_t class_id = 0;
  // Whether the device has the object at all; when not, every request is path_destination_unknown.
  std::function<bool(const state&)> present;
  // Attributes of the class; none: instance 0 is looked up as any other instance.
  std::optional<attribute_level> class_level;
  std::function<bool(const state&, std::uint32_t instance)> exists;
  cip::general_status missing = cip::general_status::path_destination_unknown;  // an instance that does not exist
  attribute_level instance_level;
  // Services other than the three generic ones, served to the instances.
  std::vector<object_service> services;
  bool attribute_paths = true;  // false: a path naming an attribute does not reach the object
};

// The reply of `t` to `c.q`.
[[nodiscard]] cip::bytes serve(const object_table& t, object_call& c);

// Encoders for the usual class attributes.
[[nodiscard]] attribute constant_u16(std::uint32_t number, std::uint16_t value);

}  // namespace edsc::sim
