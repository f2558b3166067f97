#pragma once
#include <cstdint>
#include <vector>

#include "model/value.hpp"

namespace edsc::model {

// ConnectionN field 1 (EDS_FORMAT.md §3.11.2), decoded.
struct trigger_transport {
  std::uint16_t transport_classes = 0;  // bit n = class n
  bool trigger_cyclic = false, trigger_cos = false, trigger_application = false;
  bool listen_only = false, input_only = false, exclusive_owner = false, redundant_owner = false;
  bool server = false;         // bit 31
  std::uint32_t reserved = 0;  // bits 19-23 and 28-30 as found
};

// One direction of ConnectionN field 2 (§3.11.3).
struct direction_params {
  bool fixed = false, variable = false;
  std::uint8_t real_time_format = 0;  // 0 modeless, 3 heartbeat, 4 run/idle, 5 safety
  bool type_null = false, type_multicast = false, type_p2p = false, type_reserved = false;
  bool prio_low = false, prio_high = false, prio_scheduled = false, prio_reserved = false;
};

struct connection_params {
  direction_params ot, to;
  std::uint32_t reserved = 0;  // bits 11, 15 (and the obsolete 4-7) as found
};

[[nodiscard]] trigger_transport decode_trigger(std::uint32_t v);
[[nodiscard]] connection_params decode_params(std::uint32_t v);

// What a class 1 connection point is to the device that serves it, by the
// application type bits 24-26 of field 1 (EDS_FORMAT.md §3.11.2): the one
// rule the simulator, the client and the OpENer generator share.
enum class app_type : std::uint8_t { exclusive_owner, input_only, listen_only };

struct app_kind {
  // The type named; where field 1 names several, the most an originator
  // gets from the point (an owner's outputs, then inputs with a heartbeat,
  // then inputs another connection produces); where it names none, an
  // exclusive owner, what a connection with outputs of its own is.
  app_type type = app_type::exclusive_owner;
  unsigned named = 0;       // how many of bits 24-26 are set: only 1 is unambiguous
  bool configured = false;  // the point takes configuration data (a configuration assembly)
  [[nodiscard]] bool unambiguous() const { return named == 1; }
};

[[nodiscard]] app_kind classify(const trigger_transport& tt, bool configured);

enum class connection_kind : std::uint8_t { connection, proxy, proxied };

// ConnectionN (and ProxyConnectN / ProxiedConnectN, §3.18, which hold the
// same layout for a proxied module, usually all zero). The bit fields are decoded when fields 1/2 are valid integers.
struct connection {
  connection_kind kind = connection_kind::connection;
  std::uint32_t number = 0;
  origin from;
  value trigger, params, ot_rpi, ot_size, ot_format, to_rpi, to_size, to_format, proxy_config_size, proxy_config_format,
      target_config_size, target_config_format, name, help, path, safety_async, safety_max_consumers;
  bool decoded = false;
  trigger_transport tt;
  connection_params cp;
  std::vector<value> extra;
  std::uint32_t section = none;  // [Connection Manager] or a [Connection ManagerN]
};

}  // namespace edsc::model
