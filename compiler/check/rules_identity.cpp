// [File], [Device] and [Device Classification] (EDS_FORMAT.md §7 rules 8-12, §8.1).
#include <cctype>

#include <fmt/format.h>

#include "check/context.hpp"
#include "check/text_length.hpp"
#include "cip/encap.hpp"

namespace edsc {

namespace {

struct required {
  const model::value* v;
  const char* keyword;
};

void check_required(const check_context& ctx, std::uint32_t section, const char* section_name,
                    std::initializer_list<required> keys) {
  for (const auto& [v, keyword] : keys) {
    // An entry present but empty is required-field-empty's to report.
    if (v->present() || v->from.entry != model::none) continue;
    ctx.report(diag_id::missing_keyword, ctx.section_name(section),
               fmt::format("[{}] has no {} entry, which is required", section_name, keyword));
  }
}

bool before(const model::date& a, const model::date& b) {
  return std::tie(a.year, a.month, a.day) < std::tie(b.year, b.month, b.day);
}

void check_dates(const check_context& ctx) {
  const auto& f = ctx.dev.file;
  for (const auto* v : {&f.create_date, &f.mod_date}) {
    if (v->ok() && v->d.year < 1994) {
      ctx.report(diag_id::date_too_early, ctx.where(*v),
                 fmt::format("year {} is before EDS files existed (1994)", v->d.year));
    }
  }
  if (f.create_date.ok() && f.mod_date.ok() && before(f.mod_date.d, f.create_date.d)) {
    ctx.report_with_note(diag_id::moddate_before_createdate, ctx.where(f.mod_date),
                         "ModDate is earlier than CreateDate", ctx.where(f.create_date), "CreateDate is here");
  }
}

// `VVVVTTTTPPPPMM00.eds`: the name Rockwell tools and the ODVA marketplace use.
void check_file_name(const check_context& ctx) {
  const auto& id = ctx.dev.identity;
  if (!id.vend_code.is_integer() || !id.prod_type.is_integer() || !id.prod_code.is_integer() ||
      !id.maj_rev.is_integer()) {
    return;
  }
  const std::string& path = ctx.tree.source->path();
  const auto slash = path.find_last_of('/');
  const std::string name = path.substr(slash == std::string::npos ? 0 : slash + 1);
  if (name.size() != 20) return;
  for (std::size_t i = 0; i < 16; ++i) {
    if (!std::isxdigit(static_cast<unsigned char>(name[i]))) return;
  }
  const auto expected =
      fmt::format("{:04X}{:04X}{:04X}{:02X}00", id.vend_code.as_uint() & 0xFFFF, id.prod_type.as_uint() & 0xFFFF,
                  id.prod_code.as_uint() & 0xFFFF, id.maj_rev.as_uint() & 0xFF);
  std::string stem = name.substr(0, 16);
  for (auto& c : stem) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (stem != expected) {
    ctx.report(diag_id::file_name_convention, ctx.section_name(id.section),
               fmt::format("file name '{}' follows the VVVVTTTTPPPPMM00.eds convention but the identity "
                           "gives '{}.eds'",
                           name, expected));
  }
}

}  // namespace

void check_identity(const check_context& ctx) {
  const auto& d = ctx.dev;
  if (d.file.section == model::none) {
    ctx.report(diag_id::missing_section, {0, 0}, "the file has no [File] section, which is required");
  } else {
    const auto& f = d.file;
    check_required(ctx, f.section, "File",
                   {{&f.desc_text, "DescText"},
                    {&f.create_date, "CreateDate"},
                    {&f.create_time, "CreateTime"},
                    {&f.revision, "Revision"}});
  }
  const auto& id = d.identity;
  if (id.section == model::none) {
    ctx.report(diag_id::missing_section, {0, 0}, "the file has no [Device] section, which is required");
  } else {
    check_required(ctx, id.section, "Device",
                   {{&id.vend_code, "VendCode"},
                    {&id.vend_name, "VendName"},
                    {&id.prod_type, "ProdType"},
                    {&id.prod_type_str, "ProdTypeStr"},
                    {&id.prod_code, "ProdCode"},
                    {&id.maj_rev, "MajRev"},
                    {&id.min_rev, "MinRev"},
                    {&id.prod_name, "ProdName"}});
  }
  if (id.maj_rev.is_integer() && id.maj_rev.as_uint() == 0) {
    ctx.report(diag_id::majrev_zero, ctx.where(id.maj_rev), "MajRev is 0; major revisions start at 1");
  }
  if (id.prod_name.ok() && id.prod_name.text.size() > cip::max_product_name) {
    ctx.report(diag_id::prodname_too_long, ctx.where(id.prod_name),
               fmt::format("ProdName is {}; the device's product name attribute holds at most {} bytes",
                           byte_length(id.prod_name.text), cip::max_product_name));
  }
  check_dates(ctx);
  check_file_name(ctx);

  for (std::size_t i = 0; i < d.classes.classes.size(); ++i) {
    const auto& c = d.classes.classes[i];
    if (c.number != i + 1) {
      ctx.report(diag_id::class_numbering, ctx.entry_keyword(c.network.from),
                 fmt::format("Class{} is entry {} of [Device Classification]; ClassN entries are numbered 1, 2, 3...",
                             c.number, i + 1));
      break;
    }
  }
  if (d.classes.section == model::none) {
    const bool ip_or_cnet = (ctx.networks & (model::net_ethernetip | model::net_controlnet)) != 0;
    ctx.report(ip_or_cnet ? diag_id::missing_classification : diag_id::missing_classification_devicenet,
               ctx.section_name(id.section),
               ip_or_cnet ? "the file has no [Device Classification] section; EtherNet/IP and ControlNet "
                            "tools require one"
                          : "the file has no [Device Classification] section (optional for DeviceNet)");
  }
}

}  // namespace edsc
