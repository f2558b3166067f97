// The text summary of a judged capture: each device with the EDS it was
// matched to, each connection from its Forward_Open to its end, each
// direction's frames measured.
#include <fmt/format.h>

#include "cip/status.hpp"
#include "verify/enip_capture.hpp"

namespace edsc::verify {

namespace {

std::string ms(std::uint64_t us) { return fmt::format("{:.1f} ms", static_cast<double>(us) / 1000.0); }

std::string how_words(matched_by h) {
  switch (h) {
    case matched_by::identity: return "by its identity";
    case matched_by::key: return "by the electronic key of its Forward_Opens";
    case matched_by::only_file: return "assumed: the only file given (the capture shows no identity or key)";
    case matched_by::none: break;
  }
  return "";
}

void device_line(std::string& out, const capture_device& d, std::span<const std::string> names) {
  out += address_text(d.address);
  if (d.identity) {
    const auto& id = *d.identity;
    out += fmt::format("  vendor {}, device type {}, product code {}, revision {}.{} \"{}\" (frame {})", id.vendor,
                       id.device_type, id.product_code, id.major, id.minor, id.product_name, d.identity_frame);
  }
  out += "\n  EDS: ";
  out += d.eds ? fmt::format("{}, {}\n", names[*d.eds], how_words(d.how)) : std::string("none of the files given\n");
}

void direction_line(std::string& out, const char* dir, const capture::io_direction& d, std::uint32_t api) {
  if (d.frames == 0) {
    out += fmt::format("    {}  no frame\n", dir);
    return;
  }
  out += fmt::format(
      "    {}  {} frame{} (frames {}..{}), {} bytes", dir, d.frames, d.frames == 1 ? "" : "s", d.first_frame,
      d.last_frame,
      d.min_size == d.max_size ? fmt::format("{}", d.min_size) : fmt::format("{} to {}", d.min_size, d.max_size));
  if (d.intervals.count() > 0)
    out += fmt::format(", every {} (median; p99 {}, worst {} at frame {}; granted {})", ms(d.intervals.quantile(0.5)),
                       ms(d.intervals.quantile(0.99)), ms(d.intervals.worst()), d.intervals.worst_frame(), ms(api));
  if (d.lost > 0) out += fmt::format(", {} lost", d.lost);
  if (d.out_of_order > 0) out += fmt::format(", {} out of order", d.out_of_order);
  out += "\n";
}

void connection_lines(std::string& out, const capture::connection_seen& c, const connection_verdict& v) {
  out += fmt::format("  {} (frame {}", v.point ? fmt::format("Connection{}", *v.point) : std::string("no ConnectionN"),
                     c.request_frame);
  if (c.reply_frame != 0) out += fmt::format(" -> {}", c.reply_frame);
  out += fmt::format("): {}", v.outcome);
  if (c.refused()) out += fmt::format(": {}", cip::describe_status(c.general, c.additional));
  out += "\n";
  if (!v.keying.empty()) out += fmt::format("    key: {}\n", v.keying);
  if (!v.fit.empty()) out += fmt::format("    not as the EDS describes: {}\n", v.fit);
  if (!c.granted) return;
  direction_line(out, "O->T", c.ot, c.granted->ot_api_us);
  direction_line(out, "T->O", c.to, c.granted->to_api_us);
  for (const bool ot : {true, false}) {
    const auto& d = ot ? c.ot : c.to;
    if (!(ot ? v.ot_run_idle : v.to_run_idle) || !d.run_now) continue;
    const bool first = d.changes.empty() ? *d.run_now : !d.changes[0].run;
    out += fmt::format("    {} {} from frame {}", ot ? "O->T" : "T->O", first ? "run" : "idle", d.first_frame);
    for (const auto& ch : d.changes) out += fmt::format(", {} at frame {}", ch.run ? "run" : "idle", ch.frame);
    if (d.change_count > d.changes.size()) out += fmt::format(", {} more changes", d.change_count - d.changes.size());
    out += "\n";
  }
  if (c.close_frame != 0) out += fmt::format("    Forward_Close at frame {}\n", c.close_frame);
  if (c.timeout_after_frame != 0)
    out += fmt::format("    timed out after frame {} ({} silent)\n", c.timeout_after_frame,
                       c.timeout_ot ? "O->T" : "T->O");
}

}  // namespace

std::string render_timeline(const capture::tracker& t, const capture_verdict& v, std::span<const std::string> names) {
  std::string out;
  for (const auto& d : v.devices) {
    device_line(out, d, names);
    for (const auto ci : d.connections)
      for (const auto& cv : v.connections)
        if (cv.index == ci) connection_lines(out, t.connections()[ci], cv);
    out += "\n";
  }
  if (v.devices.empty())
    out += "No EtherNet/IP device in the capture: no ListIdentity or Identity reply, no Forward_Open.\n";
  if (!t.orphan_frames().empty())
    out += fmt::format("Class 1 frames of {} connection{} opened before the capture began (not judged).\n",
                       t.orphan_frames().size(), t.orphan_frames().size() == 1 ? "" : "s");
  return out;
}

}  // namespace edsc::verify
