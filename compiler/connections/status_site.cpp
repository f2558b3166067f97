// Connection Manager statuses against one ConnectionN: each family of status
// names its field of the EDS (EDS_FORMAT.md §3.11 numbers them as
// cip/codes.def does) and the numbers there (status_site.hpp).
#include "connections/status_site.hpp"

#include <fmt/format.h>

#include "connections/summary.hpp"

namespace edsc::connections {

namespace {

using ext = cip::extended_status;

// What one status is read against: the connection's entry and settings.
struct site_context {
  const model::device& dev;
  const source_file* src;  // none: no line numbers in the words
  const model::connection& c;
  const connection_setting& s;
  std::optional<std::uint16_t> accepted;
};

bool written(const model::value& v) { return v.present() && !v.from.where.empty(); }

status_site at_field(const site_context& x, const model::value& v, int number, std::string_view what) {
  if (written(v)) return {v.from.where, fmt::format("Connection{} field {} ({})", x.s.number, number, what), {}};
  return {x.c.from.where, fmt::format("Connection{}, whose field {} ({}) is empty", x.s.number, number, what), {}};
}

// "32 + 2 sequence + 4 run/idle = 38": a direction's size as the Forward_Open counts it.
std::string sum_words(const direction_setting& d) {
  if (!d.used) return "none (a null connection)";
  std::string out = fmt::format("{}", d.data_size);
  if (d.sequence) out += " + 2 sequence";
  if (d.run_idle) out += " + 4 run/idle";
  return out + fmt::format(" = {}", d.asked.size);
}

// 0x0127, 0x0128: the size field, else the format field whose assembly gives it.
status_site size_site(const site_context& x, bool ot) {
  const auto& d = ot ? x.s.ot : x.s.to;
  const auto* dir = ot ? "O->T" : "T->O";
  const auto& size = ot ? x.c.ot_size : x.c.to_size;
  auto out = written(size) ? at_field(x, size, ot ? 4 : 7, fmt::format("{} size", dir))
                           : at_field(x, ot ? x.c.ot_format : x.c.to_format, ot ? 5 : 8,
                                      fmt::format("{} format, the assembly whose size it is", dir));
  if (!x.accepted) {
    out.words = fmt::format("the EDS says {} bytes {}", sum_words(d), dir);
    return out;
  }
  const unsigned accepted = *x.accepted, headers = (d.sequence ? 2u : 0u) + (d.run_idle ? 4u : 0u);
  out.words = fmt::format("the device accepts {} bytes {}; the EDS says {}", accepted, dir, sum_words(d));
  if (accepted == d.asked.size)
    out.words += " (the same size: look at the fixed and variable bits of field 2)";
  else if (d.run_idle && accepted + 4 == d.asked.size)
    out.words += " (4 fewer: the device counts no run/idle header; see the real-time format of field 2)";
  else if (!d.run_idle && d.data_size > 0 && accepted == d.asked.size + 4u)
    out.words += " (4 more: the device wants a run/idle header; see the real-time format of field 2)";
  else if (accepted >= headers)
    out.words += fmt::format(" (with the same headers, the device wants {} data bytes)", accepted - headers);
  return out;
}

// 0x0130, 0x0131: the assembly a direction carries and the real-time
// format field 2 gives it.
status_site format_site(const site_context& x, bool ot) {
  const auto& d = ot ? x.s.ot : x.s.to;
  const auto* dir = ot ? "O->T" : "T->O";
  auto out = at_field(x, ot ? x.c.ot_format : x.c.to_format, ot ? 5 : 8, fmt::format("{} format", dir));
  out.words = d.used ? fmt::format("the EDS gives {} {} data bytes in the {} format (bits {} of field 2): {} bytes",
                                   dir, d.data_size, format_words(d.format), ot ? "8-10" : "12-14", sum_words(d))
                     : fmt::format("the EDS gives {} no data: a null connection", dir);
  return out;
}

// 0x0126: the configuration size, in the data segment's 16-bit words.
status_site config_size_site(const site_context& x) {
  auto out = written(x.c.target_config_size) ? at_field(x, x.c.target_config_size, 11, "configuration size")
             : written(x.c.target_config_format)
                 ? at_field(x, x.c.target_config_format, 12, "configuration format, the assembly whose size it is")
                 : at_field(x, x.c.path, 15, "connection path");
  const auto eds = x.s.config_instance == 0
                       ? std::string("the EDS gives no configuration data")
                       : fmt::format("the EDS gives {} bytes of configuration data for instance {}",
                                     x.s.config_data.size(), x.s.config_instance);
  out.words = x.accepted ? fmt::format(
                               "the device accepts {0}: {1} bytes in the 16-bit words of the data segment "
                               "(as edsc sim counts), {0} if it counts bytes; {2}",
                               *x.accepted, 2u * *x.accepted, eds)
                         : eds;
  return out;
}

// A limit of an RPI parameter, with the line of the parameter.
std::string rpi_side(const site_context& x, const rpi_setting& r, std::string_view other) {
  auto out = rpi_words(r, other);
  if (r.source != rpi_source::param) return out;
  if (const auto* p = x.dev.find_param(r.param); p != nullptr && x.src != nullptr)
    out += fmt::format(", Param{} at line {}", r.param, x.src->position(p->from.where.begin).line);
  return out;
}

// 0x0111, 0x0112: the RPI fields and the parameter that bounds them.
status_site rpi_site(const site_context& x) {
  auto out = written(x.c.ot_rpi) || !written(x.c.to_rpi) ? at_field(x, x.c.ot_rpi, 3, "O->T RPI")
                                                         : at_field(x, x.c.to_rpi, 6, "T->O RPI");
  const auto &ot = x.s.ot.rpi, &to = x.s.to.rpi;
  const bool one =
      ot.source == to.source && ot.param == to.param && ot.asked_us == to.asked_us && ot.source != rpi_source::other;
  out.words = one ? fmt::format("a scanner configured from the EDS asks {} both ways: {}", interval_words(ot.asked_us),
                                rpi_side(x, ot, "T->O"))
                  : fmt::format("a scanner configured from the EDS asks O->T {} and T->O {}; O->T {}; T->O {}",
                                interval_words(ot.asked_us), interval_words(to.asked_us), rpi_side(x, ot, "T->O"),
                                rpi_side(x, to, "O->T"));
  return out;
}

// 0x0114-0x0116: the electronic key, from [Device].
status_site key_site(const site_context& x, ext status) {
  const auto& id = x.dev.identity;
  const auto& field = status == ext::vendor_or_product_code_mismatch ? id.prod_code
                      : status == ext::device_type_mismatch          ? id.prod_type
                                                                     : id.maj_rev;
  const auto* name = status == ext::vendor_or_product_code_mismatch ? "ProdCode"
                     : status == ext::device_type_mismatch          ? "ProdType"
                                                                    : "MajRev";
  status_site out{written(field) ? field.from.where : x.c.from.where, fmt::format("[Device] {}", name), {}};
  if (!x.s.key) {
    out.words = "[Device] lacks a number the key needs, so a scanner configured from the EDS sends no key";
    return out;
  }
  const auto& k = *x.s.key;
  if (status == ext::vendor_or_product_code_mismatch)
    out.words =
        fmt::format("the key asks vendor {} (VendCode) and product code {} (ProdCode)", k.vendor, k.product_code);
  else if (status == ext::device_type_mismatch)
    out.words = fmt::format("the key asks device type {} (ProdType)", k.device_type);
  else
    out.words = k.compatible ? fmt::format(
                                   "the key asks revision {0}.{1}, compatible: a device of major revision "
                                   "{0} with minor revision {1} or newer (MajRev, MinRev)",
                                   k.major, k.minor)
                             : fmt::format("the key asks exactly revision {}.{} (MajRev, MinRev)", k.major, k.minor);
  return out;
}

// "configuration instance 151 (24 97)": the segment of the path with `role`.
std::string part_words(const connection_setting& s, path_role role, std::string_view what) {
  for (const auto& p : s.path) {
    if (p.role != role) continue;
    auto out = fmt::format("{} {}", what, p.value ? fmt::format("{}", *p.value) : std::string("(the tool's)"));
    if (p.param != 0) out += fmt::format(", Param{}'s default", p.param);
    return out + fmt::format(" ({})", hex_bytes(p.bytes));
  }
  return fmt::format("no {}", what);
}

// 0x0117, 0x0118, 0x0129-0x012B, 0x012F: the parts of the connection path.
status_site path_site(const site_context& x, ext status) {
  auto out = at_field(x, x.c.path, 15, "connection path");
  const auto cfg = part_words(x.s, path_role::configuration, "configuration instance");
  const auto o = part_words(x.s, path_role::output, "O->T connection point");
  const auto i = part_words(x.s, path_role::input, "T->O connection point");
  switch (status) {
    case ext::invalid_configuration_path:
    case ext::invalid_configuration_application_path:
      out.words = fmt::format("the path names {}; {}", cfg,
                              x.s.config_instance == 0
                                  ? std::string("the EDS gives no configuration data")
                                  : fmt::format("{} bytes of configuration data go with it", x.s.config_data.size()));
      break;
    case ext::invalid_consuming_path: out.words = fmt::format("the path names {}: the output assembly", o); break;
    case ext::invalid_producing_path: out.words = fmt::format("the path names {}: the input assembly", i); break;
    default: out.words = fmt::format("the path names {}, {}, {}", cfg, o, i); break;
  }
  return out;
}

// 0x0119: a listen-only connection and the owners it needs.
status_site listen_site(const site_context& x) {
  auto out = at_field(x, x.c.trigger, 1, "trigger and transport");
  const auto w = summarize(x.s);
  out.words = x.s.kind.type == model::app_type::listen_only
                  ? fmt::format("Connection{} is listen only and {} {}", x.s.number, w.owner_label, w.owners)
                  : fmt::format(
                        "Connection{} is {}, not listen only: the status answers a listen-only connection "
                        "opened while none of its owners was",
                        x.s.number, w.kind);
  return out;
}

// 0x0103, 0x011C-0x011E: field 1.
status_site transport_site(const site_context& x) {
  auto out = at_field(x, x.c.trigger, 1, "trigger and transport");
  out.words = fmt::format("a scanner configured from the EDS asks {}, transport byte 0x{:02X}",
                          summarize(x.s).transport, x.s.transport);
  return out;
}

// 0x0108, 0x0109, 0x011F-0x0124, 0x0132: field 2, for the direction the status names.
status_site params_site(const site_context& x, ext status) {
  auto out = at_field(x, x.c.params, 2, "connection parameters");
  const auto w = summarize(x.s);
  const auto side = [&](const char* dir, const direction_setting& d, const direction_summary& ds) {
    return d.used ? fmt::format("{} {} bytes, {}; {}", dir, sum_words(d), d.asked.variable ? "variable" : "fixed",
                                ds.types)
                  : fmt::format("{} none (a null connection)", dir);
  };
  const bool ot_only =
      status == ext::invalid_ot_fixed_variable || status == ext::invalid_ot_priority || status == ext::invalid_ot_type;
  const bool to_only =
      status == ext::invalid_to_fixed_variable || status == ext::invalid_to_priority || status == ext::invalid_to_type;
  out.words = "a scanner configured from the EDS asks ";
  if (!to_only) out.words += side("O->T", x.s.ot, w.ot);
  if (!ot_only && !to_only) out.words += "; ";
  if (!ot_only) out.words += side("T->O", x.s.to, w.to);
  return out;
}

}  // namespace

bool takes_accepted_size(ext status) {
  return status == ext::invalid_configuration_size || status == ext::invalid_ot_size || status == ext::invalid_to_size;
}

std::optional<status_site> status_site_of(const model::device& dev, const source_file* src, const connection_setting& s,
                                          ext status, std::optional<std::uint16_t> accepted) {
  const model::connection* c = nullptr;
  for (const auto& x : dev.connections)
    if (x.number == s.number && x.from.where.begin == s.at.begin) c = &x;
  if (c == nullptr) return std::nullopt;
  const site_context x{dev, src, *c, s, accepted};
  switch (status) {
    case ext::invalid_ot_size: return size_site(x, true);
    case ext::invalid_to_size: return size_site(x, false);
    case ext::invalid_configuration_size: return config_size_site(x);
    case ext::inconsistent_consume_format: return format_site(x, true);
    case ext::inconsistent_produce_format: return format_site(x, false);
    case ext::rpi_not_supported:
    case ext::rpi_not_acceptable: return rpi_site(x);
    case ext::vendor_or_product_code_mismatch:
    case ext::device_type_mismatch:
    case ext::revision_mismatch: return key_site(x, status);
    case ext::invalid_application_path:
    case ext::invalid_configuration_path:
    case ext::invalid_configuration_application_path:
    case ext::invalid_consuming_path:
    case ext::invalid_producing_path:
    case ext::inconsistent_path_combination: return path_site(x, status);
    case ext::non_listen_only_not_opened: return listen_site(x);
    case ext::transport_trigger_not_supported:
    case ext::transport_class_not_supported:
    case ext::trigger_not_supported:
    case ext::direction_not_supported: return transport_site(x);
    case ext::invalid_network_parameter:
    case ext::invalid_connection_size:
    case ext::invalid_ot_fixed_variable:
    case ext::invalid_to_fixed_variable:
    case ext::invalid_ot_priority:
    case ext::invalid_to_priority:
    case ext::invalid_ot_type:
    case ext::invalid_to_type:
    case ext::null_forward_open_not_supported: return params_site(x, status);
    default: return std::nullopt;
  }
}

}  // namespace edsc::connections
