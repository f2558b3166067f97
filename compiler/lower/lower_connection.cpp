// [Connection Manager] (EDS_FORMAT.md §3.11).
#include "lower/context.hpp"
#include "model/slots.hpp"

namespace edsc::lowering {

using schema::entry_id;

void lower_connection(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  const auto& k = *m.desc;
  switch (k.id) {
    case entry_id::connection_n:
    case entry_id::proxy_connection_n:
    case entry_id::proxied_connection_n: {
      const auto kind = k.id == entry_id::proxy_connection_n     ? model::connection_kind::proxy
                        : k.id == entry_id::proxied_connection_n ? model::connection_kind::proxied
                                                                 : model::connection_kind::connection;
      auto& list = kind == model::connection_kind::connection ? c.dev.connections : c.dev.proxy_connections;
      context::lower_into(list, [&](model::connection& cn) {
        cn.kind = kind;
        cn.number = m.number;
        cn.section = c.section;
        cn.from = c.origin_of(entry, model::none);
        c.fill(entry, k, cn, model::slots::connection, &cn.extra);
        // The bit fields are only meaningful when both masks are real DWORDs.
        if (cn.trigger.is_integer() && cn.params.is_integer()) {
          cn.decoded = true;
          cn.tt = model::decode_trigger(static_cast<std::uint32_t>(cn.trigger.magnitude));
          cn.cp = model::decode_params(static_cast<std::uint32_t>(cn.params.magnitude));
        }
      });
      return;
    }
    case entry_id::pitns:
    case entry_id::pitns_usec:
    case entry_id::safety_setting:
    case entry_id::default_safety_connections: c.dev.connection_settings.push_back(make_setting(c, entry, m)); return;
    default: return lower_object_setting(c, entry, m);
  }
}

}  // namespace edsc::lowering
