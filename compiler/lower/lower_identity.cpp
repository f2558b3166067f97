// [File], [Device] and [Device Classification] (EDS_FORMAT.md §3.1-3.3).
#include "lower/context.hpp"
#include "model/decode.hpp"

namespace edsc::lowering {

using model::value;
using schema::entry_id;

namespace {

value* file_slot(model::file_info& f, entry_id id) {
  switch (id) {
    case entry_id::desc_text: return &f.desc_text;
    case entry_id::create_date: return &f.create_date;
    case entry_id::create_time: return &f.create_time;
    case entry_id::mod_date: return &f.mod_date;
    case entry_id::mod_time: return &f.mod_time;
    case entry_id::file_revision: return &f.revision;
    case entry_id::home_url: return &f.home_url;
    case entry_id::exclude: return &f.exclude;
    case entry_id::eds_file_crc: return &f.eds_file_crc;
    default: return nullptr;
  }
}

value* device_slot(model::device_info& d, entry_id id) {
  switch (id) {
    case entry_id::vend_code: return &d.vend_code;
    case entry_id::vend_name: return &d.vend_name;
    case entry_id::prod_type: return &d.prod_type;
    case entry_id::prod_type_str: return &d.prod_type_str;
    case entry_id::prod_code: return &d.prod_code;
    case entry_id::maj_rev: return &d.maj_rev;
    case entry_id::min_rev: return &d.min_rev;
    case entry_id::prod_name: return &d.prod_name;
    case entry_id::catalog: return &d.catalog;
    case entry_id::icon: return &d.icon;
    case entry_id::icon_contents: return &d.icon_contents;
    case entry_id::application_profiles_assembly: return &d.application_profiles_assembly;
    default: return nullptr;
  }
}

// IconContents is a run of literals holding Base64; decode the joined text.
void decode_icon(model::device_info& d) {
  auto& v = d.icon_contents;
  d.icon_data.clear();
  if (!v.ok()) return;
  if (!model::decode::base64(v.text, d.icon_data)) {
    d.icon_data.clear();
    v.state = model::value_state::invalid;
    v.why = model::invalid_reason::bad_base64;
  }
}

}  // namespace

void lower_identity(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  const auto& k = *m.desc;
  auto& dev = c.dev;
  // A keyword written twice keeps its first value in the slot; the second
  // is kept as an unknown-duplicate raw entry so nothing is lost.
  auto store = [&](value* slot) {
    if (slot->from.entry != model::none) {
      c.keep_raw(entry, model::raw_reason::duplicate, &k);
      return;
    }
    *slot = c.field(entry, 0, schema::field_at(k, 0));
    if (c.field_count(entry) > 1)  // one-field keywords: extra fields are kept raw
      c.keep_raw(entry, model::raw_reason::extra_fields, &k);
  };
  if (auto* s = file_slot(dev.file, k.id)) {
    store(s);
  } else if (auto* d = device_slot(dev.identity, k.id)) {
    store(d);
    if (k.id == entry_id::icon_contents) decode_icon(dev.identity);
  } else if (k.id == entry_id::class_n) {
    auto fields = c.all_fields(entry, &k);
    model::class_entry ce;
    ce.number = m.number;
    ce.network = fields.empty() ? c.field(entry, 0, &k.fields[0]) : fields.front();
    if (fields.size() > 1) ce.more.assign(fields.begin() + 1, fields.end());
    dev.classes.classes.push_back(std::move(ce));
  }
}

}  // namespace edsc::lowering
