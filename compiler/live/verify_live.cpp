#include "live/verify_live.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "cip/encap.hpp"
#include "cip/status.hpp"
#include "connections/plan.hpp"
#include "connections/settings.hpp"
#include "connections/status_site.hpp"
#include "live/facts.hpp"
#include "live/io.hpp"

namespace edsc::live {

namespace {

using model::value;
using extended = cip::extended_status;

// Where a finding points: the field when it is written, else the entity.
span at(const value& v, const model::origin& fallback) {
  return v.present() && !v.from.where.empty() ? v.from.where : fallback.where;
}

std::string revision_text(unsigned major, unsigned minor) { return fmt::format("{}.{}", major, minor); }

// The comparison of the facts with the EDS, check by check; it asks nothing.
struct checker {
  checker(const model::device& d, const live_facts& facts, live_report& r) : dev(d), f(facts), out(r) {}
  const model::device& dev;
  const live_facts& f;
  live_report& out;
  std::optional<cip::identity> device_id;
  bool finished_said = false;
  std::vector<connections::connection_setting> settings;  // made at the first refusal

  void row(std::string check, std::string eds, std::string device, verdict v) {
    check_row r;
    r.check = std::move(check);
    r.eds = std::move(eds);
    r.device = std::move(device);
    r.result = v;
    out.rows.push_back(std::move(r));
  }
  void diag(diag_id id, span where, std::string message) {
    out.diags.push_back(make_diagnostic(id, where, std::move(message)));
  }

  // Vendor, type, code: integer fields a scanner's key compares.
  void number(const char* keyword, const value& v, unsigned device_value) {
    const auto where = v.from.where;
    if (!v.is_integer()) {
      row(keyword, "(not a number)", std::to_string(device_value), verdict::not_tried);
      return;
    }
    const bool same = v.as_uint() == device_value;
    row(keyword, std::to_string(v.as_uint()), std::to_string(device_value), same ? verdict::match : verdict::mismatch);
    if (!same)
      diag(diag_id::live_identity, where,
           fmt::format("the device reports {} {}, the EDS says {}: a scanner keyed from this file refuses it", keyword,
                       device_value, v.as_uint()));
  }

  void identity(const cip::identity& id) {
    device_id = id;
    const auto& d = dev.identity;
    number("VendCode", d.vend_code, id.vendor);
    number("ProdType", d.prod_type, id.device_type);
    number("ProdCode", d.prod_code, id.product_code);
    const auto dev_rev = revision_text(id.major, id.minor);
    if (d.maj_rev.is_integer() && d.min_rev.is_integer()) {
      const auto maj = d.maj_rev.as_uint(), min = d.min_rev.as_uint();
      const auto eds_rev = revision_text(static_cast<unsigned>(maj), static_cast<unsigned>(min));
      if (maj != id.major) {
        row("MajRev", eds_rev, dev_rev, verdict::mismatch);
        diag(diag_id::live_identity, d.maj_rev.from.where,
             fmt::format("the device reports revision {}, the EDS says {}: exact and compatible keying both "
                         "refuse a different major revision",
                         dev_rev, eds_rev));
      } else if (min > id.minor) {
        // Compatible keying accepts a device at least as new as the key: not this one.
        row("MinRev", eds_rev, dev_rev, verdict::mismatch);
        diag(diag_id::live_identity, d.min_rev.from.where,
             fmt::format("the device reports revision {}, the EDS says {}: exact keying refuses it, compatible "
                         "keying refuses it too (the device's minor revision is older): a scanner keyed from this "
                         "file keeps the device off line",
                         dev_rev, eds_rev));
      } else if (min != id.minor) {
        row("MinRev", eds_rev, dev_rev, verdict::mismatch);
        diag(diag_id::live_minor_revision, d.min_rev.from.where,
             fmt::format("the device reports revision {}, the EDS says {}: exact keying refuses it, compatible "
                         "keying accepts it (the device's minor revision is newer)",
                         dev_rev, eds_rev));
      } else {
        row("MajRev/MinRev", eds_rev, dev_rev, verdict::match);
      }
    } else {
      row("MajRev/MinRev", "(not numbers)", dev_rev, verdict::not_tried);
    }
    if (d.prod_name.ok()) {
      // The device holds at most 32 bytes of it, as the header and the simulator cut it.
      const bool same = cip::held_product_name(d.prod_name.text) == id.product_name;
      row("ProdName", fmt::format("\"{}\"", d.prod_name.text), fmt::format("\"{}\"", id.product_name),
          same ? verdict::match : verdict::mismatch);
      if (!same)
        diag(diag_id::live_product_name, d.prod_name.from.where,
             fmt::format("the device reports product name \"{}\", the EDS says \"{}\"", id.product_name,
                         d.prod_name.text));
    }
  }

  std::string assem_name(const model::assembly& a) { return fmt::format("Assem{}", a.number); }

  // Attribute 4 of each assembly instance the EDS locates.
  void assemblies() {
    const auto targets = plan_assemblies(dev);
    for (std::size_t i = 0; i < targets.size(); ++i) {
      const auto& t = targets[i];
      const auto check = fmt::format("{} size (instance {})", assem_name(*t.assem), t.instance);
      const auto eds_size = t.eds_size ? std::to_string(*t.eds_size) : std::string("(not given)");
      if (unreached(check, eds_size, i < f.assemblies.size())) continue;
      const auto& rep = f.assemblies[i].size;
      const auto where = at(t.assem->size, t.assem->from);
      // Path destination unknown is OpENer's answer.
      if (f.assemblies[i].class_answers.value_or(false)) {
        row(check, eds_size, "no such instance", verdict::mismatch);
        diag(diag_id::live_assembly_missing, t.named_at,
             fmt::format("the device has no assembly instance {} ({}), which {} says it has", t.instance,
                         cip::describe_status(rep.general, rep.additional), assem_name(*t.assem)));
        continue;
      }
      if (rep.general != 0 || rep.data.size() < 2) {
        const auto why = rep.general != 0 ? cip::describe_status(rep.general, rep.additional)
                                          : std::string("a reply without the size");
        row(check, eds_size, "not readable", verdict::not_readable);
        diag(diag_id::live_not_checked, where,
             fmt::format("{}: the device does not give the size of assembly instance {} ({})", assem_name(*t.assem),
                         t.instance, why));
        continue;
      }
      const unsigned size = rep.data[0] | (rep.data[1] << 8);
      if (!t.eds_size) {
        // No size in the EDS is not a size of 0: say what the device holds.
        row(check, eds_size, std::to_string(size), verdict::not_tried);
        diag(diag_id::live_not_checked, where,
             fmt::format("{} gives no size; the device holds {} in assembly instance {}", assem_name(*t.assem),
                         plural(size, "byte"), t.instance));
        continue;
      }
      // Attribute 4 is in bytes; a device may count words (an older reading): accept neither silently.
      row(check, eds_size, std::to_string(size), size == *t.eds_size ? verdict::match : verdict::mismatch);
      if (size != *t.eds_size)
        diag(diag_id::live_assembly_size, where,
             fmt::format("assembly instance {} holds {} on the device, {} says {}", t.instance, plural(size, "byte"),
                         assem_name(*t.assem), *t.eds_size));
    }
  }

  // The field a refusal is about: the size field when written, else the
  // format (the assembly reference) or the path, else the entry.
  span refusal_site(const connection_plan& p, std::uint16_t ext) {
    const auto& c = *p.conn;
    switch (extended{ext}) {
      case extended::invalid_ot_size: return at(c.ot_size, model::origin{0, at(c.ot_format, c.from)});
      case extended::invalid_to_size: return at(c.to_size, model::origin{0, at(c.to_format, c.from)});
      case extended::invalid_configuration_size:
      case extended::invalid_configuration_application_path:
        return at(c.target_config_size, model::origin{0, at(c.target_config_format, at_path(c))});
      case extended::rpi_not_supported:
      case extended::rpi_not_acceptable: return at(c.ot_rpi, c.from);
      case extended::vendor_or_product_code_mismatch: return at(dev.identity.prod_code, c.from);
      case extended::device_type_mismatch: return at(dev.identity.prod_type, c.from);
      case extended::revision_mismatch: {
        // The revision field that differs: the minor one when the majors agree.
        const auto& d = dev.identity;
        const bool minor_only = device_id && d.maj_rev.is_integer() && d.maj_rev.as_uint() == device_id->major;
        return at(minor_only ? d.min_rev : d.maj_rev, c.from);
      }
      default: return at_path(c).where;
    }
  }
  model::origin at_path(const model::connection& c) { return {0, at(c.path, c.from)}; }

  // The status in ODVA's words, then what it points at in the EDS with the
  // numbers there: the words `edsc explain --eds` prints (status_site.hpp).
  std::string refusal_words(const connection_plan& p, const connection_outcome& o) {
    const auto status = cip::describe_status(o.general, o.additional);
    if (o.general != cip::code(cip::general_status::connection_failure) || o.additional.empty()) return status;
    const extended ext{o.additional[0]};
    if (settings.empty()) settings = connections::describe_connections(dev);
    const auto s = std::find_if(settings.begin(), settings.end(), [&](const auto& x) {
      return x.number == p.facts.number && x.at == p.conn->from.where;
    });
    if (s == settings.end()) return status;
    std::optional<std::uint16_t> accepted;
    if (connections::takes_accepted_size(ext) && o.additional.size() >= 2) accepted = o.additional[1];
    const auto site = connections::status_site_of(dev, nullptr, *s, ext, accepted);
    return site ? fmt::format("{}: {}", status, site->words) : status;
  }

  void connections() {
    const auto plans = plan_connections(dev);
    for (std::size_t i = 0; i < plans.size(); ++i) {
      const auto& p = plans[i];
      const auto name = fmt::format("Connection{}", p.facts.number);
      const auto sizes =
          fmt::format("O->T {} T->O {} cfg {}", p.facts.output_size, p.facts.input_size, p.facts.config_size);
      if (unreached(name, sizes, i < f.connections.size())) continue;
      if (!p.not_openable.empty() || !f.connections[i]) {
        row(name, sizes, "not opened", verdict::not_tried);
        diag(diag_id::live_not_checked, p.conn->from.where, fmt::format("{} not opened: {}", name, p.not_openable));
        continue;
      }
      const auto& o = *f.connections[i];
      if (o.opened)
        frames(p, o, name, sizes);
      else
        refused(p, o, name, sizes);
    }
  }

  void refused(const connection_plan& p, const connection_outcome& o, const std::string& name,
               const std::string& sizes) {
    const std::uint16_t ext = cip::extended_of(o.general, o.additional);
    if (const auto* why = cip::busy_reason(o.general, ext)) {
      row(name, sizes, fmt::format("busy 0x{:02X}/0x{:04X}", o.general, ext), verdict::not_tried);
      out.rows.back().refused = std::pair<int, int>{o.general, ext};
      out.busy.push_back(
          fmt::format("{} not checked: the device refused it with {}: {}; that says nothing "
                      "of the EDS",
                      name, cip::describe_status(o.general, o.additional), why));
      return;
    }
    row(name, sizes, fmt::format("refused 0x{:02X}/0x{:04X}", o.general, ext), verdict::mismatch);
    out.rows.back().refused = std::pair<int, int>{o.general, ext};
    diag(diag_id::live_connection_refused, refusal_site(p, ext),
         fmt::format("{} refused: {}", name, refusal_words(p, o)));
  }

  void frames(const connection_plan& p, const connection_outcome& o, const std::string& name,
              const std::string& sizes) {
    const auto& st = o.io;
    const auto& c = *p.conn;
    const auto to_site = at(c.to_size, model::origin{0, at(c.to_format, c.from)});
    bool ok = true;
    if (!o.close_problem.empty())
      diag(diag_id::live_not_checked, c.from.where, fmt::format("{}: {}", name, o.close_problem));
    // Frames of a multicast T->O go to a group edsc does not join: not watched.
    const bool multicast = p.request.to.type == cip::conn_type::multicast;
    if (multicast) {
      diag(diag_id::live_not_checked, to_site,
           fmt::format("{} opened, its T->O frames not watched: they are multicast and edsc joins no group", name));
      row(name, sizes, "open; T->O multicast, frames not watched", verdict::match);
      return;
    }
    // A watch cut short proves nothing by what did not come yet.
    const bool whole_watch = !o.interrupted && !o.failure;
    const bool expects_frames = p.request.to.type != cip::conn_type::null;
    if (whole_watch && expects_frames && st.frames == 0) {
      ok = false;
      diag(diag_id::live_io_frames, to_site,
           fmt::format("{} opened, but no T->O frame came within {} ms (RPI {} us granted)", name, st.watched.count(),
                       o.granted.to_api_us));
    }
    if (st.wrong_size > 0) {
      ok = false;
      diag(diag_id::live_io_frames, to_site,
           fmt::format("{}: {} of {} T->O frames carry {}, the EDS says {}", name, st.wrong_size, st.frames,
                       plural(st.a_wrong_size, "data byte"), p.facts.input_size));
    }
    if (st.without_header > 0) {
      ok = false;
      diag(diag_id::live_io_frames, to_site,
           fmt::format("{}: {} of {} T->O frames lack the run/idle header the T->O format (4) asks for", name,
                       st.without_header, st.frames));
    }
    if (whole_watch)
      if (auto slow = io_rate_warning(name, st, o.granted.to_api_us)) diag(diag_id::live_io_rate, to_site, *slow);
    const auto bytes = st.wrong_size ? st.a_wrong_size : p.facts.input_size;
    auto seen =
        fmt::format("open; {} frames of {} B{}, every {:.1f} ms (API {:.1f} ms)", st.frames, bytes,
                    p.to_run_idle ? " +run/idle" : "", st.mean_interval_us / 1000, o.granted.to_api_us / 1000.0);
    if (!whole_watch)
      seen += fmt::format("; {} after {:.1f} s", o.interrupted ? "interrupted" : "device lost",
                          st.watched.count() / 1000.0);
    // Cut short, what was seen can still have matched.
    const bool seen_enough = whole_watch || st.frames > 0 || !expects_frames;
    row(name, sizes, seen, !ok ? verdict::mismatch : seen_enough ? verdict::match : verdict::not_tried);
    out.rows.back().io = io_summary{st.frames,
                                    bytes,
                                    p.to_run_idle,
                                    st.mean_interval_us / 1000,
                                    o.granted.to_api_us / 1000.0,
                                    static_cast<unsigned>(st.watched.count()),
                                    st.sent};
  }

  // A check without its fact: the run stopped before it, or during it (the
  // first such check after a failure during a check). Its row says which.
  bool unreached(const std::string& check, const std::string& eds, bool have) {
    if (have) return false;
    std::string words = f.failure || !f.interrupted ? "not reached" : "not reached: interrupted";
    if (f.failure && f.during_check && !finished_said) {
      words = "not finished";
      finished_said = true;
    }
    row(check, eds, std::move(words), verdict::not_tried);
    return true;
  }
};
}  // namespace

std::optional<std::string> io_rate_warning(std::string_view name, const io_stats& st, std::uint32_t to_api_us) {
  // Generous: only a device far slower than it promised is worth a word.
  if (st.frames >= 3 && to_api_us > 0 && st.mean_interval_us > 2.0 * to_api_us)
    return fmt::format("{}: T->O frames every {:.1f} ms on average, {:.1f} ms granted", name,
                       st.mean_interval_us / 1000, to_api_us / 1000.0);
  return std::nullopt;
}

std::string_view to_string(verdict v) {
  switch (v) {
    case verdict::match: return "match";
    case verdict::mismatch: return "mismatch";
    case verdict::not_readable: return "not readable";
    case verdict::not_tried: return "not tried";
  }
  return "?";
}

std::chrono::milliseconds io_window(const live_options& opt, std::uint32_t to_rpi_us) {
  if (opt.io_window.count() > 0) return opt.io_window;
  const auto ten_rpis_ms = static_cast<long long>(to_rpi_us) / 100;
  return std::chrono::milliseconds(std::max<long long>(300, ten_rpis_ms));
}

live_report judge_facts(const model::device& dev, const live_facts& facts, bool connections) {
  live_report out;
  out.failure = facts.failure;
  out.interrupted = facts.interrupted;
  if (!facts.connected) return out;
  checker ck(dev, facts, out);
  if (!ck.unreached("identity", "[Device]", facts.identity.has_value())) ck.identity(*facts.identity);
  ck.assemblies();
  if (connections) {
    ck.connections();
  } else {
    for (const auto& c : dev.connections)
      ck.row(fmt::format("Connection{}", c.number), "", "--connections not given", verdict::not_tried);
  }
  std::stable_sort(out.diags.begin(), out.diags.end(),
                   [](const diagnostic& a, const diagnostic& b) { return a.where.begin < b.where.begin; });
  return out;
}

live_report verify_live(const net::endpoint& device, const model::device& dev, const live_options& opt) {
  return judge_facts(dev, gather_facts(device, dev, opt), opt.connections);
}

std::string render_rows(const std::vector<check_row>& rows) {
  std::size_t w0 = 5, w1 = 3, w2 = 6;
  for (const auto& r : rows) {
    w0 = std::max(w0, r.check.size());
    w1 = std::max(w1, r.eds.size());
    w2 = std::max(w2, r.device.size());
  }
  std::string out = fmt::format("{:<{}}  {:<{}}  {:<{}}  {}\n", "check", w0, "EDS", w1, "device", w2, "result");
  for (const auto& r : rows)
    out += fmt::format("{:<{}}  {:<{}}  {:<{}}  {}\n", r.check, w0, r.eds, w1, r.device, w2, to_string(r.result));
  return out;
}

}  // namespace edsc::live
