// `edsc probe HOST [--library DIR]`: what a running EtherNet/IP device says
// about itself, the sizes of its assemblies, and which EDS files of a library
// describe it (docs/live.md).
#include <algorithm>
#include <memory>
#include <optional>
#include <variant>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/plural.hpp"
#include "check/check_file.hpp"
#include "cip/status.hpp"
#include "connections/plan.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "driver/verify_live.hpp"
#include "io/collect_inputs.hpp"
#include "io/output_target.hpp"
#include "live/client.hpp"
#include "live/probe.hpp"
#include "live/upload.hpp"

namespace edsc::driver {

namespace {

struct probe_cli {
  std::string host, library, upload_eds;
  double timeout_s = 3.0;
  bool udp = false;
  std::string format = "text";
};

// One library file that describes the device's product (vendor, type, code).
struct library_match {
  std::string path;
  unsigned major = 0, minor = 0;
  live::keying verdict = live::keying::none;
  std::vector<std::uint32_t> instances;  // assembly instances it names
  std::string vendor_name;               // its VendName
};

std::vector<library_match> match_library(const io::collected_inputs& inputs, const cip::identity& id) {
  std::vector<library_match> out;
  for (const auto& path : inputs.files) {
    auto read = io::read_source(path);
    auto* src = (read ? &read.value() : nullptr);
    if (src == nullptr) continue;
    const auto a = analyze(std::move(*src), check_options{});
    const auto& d = a->dev.identity;
    auto is = [](const model::value& v, unsigned n) { return v.is_integer() && v.as_uint() == n; };
    if (!is(d.vend_code, id.vendor) || !is(d.prod_type, id.device_type) || !is(d.prod_code, id.product_code)) continue;
    library_match m;
    m.path = path;
    m.major = d.maj_rev.is_integer() ? static_cast<unsigned>(d.maj_rev.as_uint()) : 0;
    m.minor = d.min_rev.is_integer() ? static_cast<unsigned>(d.min_rev.as_uint()) : 0;
    m.verdict = live::keying_verdict(m.major, m.minor, id.major, id.minor);
    if (d.vend_name.ok()) m.vendor_name = std::string(d.vend_name.text);
    for (const auto& t : connections::plan_assemblies(a->dev)) m.instances.push_back(t.instance);
    out.push_back(std::move(m));
  }
  // Exact first, then compatible, then the others.
  std::stable_sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.verdict < y.verdict; });
  return out;
}

std::string render_probe_text(const probe_cli& cli, const live::probe_result& r,
                              const std::vector<library_match>& lib) {
  const auto& id = r.identity;
  std::string out = fmt::format("{} ({})\n", cli.host, r.identity_source);
  // edsc has no vendor table: the name is what a matching EDS file calls it.
  const auto named = std::find_if(lib.begin(), lib.end(), [](const auto& m) { return !m.vendor_name.empty(); });
  out += named == lib.end()
             ? fmt::format("  vendor        {}\n", id.vendor)
             : fmt::format("  vendor        {} ({}, as {} names it)\n", id.vendor, named->vendor_name, named->path);
  out += fmt::format("  device type   {}\n", id.device_type);
  out += fmt::format("  product code  {}\n", id.product_code);
  out += fmt::format("  revision      {}.{}\n", id.major, id.minor);
  out += fmt::format("  serial        0x{:08X}\n", id.serial);
  out += fmt::format("  status        {}\n", cip::describe_identity_status(id.status));
  out += fmt::format("  product name  \"{}\"\n", id.product_name);
  if (id.state != 0xFF) out += fmt::format("  state         {}\n", id.state);
  for (const auto& sv : r.services)
    out += fmt::format("  service       \"{}\" version {}, capability 0x{:04X}\n", sv.name, sv.version, sv.capability);
  out += "assemblies (instance: bytes)\n";
  for (const auto& a : r.assemblies) out += fmt::format("  {:>5}: {}\n", a.instance, a.size);
  if (r.assemblies.empty()) out += "  none readable\n";
  if (!r.assemblies_note.empty()) out += fmt::format("  ({})\n", r.assemblies_note);
  if (!cli.library.empty()) {
    out += fmt::format("library {}\n", cli.library);
    for (const auto& m : lib)
      out += fmt::format("  {:<10}  {}  (revision {}.{})\n", live::to_string(m.verdict), m.path, m.major, m.minor);
    if (lib.empty()) out += "  no EDS file of this vendor, device type and product code\n";
  }
  return out;
}

// --upload-eds FILE: the device's own EDS from its File object, written by
// the output policy (io/output_target.hpp) as every output is; the bytes
// written, or the problem in words.
std::variant<std::size_t, std::string> upload_eds(const probe_cli& cli, const net::endpoint& to,
                                                  std::chrono::milliseconds timeout) {
  auto opened = live::client::open(to, timeout);
  if (!opened) return opened.error().message;
  auto& s = *opened;
  auto file = live::upload_file(s);
  s.close();
  if (!file) return "upload of the EDS from the device: " + file.error().message;
  const auto& bytes = *file;
  std::fflush(stdout);
  if (auto w =
          io::write_output(cli.upload_eds, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
      !w)
    return w.error().message;
  return bytes.size();
}

std::string render_probe_json(const probe_cli& cli, const live::probe_result& r,
                              const std::vector<library_match>& lib) {
  const auto& id = r.identity;
  nlohmann::ordered_json j;
  j["host"] = cli.host;
  j["source"] = r.identity_source;
  j["identity"] = {{"vendor_id", id.vendor},
                   {"device_type", id.device_type},
                   {"product_code", id.product_code},
                   {"revision", {{"major", id.major}, {"minor", id.minor}}},
                   {"serial_number", id.serial},
                   {"status", id.status},
                   {"status_text", cip::describe_identity_status(id.status)},
                   {"product_name", id.product_name}};
  if (id.state != 0xFF) j["identity"]["state"] = id.state;
  j["services"] = nlohmann::ordered_json::array();
  for (const auto& sv : r.services)
    j["services"].push_back({{"name", sv.name}, {"version", sv.version}, {"capability", sv.capability}});
  j["assemblies"] = nlohmann::ordered_json::array();
  for (const auto& a : r.assemblies) j["assemblies"].push_back({{"instance", a.instance}, {"size", a.size}});
  if (!r.assemblies_note.empty()) j["assemblies_note"] = r.assemblies_note;
  if (!cli.library.empty()) {
    j["library"] = nlohmann::ordered_json::array();
    for (const auto& m : lib)
      j["library"].push_back({{"path", m.path},
                              {"vendor_name", m.vendor_name},
                              {"revision", {{"major", m.major}, {"minor", m.minor}}},
                              {"keying", live::to_string(m.verdict)}});
  }
  return j.dump(2) + "\n";
}

int run_probe(const probe_cli& cli) {
  // A library that cannot be read is a usage error, found before the device is asked.
  io::collected_inputs library;
  if (!cli.library.empty()) {
    library = io::collect_inputs({cli.library});
    for (const auto& e : library.errors) print_error(fmt::format("--library {}", e.message));
    if (!library.errors.empty()) return exit_failure;
  }
  const auto to = device_address(cli.host);
  if (!to) return exit_failure;
  live::probe_options opt;
  opt.timeout = timeout_ms(cli.timeout_s);
  opt.udp = cli.udp;
  // A first pass learns the identity; the library's instances join the scan.
  auto r = live::probe(*to, opt);
  if (!r) {
    print_device_error(cli.host, r.error());
    return exit_failure;
  }
  auto& result = *r;
  std::vector<library_match> lib;
  if (!cli.library.empty()) {
    lib = match_library(library, result.identity);
    std::vector<std::uint32_t> named;
    for (const auto& m : lib) named.insert(named.end(), m.instances.begin(), m.instances.end());
    if (!named.empty() && !result.assemblies_note.empty()) {
      opt.extra_instances = named;
      auto again = live::probe(*to, opt);
      if (!again) {
        print_device_error(cli.host, again.error());
        return exit_failure;
      }
      result = *again;
    }
  }
  std::optional<std::variant<std::size_t, std::string>> uploaded;
  if (!cli.upload_eds.empty()) uploaded = upload_eds(cli, *to, opt.timeout);
  auto text = cli.format == "json" ? render_probe_json(cli, result, lib) : render_probe_text(cli, result, lib);
  if (uploaded && std::holds_alternative<std::size_t>(*uploaded)) {
    const auto n = std::get<std::size_t>(*uploaded);
    if (cli.format == "json") {
      auto j = nlohmann::ordered_json::parse(text);
      j["eds_upload"] = {{"path", cli.upload_eds}, {"size", n}};
      text = j.dump(2) + "\n";
    } else {
      text += fmt::format("eds upload      {} from File object instance 0x{:X} to {}\n", plural(n, "byte"),
                          live::eds_file_instance, io::is_stdout(cli.upload_eds) ? "standard output" : cli.upload_eds);
    }
  }
  // The EDS on standard output keeps it clean: the report goes to standard error.
  std::FILE* report = io::is_stdout(cli.upload_eds) ? stderr : stdout;
  if (!write_all(report, text)) return exit_failure;
  std::fflush(report);
  if (uploaded && std::holds_alternative<std::string>(*uploaded)) {
    print_error(std::get<std::string>(*uploaded));
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace

void register_probe(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<probe_cli>();
  auto* cmd = app.add_subcommand(
      "probe", "Ask a running EtherNet/IP device who it is and how large its assemblies are (docs/live.md)");
  takes(cmd->add_option("host", cli->host, "The device's address (only this address is contacted)"), arg_kind::host)
      ->required();
  takes(cmd->add_option("--library", cli->library,
                        "A folder of EDS files: list those that describe the device, with "
                        "the keying verdict (exact, compatible, none)"),
        arg_kind::dir)
      ->type_name("DIR");
  add_choice(cmd, "--format", cli->format, {"text", "json"}, "Output format: text (the default) or json");
  add_seconds(cmd, "--timeout", cli->timeout_s, 0.05, 600.0, "Seconds to wait for each answer (default 3)");
  cmd->add_flag("--udp", cli->udp, "Ask the identity by UDP ListIdentity (unicast) instead of TCP");
  takes(cmd->add_option("--upload-eds", cli->upload_eds,
                        "Upload the device's own EDS from its File object (class 0x37, instance 0xC8) into FILE "
                        "('-': standard output, the report then going to standard error)"),
        arg_kind::output)
      ->type_name("FILE");
  add_example(cmd, "edsc probe 198.51.100.20 --library eds/", "who the device is, and which EDS files describe it");
  add_example(cmd, "edsc probe 198.51.100.20 --upload-eds device.eds", "save the EDS the device carries");
  cmd->callback([&run, cli] { run = [cli] { return run_probe(*cli); }; });
}

}  // namespace edsc::driver
