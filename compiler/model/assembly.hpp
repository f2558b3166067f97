#pragma once
#include <cstdint>
#include <vector>

#include "model/value.hpp"

namespace edsc::model {

enum class assembly_kind : std::uint8_t {
  assem,
  assem_exa,
  proxy_assem,
  proxied_assem,
  proxy_assem_exa,
  proxied_assem_exa,
};

// One `size, reference` pair. `size` is in bits; `ref` is a reference,
// an EPATH, an integer or empty (padding).
struct assembly_member {
  value size, ref;
};

// AssemN / AssemExaN / Proxy* (EDS_FORMAT.md §3.10.1). `size` is in bytes,
// or (AssemExa) a ParamN reference.
struct assembly {
  assembly_kind kind = assembly_kind::assem;
  std::uint32_t number = 0;
  origin from;
  value name, path, size, descriptor, reserved1, reserved2;
  std::vector<assembly_member> members;
  value dangling;  // a member size without its reference field (odd count)
};

enum class variant_kind : std::uint8_t { variant, variant_exa, bitstring_variant };

// VariantN / VariantExaN: (selection, target) pairs; BitStringVariantN:
// (bit, when_set, when_clear) triples, with `target` = when_set.
struct variant_choice {
  value selection, target, when_clear;
};

struct variant {
  variant_kind kind = variant_kind::variant;
  std::uint32_t number = 0;
  origin from;
  value name, help, reserved1, reserved2, reserved3, selector;
  std::vector<variant_choice> choices;
  std::vector<value> incomplete;  // fields of a last, partial group
};

// ArrayN (§3.10.2, layout from one library only).
struct array {
  std::uint32_t number = 0;
  origin from;
  value name, path, descriptor, help, reserved1, reserved2, reserved3, element_size, element_type, dimensions;
  std::vector<value> extents;
};

}  // namespace edsc::model
