#include <fstream>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "diag/render_text.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "edit/analyze.hpp"
#include "edit/locate.hpp"
#include "edit/new_device.hpp"

namespace edsc::driver {

namespace {

struct new_options {
  edit::device_spec spec;
  std::string from;
  std::string output;
  std::string eol = "lf";
  bool force = false;
};

int run_new(new_options opt) {
  // `--output 4` meant four output bytes before --output-bytes existed; a
  // file named by digits alone is far more likely that old spelling.
  if (!opt.output.empty() && opt.output.find_first_not_of("0123456789") == std::string::npos) {
    print_error(fmt::format("-o/--output {} names the file to write; for {} output bytes use --output-bytes {}",
                            opt.output, opt.output, opt.output));
    return exit_failure;
  }
  if (!opt.from.empty() && refuse_input_as_output(opt.output, {opt.from}) != exit_ok) return exit_failure;
  try {
    if (!opt.from.empty()) {
      std::ifstream in(opt.from, std::ios::binary);
      if (!in) {
        print_error(fmt::format("{}: cannot read the device description", opt.from));
        return exit_failure;
      }
      std::stringstream ss;
      ss << in.rdbuf();
      auto spec = edit::spec_from_json(ss.str());
      // Command-line dates win, so a build can pin one for every file.
      if (!opt.spec.date.empty()) spec.date = opt.spec.date;
      if (!opt.spec.time.empty()) spec.time = opt.spec.time;
      opt.spec = std::move(spec);
    }
    const auto text = edit::make_eds(opt.spec, opt.eol == "crlf" ? "\r\n" : "\n");
    // Whatever was asked for, the result must check clean before it is written.
    const auto a = edit::analyze(opt.output.empty() ? "<new>" : opt.output, text);
    std::string report;
    for (const auto& d : a->diags) render_text(*a->source, d, text_style{use_color(color_mode::auto_detect, stderr)}, report);
    write_all(stderr, report);
    if (a->errors() > 0 && !opt.force) {
      print_error("the new file would have the errors above; nothing written (--force writes anyway)");
      return exit_findings;
    }
    return write_result(opt.output.empty() ? std::string("-") : opt.output, text);
  } catch (const edit::edit_error& e) {
    print_error(e.what());
    return exit_failure;
  }
}

}  // namespace

void register_new(CLI::App& app, command_action& run) {
  auto opt = std::make_shared<new_options>();
  auto& s = opt->spec;
  auto* cmd = app.add_subcommand("new", "Write a complete, valid, formatted EDS for a new device");
  auto* from = takes(cmd->add_option("--from", opt->from, "Read the device description from a JSON file (docs/authoring.md)"),
                     arg_kind::json);
  const std::uint32_t u16 = 65535;
  auto* vendor = add_number(cmd, "--vendor", s.vendor, 0u, u16, "Vendor ID (ODVA-assigned)");
  auto* type = add_number(cmd, "--product-type", s.product_type, 0u, u16, "Product type (7 discrete I/O, 100 vendor specific...)");
  auto* code = add_number(cmd, "--product-code", s.product_code, 0u, u16, "Product code");
  auto* name = takes(cmd->add_option("--name", s.name, "Product name"), arg_kind::text);
  for (auto* o : {vendor, type, code, name}) o->excludes(from);
  auto text = [cmd](const std::string& option, std::string& value, const std::string& help) {
    return takes(cmd->add_option(option, value, help), arg_kind::text);
  };
  text("--vendor-name", s.vendor_name, "Vendor name (default: \"Vendor <id>\")");
  text("--product-type-name", s.product_type_name, "Product type text (default: the usual name)");
  text("--catalog", s.catalog, "Catalog number");
  text("--description", s.description, "[File] DescText");
  text("--revision", s.revision, "Device revision major.minor (default 1.1)");
  add_choice(cmd, "--network", s.network, {"devicenet", "ethernetip"}, "The device's network (default: devicenet)");
  add_number(cmd, "--input-bytes", s.input, 0u, u16, "Input bytes (produced by the device)");
  add_number(cmd, "--output-bytes", s.output, 0u, u16, "Output bytes (consumed by the device)");
  // The spelling before --input-bytes, kept for scripts (hidden). The old
  // --output N became -o's long form, which every other command uses.
  add_number(cmd, "--input", s.input, 0u, u16, "")->group("");
  takes(cmd->add_option("--connections", s.connections,
                        "DeviceNet connections, first is the default: poll,strobe,cos,cyclic"),
        arg_kind::text)
      ->delimiter(',');
  text("--input-name", s.input_name, "Name of the input data");
  text("--output-name", s.output_name, "Name of the output data");
  text("--input-help", s.input_help, "Help text of the input data");
  text("--output-help", s.output_help, "Help text of the output data");
  text("--date", s.date, "Creation date mm-dd-yyyy (default: today), for reproducible builds");
  text("--time", s.time, "Creation time hh:mm:ss (default: 00:00:00 with --date, else now)");
  add_choice(cmd, "--eol", opt->eol, {"lf", "crlf"}, "Line endings (default: lf)");
  takes(cmd->add_option("-o,--output", opt->output, "Write the file here ('-': standard output, the default)"),
        arg_kind::output);
  cmd->add_option("--output-file", opt->output)->group("");  // -o's old long form (hidden)
  cmd->add_flag("--force", opt->force, "Write even when the result has errors");
  add_example(cmd, "edsc new --vendor 65535 --product-type 7 --product-code 2 --name 'Sensor' --input-bytes 3 -o sensor.eds",
              "start the EDS of a new DeviceNet node");
  cmd->callback([&run, opt, vendor, type, code, name, from] {
    if (from->count() == 0) {
      for (auto* o : {vendor, type, code, name})
        if (o->count() == 0) throw CLI::RequiredError(o->get_name() + " (or --from)");
    }
    run = [opt] { return run_new(*opt); };
  });
}

}  // namespace edsc::driver
