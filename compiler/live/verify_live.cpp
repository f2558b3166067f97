#include "live/verify_live.hpp"

#include <unistd.h>

#include <algorithm>

#include <fmt/format.h>

#include "cip/status.hpp"
#include "diag/plural.hpp"
#include "live/io.hpp"
#include "live/plan.hpp"
#include "live/session.hpp"

namespace edsc::live {

namespace {

using model::value;

// Where a finding points: the field when it is written, else the entity.
span at(const value& v, const model::origin& fallback) {
  return v.present() && !v.from.where.empty() ? v.from.where : fallback.where;
}

std::string revision_text(unsigned major, unsigned minor) { return fmt::format("{}.{}", major, minor); }

struct checker {
  const model::device& dev;
  const live_options& opt;
  live_report& out;
  std::optional<cip::identity> device_id;

  void row(std::string check, std::string eds, std::string device, verdict v) {
    out.rows.push_back({std::move(check), std::move(eds), std::move(device), v});
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
           fmt::format("the device reports {} {}, the EDS says {}: a scanner keyed from this file refuses it",
                       keyword, device_value, v.as_uint()));
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
      } else if (min != id.minor) {
        const bool compatible = id.minor >= min;
        row("MinRev", eds_rev, dev_rev, verdict::mismatch);
        diag(diag_id::live_minor_revision, d.min_rev.from.where,
             fmt::format("the device reports revision {}, the EDS says {}: exact keying refuses it, compatible "
                         "keying {}",
                         dev_rev, eds_rev,
                         compatible ? "accepts it (the device's minor revision is newer)"
                                    : "refuses it too (the device's minor revision is older)"));
      } else {
        row("MajRev/MinRev", eds_rev, dev_rev, verdict::match);
      }
    } else {
      row("MajRev/MinRev", "(not numbers)", dev_rev, verdict::not_tried);
    }
    if (d.prod_name.ok()) {
      const bool same = d.prod_name.text == id.product_name;
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
  std::optional<net_error> assemblies(session& s) {
    for (const auto& t : plan_assemblies(dev)) {
      const auto check = fmt::format("{} size (instance {})", assem_name(*t.assem), t.instance);
      auto r = s.request(cip::service::get_attribute_single, cip::logical_path(0x04, t.instance, 4));
      if (auto* e = failed(r)) return *e;
      const auto& rep = std::get<cip::reply>(r);
      const auto where = at(t.assem->size, t.assem->from);
      if (rep.general != 0 || rep.data.size() < 2) {
        const auto why = rep.general != 0 ? cip::describe_status(rep.general, rep.additional)
                                          : std::string("a reply without the size");
        row(check, std::to_string(t.eds_size), "not readable", verdict::not_readable);
        diag(diag_id::live_not_checked, where,
             fmt::format("{}: the device does not give the size of assembly instance {} ({})", assem_name(*t.assem),
                         t.instance, why));
        continue;
      }
      const unsigned size = rep.data[0] | (rep.data[1] << 8);
      // Attribute 4 is in bytes; a device may count words (an older reading): accept neither silently.
      row(check, std::to_string(t.eds_size), std::to_string(size), size == t.eds_size ? verdict::match : verdict::mismatch);
      if (size != t.eds_size)
        diag(diag_id::live_assembly_size, where,
             fmt::format("assembly instance {} holds {} on the device, {} says {}", t.instance, plural(size, "byte"),
                         assem_name(*t.assem), t.eds_size));
    }
    return std::nullopt;
  }

  // The field a refusal is about: the size field when written, else the
  // format (the assembly reference) or the path, else the entry.
  span refusal_site(const connection_plan& p, std::uint16_t ext) {
    const auto& c = *p.conn;
    switch (ext) {
      case 0x0127: return at(c.ot_size, model::origin{0, at(c.ot_format, c.from)});
      case 0x0128: return at(c.to_size, model::origin{0, at(c.to_format, c.from)});
      case 0x0126:
      case 0x0129: return at(c.target_config_size, model::origin{0, at(c.target_config_format, at_path(c))});
      case 0x0111:
      case 0x0112: return at(c.ot_rpi, c.from);
      case 0x0114:
        return at(dev.identity.prod_code, c.from);
      case 0x0115: return at(dev.identity.prod_type, c.from);
      case 0x0116: {
        // The revision field that differs: the minor one when the majors agree.
        const auto& d = dev.identity;
        const bool minor_only = device_id && d.maj_rev.is_integer() && d.maj_rev.as_uint() == device_id->major;
        return at(minor_only ? d.min_rev : d.maj_rev, c.from);
      }
      default: return at_path(c).where;
    }
  }
  model::origin at_path(const model::connection& c) { return {0, at(c.path, c.from)}; }

  std::string refusal_words(const connection_plan& p, const connection_outcome& o) {
    const auto status = cip::describe_status(o.general, o.additional);
    if (o.general != 0x01 || o.additional.empty()) return status;
    const auto ext = o.additional[0];
    const bool has_size = o.additional.size() >= 2;
    const unsigned accepted = has_size ? o.additional[1] : 0;
    if (ext == 0x0127 && has_size)
      return fmt::format("{}: the device accepts {} O->T, the EDS says {} ({}{})", status, plural(accepted, "byte"),
                         p.request.ot.size, plural(p.facts.output_size, "data byte"),
                         p.ot_run_idle ? " + 2 sequence + 4 run/idle" : " + 2 sequence");
    if (ext == 0x0128 && has_size)
      return fmt::format("{}: the device accepts {} T->O, the EDS says {} ({}{})", status, plural(accepted, "byte"),
                         p.request.to.size, plural(p.facts.input_size, "data byte"),
                         p.to_run_idle ? " + 2 sequence + 4 run/idle" : " + 2 sequence");
    if (ext == 0x0126 || ext == 0x0129)
      return fmt::format("{}: refused the {} bytes of configuration the EDS gives instance {}", status,
                         p.facts.config_size, p.facts.config_instance);
    if (ext == 0x012F || ext == 0x012A || ext == 0x012B || ext == 0x0117)
      return fmt::format("{}: the path names O->T instance {}, T->O instance {}, configuration instance {}", status,
                         p.facts.output_instance, p.facts.input_instance, p.facts.config_instance);
    return status;
  }

  std::optional<net_error> connections(session& s) {
    std::uint16_t serial = static_cast<std::uint16_t>(0x4500 + (::getpid() & 0xFF));
    for (const auto& p : plan_connections(dev)) {
      const auto name = fmt::format("Connection{}", p.facts.number);
      const auto sizes = fmt::format("O->T {} T->O {} cfg {}", p.facts.output_size, p.facts.input_size, p.facts.config_size);
      if (!p.not_openable.empty()) {
        row(name, sizes, "not opened", verdict::not_tried);
        diag(diag_id::live_not_checked, p.conn->from.where,
             fmt::format("{} not opened: {}", name, p.not_openable));
        continue;
      }
      const auto rpi_ms = std::max<std::uint32_t>(p.to_rpi_us / 1000, 1);
      const auto window = opt.io_window.count() > 0 ? opt.io_window
                                                    : std::chrono::milliseconds(std::max<std::uint32_t>(300, rpi_ms * 10));
      auto r = exercise_connection(s, p, ++serial, std::min(window, opt.timeout));
      if (auto* e = failed(r)) return *e;
      const auto& o = std::get<connection_outcome>(r);
      if (!o.opened) {
        const auto ext = o.general == 0x01 && !o.additional.empty() ? o.additional[0] : 0;
        row(name, sizes, fmt::format("refused 0x{:02X}/0x{:04X}", o.general, ext), verdict::mismatch);
        diag(diag_id::live_connection_refused, refusal_site(p, ext),
             fmt::format("{} refused: {}", name, refusal_words(p, o)));
        continue;
      }
      frames(p, o, name, sizes);
    }
    return std::nullopt;
  }

  void frames(const connection_plan& p, const connection_outcome& o, const std::string& name, const std::string& sizes) {
    const auto& st = o.io;
    const auto& c = *p.conn;
    const auto to_site = at(c.to_size, model::origin{0, at(c.to_format, c.from)});
    bool ok = true;
    // Frames of a multicast T->O go to a group edsc does not join: not watched.
    const bool multicast = p.request.to.type == cip::conn_type::multicast;
    if (multicast) {
      diag(diag_id::live_not_checked, to_site,
           fmt::format("{} opened, its T->O frames not watched: they are multicast and edsc joins no group", name));
      row(name, sizes, "open; T->O multicast, frames not watched", verdict::match);
      return;
    }
    const bool expects_frames = p.request.to.type != cip::conn_type::null;
    if (expects_frames && st.frames == 0) {
      ok = false;
      diag(diag_id::live_io_frames, to_site,
           fmt::format("{} opened, but no T->O frame came within {} ms (RPI {} us granted)", name,
                       std::max<std::uint32_t>(300, p.to_rpi_us / 100), o.granted.to_api_us));
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
    if (auto slow = io_rate_warning(name, st, o.granted.to_api_us)) diag(diag_id::live_io_rate, to_site, *slow);
    if (!o.close_problem.empty())
      diag(diag_id::live_not_checked, c.from.where, fmt::format("{}: {}", name, o.close_problem));
    row(name, sizes,
        fmt::format("open; {} frames of {} B{}, every {:.1f} ms (API {:.1f} ms)", st.frames,
                    st.wrong_size ? st.a_wrong_size : p.facts.input_size, p.to_run_idle ? " +run/idle" : "",
                    st.mean_interval_us / 1000, o.granted.to_api_us / 1000.0),
        ok ? verdict::match : verdict::mismatch);
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

live_report verify_live(const endpoint& device, const model::device& dev, const live_options& opt) {
  live_report out;
  checker ck{dev, opt, out, std::nullopt};
  auto opened = session::open(device, opt.timeout);
  if (auto* e = failed(opened)) {
    out.failure = *e;
    return out;
  }
  auto& s = std::get<session>(opened);
  auto id = read_identity(s);
  if (auto* e = failed(id)) {
    out.failure = *e;
    return out;
  }
  ck.identity(std::get<cip::identity>(id));
  if (auto e = ck.assemblies(s)) {
    out.failure = *e;
    return out;
  }
  if (opt.connections) {
    if (auto e = ck.connections(s)) {
      out.failure = *e;
      return out;
    }
  } else {
    for (const auto& c : dev.connections) ck.row(fmt::format("Connection{}", c.number), "", "--connections not given", verdict::not_tried);
  }
  s.close();
  std::stable_sort(out.diags.begin(), out.diags.end(),
                   [](const diagnostic& a, const diagnostic& b) { return a.where.begin < b.where.begin; });
  return out;
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
