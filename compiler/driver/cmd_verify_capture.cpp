// `edsc verify --capture FILE.pcap|.pcapng FILE.eds... [--library DIR]`: an
// EtherNet/IP capture judged against EDS files (docs/capture.md). The capture
// is read streaming; the judge is verify/enip_capture.hpp.
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/plural.hpp"
#include "capture/reader.hpp"
#include "check/check_file.hpp"
#include "driver/commands.hpp"
#include "driver/net_report.hpp"
#include "driver/verify_capture.hpp"
#include "io/collect_inputs.hpp"
#include "verify/enip_capture.hpp"

namespace edsc::driver {

namespace {

using json = nlohmann::ordered_json;

// The EDS files to judge against: those named, then a library's (files with
// syntax errors in a library are left out and counted, as probe does).
struct loaded {
  std::vector<std::unique_ptr<analysis>> files;
  std::vector<std::string> names;
  std::size_t skipped = 0;
};

std::optional<loaded> load(const verify_capture_cli& cli, const check_options& options) {
  loaded out;
  auto take = [&](const std::string& path, bool named) {
    auto source = read_or_report(path);
    if (!source) return !named;
    auto a = analyze(std::move(source), options);
    if (a->has_syntax_errors()) {
      if (named) print_error(fmt::format("{}: syntax errors (see edsc check {}); not compared", path, path));
      ++out.skipped;
      return !named;
    }
    out.files.push_back(std::move(a));
    out.names.push_back(path);
    return true;
  };
  for (const auto& p : cli.eds)
    if (!take(p, true)) return std::nullopt;
  if (!cli.library.empty()) {
    auto lib = io::collect_inputs({cli.library});
    for (const auto& e : lib.errors) print_error(fmt::format("--library {}", e.message));
    if (!lib.errors.empty()) return std::nullopt;
    for (const auto& p : lib.files) take(p, false);
  }
  return out;
}

struct read_capture {
  capture::tracker trace;
  capture::drop_counts drops;
  std::uint64_t frames = 0, messages = 0;
  std::string error;  // the file ended badly: what was read stands
};

std::optional<read_capture> read(const std::string& path) {
  auto r = capture::reader::open(path);
  if (!r) {
    print_error(r.error().message);  // it names the file
    return std::nullopt;
  }
  read_capture out;
  std::int64_t last_ns = 0;
  for (;;) {
    auto m = r->next();
    if (!m) {
      out.error =
          m.error().frame > 0 ? fmt::format("frame {}: {}", m.error().frame, m.error().message) : m.error().message;
      break;
    }
    if (!m->has_value()) break;
    ++out.messages;
    last_ns = std::max(last_ns, (*m)->time.total_ns());
    out.trace.add(**m);
  }
  out.trace.finish(last_ns);
  out.drops = r->drops();
  out.frames = r->frames();
  return out;
}

std::string drops_text(const capture::drop_counts& d) {
  std::string out;
  for (std::size_t i = 0; i < capture::drop_count; ++i) {
    const auto reason = static_cast<capture::drop>(i);
    if (!capture::is_malformed(reason) || d[reason] == 0) continue;
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", capture::drop_name(reason), d[reason]);
  }
  return out;
}

json direction_json(const capture::io_direction& d) {
  return {{"frames", d.frames},
          {"first_frame", d.first_frame},
          {"last_frame", d.last_frame},
          {"min_size", d.min_size},
          {"max_size", d.max_size},
          {"median_interval_us", d.intervals.quantile(0.5)},
          {"p99_interval_us", d.intervals.quantile(0.99)},
          {"worst_interval_us", d.intervals.worst()},
          {"worst_interval_frame", d.intervals.worst_frame()},
          {"lost", d.lost},
          {"out_of_order", d.out_of_order}};
}

json connection_json(const capture::connection_seen& c, const verify::connection_verdict& v) {
  json j = {{"originator", verify::address_text(c.originator.address)},
            {"target", verify::address_text(c.target.address)},
            {"request_frame", c.request_frame},
            {"reply_frame", c.reply_frame},
            {"connection", v.point ? json(*v.point) : json(nullptr)},
            {"outcome", v.outcome},
            {"not_as_eds", v.fit},
            {"keying", v.keying},
            {"serial", c.request.connection_serial},
            {"originator_vendor", c.request.originator_vendor},
            {"originator_serial", c.request.originator_serial},
            {"large", c.large},
            {"timeout_multiplier", c.request.timeout_multiplier},
            {"ot_rpi_us", c.request.ot_rpi_us},
            {"to_rpi_us", c.request.to_rpi_us},
            {"ot_size", c.request.ot.size},
            {"to_size", c.request.to.size},
            {"transport", c.request.transport}};
  if (c.refused()) j["refused"] = {{"general", c.general}, {"additional", c.additional}};
  if (c.granted) {
    j["ot_connection_id"] = c.granted->ot_connection_id;
    j["to_connection_id"] = c.granted->to_connection_id;
    j["ot_api_us"] = c.granted->ot_api_us;
    j["to_api_us"] = c.granted->to_api_us;
    j["ot"] = direction_json(c.ot);
    j["to"] = direction_json(c.to);
  }
  j["close_frame"] = c.close_frame;
  j["timeout_after_frame"] = c.timeout_after_frame;
  return j;
}

json capture_json(const std::string& path, const read_capture& c, const verify::capture_verdict& v,
                  const std::vector<std::string>& names) {
  json devices = json::array();
  for (const auto& d : v.devices) {
    json j = {{"address", verify::address_text(d.address)}};
    if (d.identity)
      j["identity"] = {{"vendor", d.identity->vendor},
                       {"device_type", d.identity->device_type},
                       {"product_code", d.identity->product_code},
                       {"major", d.identity->major},
                       {"minor", d.identity->minor},
                       {"product_name", d.identity->product_name},
                       {"frame", d.identity_frame}};
    j["eds"] = d.eds ? json(names[*d.eds]) : json(nullptr);
    devices.push_back(std::move(j));
  }
  json conns = json::array();
  for (const auto& cv : v.connections) conns.push_back(connection_json(c.trace.connections()[cv.index], cv));
  json drops = json::object();
  for (std::size_t i = 0; i < capture::drop_count; ++i)
    if (const auto n = c.drops[static_cast<capture::drop>(i)]; n > 0)
      drops[std::string(capture::drop_name(static_cast<capture::drop>(i)))] = n;
  json out = {{"file", path},   {"frames", c.frames}, {"messages", c.messages},
              {"drops", drops}, {"devices", devices}, {"connections", conns}};
  if (const auto routed = c.trace.routed(); routed > 0) out["routed_requests"] = routed;
  return out;
}

std::string dump(const json& j) { return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n"; }

void print(std::vector<file_report>& reports, const report_totals& totals, const verify_capture_cli& cli,
           const std::string& what, const read_capture& c, const verify::capture_verdict& v,
           const std::vector<std::string>& names) {
  if (cli.format == report_format::text) {
    std::string tail = "\n" + verify::render_timeline(c.trace, v, names);
    tail += fmt::format("{}: {}, {} EtherNet/IP message{}", cli.capture, plural(c.frames, "frame"), c.messages,
                        c.messages == 1 ? "" : "s");
    if (const auto bad = drops_text(c.drops); !bad.empty()) tail += fmt::format("; malformed: {}", bad);
    if (const auto over = c.trace.over_limits(); over > 0) tail += fmt::format("; {} past the tracker's limits", over);
    if (const auto routed = c.trace.routed(); routed > 0)
      tail += fmt::format("; {} routed past the device, not judged", plural(routed, "request"));
    if (!c.trace.problems().empty())
      tail += fmt::format("; {} undecodable (first: frame {}: {})", plural(c.trace.problems().size(), "message"),
                          c.trace.problems()[0].frame, c.trace.problems()[0].what);
    print_reports(reports, totals, cli.format, cli.color, what, tail + "\n\n");
    return;
  }
  const auto doc = cli.format == report_format::json ? render_json(reports, totals) : render_sarif(reports);
  auto j = json::parse(doc);
  auto cj = capture_json(cli.capture, c, v, names);
  if (cli.format == report_format::json)
    j["capture"] = std::move(cj);
  else
    j["runs"][0]["properties"]["capture"] = std::move(cj);
  write_all(stdout, dump(j));
  std::fflush(stdout);
}

}  // namespace

bool is_packet_capture(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char m[4] = {0, 0, 0, 0};
  if (!in.read(reinterpret_cast<char*>(m), 4)) return false;
  const std::uint32_t be =
      (std::uint32_t{m[0]} << 24) | (std::uint32_t{m[1]} << 16) | (std::uint32_t{m[2]} << 8) | m[3];
  // pcap (microseconds, nanoseconds; either byte order) and pcapng's section header block.
  for (const std::uint32_t magic : {0xA1B2C3D4u, 0xD4C3B2A1u, 0xA1B23C4Du, 0x4D3CB2A1u, 0x0A0D0D0Au})
    if (be == magic) return true;
  return false;
}

int run_verify_capture(const verify_capture_cli& cli) {
  if (cli.eds.empty() && cli.library.empty()) {
    print_error("verify --capture on a packet capture needs the devices' EDS files, or --library DIR");
    return exit_failure;
  }
  check_options options;
  if (!apply_flags(cli.warning_flags, options)) return exit_failure;
  auto files = load(cli, options);
  if (!files) return exit_failure;
  auto c = read(cli.capture);
  if (!c) return exit_failure;
  std::vector<verify::capture_eds> eds;
  for (const auto& f : files->files) eds.push_back({&f->dev, f->source.get()});
  auto v = verify::judge_capture(c->trace, eds);
  std::vector<diagnostics> by_file(files->files.size());
  for (auto& f : v.findings) by_file[f.eds].push_back(std::move(f.d));
  std::vector<file_report> reports;
  report_totals totals;
  totals.files = files->files.size();
  for (std::size_t i = 0; i < files->files.size(); ++i) {
    if (by_file[i].empty()) continue;
    options.policy.apply(by_file[i]);
    std::stable_sort(by_file[i].begin(), by_file[i].end(),
                     [](const diagnostic& a, const diagnostic& b) { return a.where.begin < b.where.begin; });
    totals.add(by_file[i]);
    reports.push_back({std::move(files->files[i]->source), std::move(by_file[i])});
  }
  print(reports, totals, cli, fmt::format("{} against {}", cli.capture, plural(files->files.size(), "EDS file")), *c, v,
        files->names);
  if (!c->error.empty()) {
    print_error(fmt::format("{}: {}; what came before it is reported", cli.capture, c->error));
    return exit_failure;
  }
  return totals.errors > 0 ? exit_findings : exit_ok;
}

}  // namespace edsc::driver
