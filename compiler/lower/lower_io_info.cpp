// [IO_Info] and [Variant_IO_Info] (EDS_FORMAT.md §3.4-3.5).
#include "lower/context.hpp"
#include "model/slots.hpp"

namespace edsc::lowering {

using schema::entry_id;

void lower_io_info(context& c, model::io_info& io, std::uint32_t entry, const schema::keyword_match& m) {
  const auto& k = *m.desc;
  switch (k.id) {
    case entry_id::io_default:
      if (io.default_from.entry != model::none) {
        c.keep_raw(entry, model::raw_reason::duplicate, &k);
        return;
      }
      io.default_from = c.origin_of(entry, model::none);
      io.default_mask = c.field(entry, 0, schema::field_at(k, 0));
      if (c.field_count(entry) > 1) c.keep_raw(entry, model::raw_reason::extra_fields, &k);
      return;
    case entry_id::poll_info:
    case entry_id::strobe_info:
    case entry_id::cos_info:
    case entry_id::cyclic_info: {
      model::io_connection_info info;
      info.type = static_cast<model::io_connection>(static_cast<int>(k.id) - static_cast<int>(entry_id::poll_info));
      info.from = c.origin_of(entry, model::none);
      c.fill(entry, k, info, model::slots::io_conn, nullptr);
      if (c.field_count(entry) > 3) c.keep_raw(entry, model::raw_reason::extra_fields, &k);
      io.connections.push_back(info);
      return;
    }
    case entry_id::input_n:
    case entry_id::output_n:
    case entry_id::input_exa_n:
    case entry_id::output_exa_n: {
      model::io_data d;
      d.number = m.number;
      d.output = k.id == entry_id::output_n || k.id == entry_id::output_exa_n;
      d.from = c.origin_of(entry, model::none);
      c.fill(entry, k, d, model::slots::io, &d.extra);
      const bool exa = k.id == entry_id::input_exa_n || k.id == entry_id::output_exa_n;
      auto& list = exa ? (d.output ? io.output_exas : io.input_exas) : (d.output ? io.outputs : io.inputs);
      list.push_back(std::move(d));
      return;
    }
    default: c.keep_raw(entry, model::raw_reason::unknown_keyword, &k); return;
  }
}

}  // namespace edsc::lowering
