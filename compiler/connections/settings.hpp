#pragma once
// What a scanner needs to open each ConnectionN of an EDS: its kind, the
// connection path segment by segment, the electronic key, each direction's
// sizes with their header bytes, types, priorities and network connection
// parameters, the RPI and where it comes from, the configuration data and
// the whole Forward_Open. One value per connection, built on the plan that
// `verify --live --connections` opens and `sim` serves, so what edsc
// announces is what it sends. `edsc connection` renders it
// (emit/connection_text.cpp, emit/connection_json.cpp).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "connections/fields.hpp"
#include "connections/plan.hpp"

namespace edsc::connections {

// Where a direction's RPI comes from (ConnectionN field 3 or 6).
enum class rpi_source : std::uint8_t {
  number,     // the field gives microseconds
  param,      // the field names a ParamN: its default, minimum and maximum
  other,      // the field is empty; the other direction's RPI is used
  not_given,  // both fields are empty: edsc asks its own default
};

struct rpi_setting {
  rpi_source source = rpi_source::not_given;
  std::uint32_t asked_us = 0;                   // what edsc puts in the Forward_Open
  std::optional<std::uint32_t> min_us, max_us;  // from the parameter, where it gives them
  std::uint32_t param = 0;                      // N of ParamN (source param)
};

struct direction_setting {
  bool used = false;           // not a null connection
  std::uint32_t instance = 0;  // connection point (assembly instance); 0 when the EDS gives none
  std::uint32_t data_size = 0;
  bool sequence = false;  // the 16-bit sequence count of class 1 (+2 bytes)
  bool run_idle = false;  // the 32-bit run/idle header of format 4 (+4 bytes)
  std::uint8_t format = 0;
  bool fixed = false, variable = false;
  std::vector<cip::conn_type> types;  // offered by field 2
  std::vector<cip::conn_priority> priorities;
  cip::net_params asked;                // what edsc asks
  std::optional<std::uint16_t> word16;  // the Forward_Open form; none above 511 bytes
  std::uint32_t word32 = 0;             // the Large_Forward_Open form
  rpi_setting rpi;
};

// One segment of the connection path.
enum class path_role : std::uint8_t { none, configuration, output, input };
struct path_part {
  model::segment_kind kind = model::segment_kind::unknown;
  std::optional<std::uint32_t> value;  // none: the tool fills it in
  std::uint32_t param = 0;             // N when a [ParamN] gives the value (its default)
  path_role role = path_role::none;
  cip::bytes bytes;  // empty when the segment cannot be encoded
};

// One field of the configuration data: a member parameter, its place and the
// value the data holds (its default, or what --set chose).
struct config_field {
  data_field field;
  number value;
  std::string enum_text;  // the EnumN text of the value, where it has one
  bool set = false;       // chosen with --set
};

struct connection_setting {
  std::uint32_t number = 0;
  std::string name;
  span at;  // the ConnectionN entry
  model::app_kind kind;
  bool redundant_owner = false;       // field 1 bit 27
  std::vector<unsigned> classes;      // transport classes field 1 offers
  std::vector<std::string> triggers;  // "cyclic", "change of state", "application"
  std::string trigger_asked;          // the one edsc asks
  std::uint8_t transport = 0;         // the Forward_Open's transport type/trigger byte
  // Connections that produce this one's input (T->O) point: the owners a
  // listen-only connection needs one of, or that an input-only one shares.
  std::vector<std::uint32_t> owners;
  std::vector<path_part> path;
  cip::bytes app_path;
  std::optional<cip::electronic_key> key;
  cip::bytes key_bytes;
  direction_setting ot, to;
  std::uint32_t config_instance = 0;
  cip::bytes config_data;
  std::vector<config_field> config_fields;
  bool large = false;          // a size over 511: Large_Forward_Open
  cip::bytes connection_path;  // the request's path field: key, application path, configuration data segment
  cip::bytes request;          // the whole Forward_Open; serial numbers zero
  std::string cannot_express;  // why edsc cannot give the request; empty: it can
};

// `set_params`: indices into device::params whose defaults --set replaced.
[[nodiscard]] std::vector<connection_setting> describe_connections(const model::device& dev,
                                                                   const std::vector<std::uint32_t>& set_params = {});

// Words for the settings, shared by every rendering.
[[nodiscard]] std::string_view kind_words(const model::app_kind& k);
[[nodiscard]] std::string_view type_words(cip::conn_type t);
[[nodiscard]] std::string_view priority_words(cip::conn_priority p);
[[nodiscard]] std::string_view segment_words(model::segment_kind k);
[[nodiscard]] std::string_view role_words(path_role r);
[[nodiscard]] std::string_view format_words(std::uint8_t real_time_format);

}  // namespace edsc::connections
