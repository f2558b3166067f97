#pragma once
// What a scanner configured from the EDS sends: the Forward_Open of each
// ConnectionN (paths, sizes with their header bytes, transport, RPI, the
// electronic key from [Device], the configuration data) and the assembly
// instances whose sizes can be read. Built from the typed model; the sizes
// and instances come from the same collector `edsc header` uses.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "cip/connection_manager.hpp"
#include "facts/header_view.hpp"
#include "model/device.hpp"

namespace edsc::connections {

// The RPI edsc asks where a ConnectionN leaves both RPI fields empty: the
// EDS sets no interval and leaves it to the tool (EDS_FORMAT.md §3.11.1).
inline constexpr std::uint32_t default_rpi_us = 10'000;

struct connection_plan {
  const model::connection* conn = nullptr;
  emit::eip_connection_facts facts;
  std::uint32_t ot_rpi_us = 0, to_rpi_us = 0;
  bool ot_run_idle = false, to_run_idle = false;
  model::app_kind kind;               // the one rule (model::classify) over field 1 and the configuration
  cip::forward_open_request request;  // serials left to the caller
  cip::bytes app_path;                // without key and data (for Forward_Close)
  cip::bytes config_data;             // the data segment's bytes: member parameters' defaults
  std::string not_openable;           // why edsc does not open it; empty: it does
  bool needs_owner = false;           // listen-only: the request is whole, but opens only beside an owner
};

// The key a scanner builds from [Device]; nullopt when a field is missing.
[[nodiscard]] std::optional<cip::electronic_key> key_from_device(const model::device& dev);
[[nodiscard]] std::vector<connection_plan> plan_connections(const model::device& dev);

// An assembly whose instance is known: from its own class 4 path, or from a
// connection path whose size/format fields name it.
struct assembly_target {
  const model::assembly* assem = nullptr;
  std::uint32_t instance = 0;
  // Bytes; none when the EDS gives no size (an empty size field and no
  // member of any bits), which is not a size of 0.
  std::optional<std::uint32_t> eds_size;
  span named_at;  // the path that gives the instance (the assembly's own, or a connection's)
};
[[nodiscard]] std::vector<assembly_target> plan_assemblies(const model::device& dev);

// One segment of a connection path as bytes, or why edsc cannot send it.
[[nodiscard]] result<cip::bytes, std::string> encode_segment(const model::device& dev, const model::epath_segment& s);
// The number a segment carries, a [ParamN] placeholder at its default; none
// when the tool fills it in (`SLOT`) or the parameter has no number.
[[nodiscard]] std::optional<std::uint32_t> segment_value(const model::device& dev, const model::epath_segment& s);

// The connection path field as bytes, [ParamN] placeholders at their
// defaults (what a scanner sends), or the reason it cannot be encoded.
// The simulator reads listen-only paths with it too, which plans leave empty.
[[nodiscard]] result<cip::bytes, std::string> encode_connection_path(const model::device& dev, const model::epath& p);

// The data size plus the 16-bit sequence count and, where the format has
// one, the 32-bit run/idle header (as OpENer counts them, cipioconnection.c).
[[nodiscard]] std::uint16_t network_size(std::uint32_t data, bool run_idle);

}  // namespace edsc::connections
