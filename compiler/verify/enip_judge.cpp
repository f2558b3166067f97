#include "verify/enip_judge.hpp"

#include <fmt/format.h>

#include "cip/request.hpp"
#include "cip/status.hpp"
#include "connections/forward_open_fit.hpp"
#include "connections/plan.hpp"
#include "connections/served_points.hpp"
#include "connections/settings.hpp"
#include "connections/status_site.hpp"

namespace edsc::verify {

namespace {

using ext = cip::extended_status;

// What one EDS file offers, read once for every connection judged against it.
struct eds_view {
  const capture_eds* file = nullptr;
  connections::served_points served;
  std::vector<connections::connection_setting> settings;

  [[nodiscard]] const connections::connection_setting* setting(std::uint32_t number) const {
    for (const auto& s : settings)
      if (s.number == number) return &s;
    return nullptr;
  }
};

std::string key_words(const cip::electronic_key& k, const std::optional<connections::refusal>& r) {
  return fmt::format("vendor {}, device type {}, product code {}, revision {}.{}, {} keying: {}", k.vendor,
                     k.device_type, k.product_code, k.major, k.minor, k.compatible ? "compatible" : "exact",
                     r ? r->why : std::string("[Device] fits it"));
}

// The first [Device] field a device's identity differs in, as a scanner
// compares them: vendor, device type, product code, major revision.
span first_difference(const model::device& dev, const cip::identity& id) {
  const auto& i = dev.identity;
  const auto k = connections::key_from_device(dev).value_or(cip::electronic_key{});
  if (k.vendor != id.vendor) return i.vend_code.from.where;
  if (k.device_type != id.device_type) return i.prod_type.from.where;
  if (k.product_code != id.product_code) return i.prod_code.from.where;
  return i.maj_rev.from.where;
}

std::string ms_text(std::uint64_t us) { return fmt::format("{:.1f} ms", static_cast<double>(us) / 1000.0); }

}  // namespace

namespace {

class judge {
 public:
  judge(const capture::tracker& t, std::span<const capture_eds> files) : t_(t), files_(files) {
    for (const auto& f : files) {
      eds_view v;
      v.file = &f;
      v.served = connections::serve_points(*f.dev);
      v.settings = connections::describe_connections(*f.dev);
      views_.push_back(std::move(v));
    }
  }

  capture_verdict run() {
    out_.devices = find_devices(t_, files_);
    for (const auto& d : out_.devices) device(d);
    for (auto& f : judge_writes(t_, out_.devices, files_)) out_.findings.push_back(std::move(f));
    return std::move(out_);
  }

 private:
  void add(std::size_t eds, diag_id id, span where, std::string message) {
    out_.findings.push_back({eds, make_diagnostic(id, where, std::move(message))});
  }

  void device(const capture_device& d) {
    if (!d.eds) {
      if (d.identity && files_.size() == 1) identity_mismatch(d);
      for (const auto ci : d.connections) out_.connections.push_back({ci, std::nullopt, outcome(ci), {}});
      return;
    }
    for (const auto ci : d.connections) connection(*d.eds, ci);
  }

  void identity_mismatch(const capture_device& d) {
    const auto& dev = *files_[0].dev;
    const auto& id = *d.identity;
    add(0, diag_id::capture_identity, first_difference(dev, id),
        fmt::format("frame {}: {} says it is vendor {}, device type {}, product code {}, revision {}.{} (\"{}\"): "
                    "not the device this EDS describes; its connections are not judged against it",
                    d.identity_frame, address_text(d.address), id.vendor, id.device_type, id.product_code, id.major,
                    id.minor, id.product_name));
  }

  std::string outcome(std::size_t ci) const {
    const auto& c = t_.connections()[ci];
    if (c.reply_frame == 0) return "no reply";
    if (c.granted) return "open";
    return fmt::format("refused 0x{:02X}/0x{:04X}", c.general, cip::extended_of(c.general, c.additional));
  }

  void connection(std::size_t eds, std::size_t ci);
  void against(std::size_t eds, const capture::connection_seen& c, const connections::connection_point& p,
               const std::optional<connections::refusal>& fit, connection_verdict& v);
  void refused_though_fit(std::size_t eds, const capture::connection_seen& c, const connections::connection_point& p);
  void io(std::size_t eds, const capture::connection_seen& c, const connections::connection_point& p);
  void direction(std::size_t eds, const capture::connection_seen& c, const connections::connection_point& p, bool ot);
  [[nodiscard]] span rpi_field(std::size_t eds, const connections::connection_point& p, bool ot) const {
    const auto& v = ot ? p.plan.conn->ot_rpi : p.plan.conn->to_rpi;
    return v.present() && !v.from.where.empty() ? v.from.where : views_[eds].setting(p.number)->at;
  }
  [[nodiscard]] span site(std::size_t eds, std::uint32_t number, ext status,
                          std::optional<std::uint16_t> accepted = std::nullopt) const;

  const capture::tracker& t_;
  std::span<const capture_eds> files_;
  std::vector<eds_view> views_;
  capture_verdict out_;
};

// Where a status points in the EDS for ConnectionN; its entry when the
// status names no one field.
span judge::site(std::size_t eds, std::uint32_t number, ext status, std::optional<std::uint16_t> accepted) const {
  const auto& v = views_[eds];
  const auto* s = v.setting(number);
  if (s == nullptr) return {};
  if (auto at = connections::status_site_of(*v.file->dev, v.file->src, *s, status, accepted)) return at->where;
  return s->at;
}

void judge::connection(std::size_t eds, std::size_t ci) {
  const auto& c = t_.connections()[ci];
  connection_verdict v{ci, std::nullopt, outcome(ci), {}};
  const auto sp = connections::split_connection_path(c.request);
  const auto& view = views_[eds];
  const connections::connection_point* chosen = nullptr;
  const connections::connection_point* first = nullptr;
  std::optional<connections::refusal> first_fit;
  // The key, when there is one, is held to [Device] first, as a device does.
  std::optional<connections::refusal> key_fit;
  if (sp && sp->key) {
    key_fit = connections::check_key(connections::identity_from_eds(*view.file->dev), *sp->key);
    v.keying = key_words(*sp->key, key_fit);
  }
  for (const auto& p : view.served.points) {
    if (!sp || p.segments != sp->app) continue;
    auto fit = key_fit ? key_fit : connections::check_fit(view.file->dev, p, c.request, sp->config);
    if (!fit) {
      chosen = &p;
      break;
    }
    if (first == nullptr) first = &p, first_fit = std::move(fit);
  }
  if (chosen == nullptr && first == nullptr) {
    v.fit = sp ? "no ConnectionN has the application path " + connections::path_words(sp->app)
               : std::string("its connection path cannot be read");
    const auto where = view.settings.empty() ? view.file->dev->identity.prod_code.from.where : view.settings[0].at;
    add(eds, diag_id::capture_path_unknown, where,
        fmt::format("frame {}: the Forward_Open to {}: {}", c.request_frame, address_text(c.target.address), v.fit));
  } else {
    against(eds, c, chosen != nullptr ? *chosen : *first, chosen != nullptr ? std::nullopt : first_fit, v);
  }
  out_.connections.push_back(std::move(v));
}

void judge::against(std::size_t eds, const capture::connection_seen& c, const connections::connection_point& p,
                    const std::optional<connections::refusal>& fit, connection_verdict& v) {
  v.point = p.number;
  v.ot_run_idle = p.plan.ot_run_idle;
  v.to_run_idle = p.plan.to_run_idle;
  const bool refused = c.refused();
  if (!fit) {
    if (refused) refused_though_fit(eds, c, p);
    if (c.granted) io(eds, c, p);
    return;
  }
  v.fit = fit->why;
  const auto where = site(eds, p.number, fit->status, fit->size_accepted);
  if (refused) {
    add(eds, diag_id::capture_forward_open, where,
        fmt::format("frame {}: the Forward_Open for Connection{} asks what the EDS does not describe: {}; the device "
                    "refused it (frame {}: {})",
                    c.request_frame, p.number, fit->why, c.reply_frame, cip::describe_status(c.general, c.additional)));
    return;
  }
  add(eds, diag_id::capture_forward_open_granted, where,
      fmt::format("frame {}: the Forward_Open for Connection{} asks what the EDS does not describe: {}; {}",
                  c.request_frame, p.number, fit->why,
                  c.granted ? fmt::format("the device opened it (frame {})", c.reply_frame)
                            : std::string("the capture holds no reply")));
  if (c.granted) io(eds, c, p);
}

void judge::refused_though_fit(std::size_t eds, const capture::connection_seen& c,
                               const connections::connection_point& p) {
  const auto e = cip::extended_of(c.general, c.additional);
  if (cip::busy_reason(c.general, e) != nullptr) return;  // the device's state, not the EDS's: the timeline says it
  std::optional<std::uint16_t> accepted;
  if (connections::takes_accepted_size(ext{e}) && c.additional.size() > 1) accepted = c.additional[1];
  add(eds, diag_id::capture_refused, e != 0 ? site(eds, p.number, ext{e}, accepted) : site(eds, p.number, ext{}),
      fmt::format("frame {}: the device refused the Forward_Open of frame {} for Connection{}, which asks what "
                  "the EDS describes: {}",
                  c.reply_frame, c.request_frame, p.number, cip::describe_status(c.general, c.additional)));
}

void judge::io(std::size_t eds, const capture::connection_seen& c, const connections::connection_point& p) {
  direction(eds, c, p, true);
  direction(eds, c, p, false);
  if (c.timeout_after_frame != 0) {
    const auto* s = views_[eds].setting(p.number);
    add(eds, diag_id::capture_timeout, s != nullptr ? s->at : span{},
        fmt::format("Connection{} timed out: no {} frame for longer than its timeout ({}) after frame {}{}", p.number,
                    c.timeout_ot ? "O->T" : "T->O", ms_text(c.timeout_us(c.timeout_ot)), c.timeout_after_frame,
                    c.close_frame != 0 ? fmt::format(", before the Forward_Close of frame {}", c.close_frame)
                                       : std::string(", and no Forward_Close")));
  }
}

void judge::direction(std::size_t eds, const capture::connection_seen& c, const connections::connection_point& p,
                      bool ot) {
  const auto& d = ot ? c.ot : c.to;
  const char* dir = ot ? "O->T" : "T->O";
  const auto asked = ot ? c.request.ot.size : c.request.to.size;
  if (d.size_mismatch_frame != 0)
    add(eds, diag_id::capture_io_size, site(eds, p.number, ot ? ext::invalid_ot_size : ext::invalid_to_size),
        fmt::format(
            "frame {}: Connection{}'s {} frames carry {} bytes, the Forward_Open of frame {} asked {} "
            "(sequence count and run/idle header included)",
            d.size_mismatch_frame, p.number, dir,
            d.min_size == d.max_size ? fmt::format("{}", d.min_size) : fmt::format("{} to {}", d.min_size, d.max_size),
            c.request_frame, asked));
  if (d.lost != 0)
    add(eds, diag_id::capture_io_lost, views_[eds].setting(p.number)->at,
        fmt::format("Connection{}: {} {} frames lost (gaps in the sequence number) among the {} captured, from "
                    "frame {} to {}",
                    p.number, d.lost, dir, d.frames, d.first_frame, d.last_frame));
  const auto api = ot ? c.granted->ot_api_us : c.granted->to_api_us;
  const auto median = d.intervals.quantile(0.5);
  if (d.intervals.count() >= 3 && api > 0 && median * 2 > api * 3)
    add(eds, diag_id::capture_io_interval, rpi_field(eds, p, ot),
        fmt::format("Connection{}'s {} frames come every {} (median; p99 {}, worst gap {} ending at frame {}), the "
                    "device granted {}",
                    p.number, dir, ms_text(median), ms_text(d.intervals.quantile(0.99)), ms_text(d.intervals.worst()),
                    d.intervals.worst_frame(), ms_text(api)));
}

}  // namespace

capture_verdict judge_capture(const capture::tracker& t, std::span<const capture_eds> files) {
  return judge(t, files).run();
}

}  // namespace edsc::verify
