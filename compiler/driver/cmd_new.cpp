#include <algorithm>
#include <functional>
#include <memory>

#include <fmt/format.h>

#include "diag/render_text.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "edit/analyze.hpp"
#include "edit/edit_error.hpp"
#include "edit/new_device.hpp"

namespace edsc::driver {

namespace {

using spec_copy = std::function<void(edit::device_spec& to, const edit::device_spec& from)>;

// An option that sets one fact of the device, and how to carry its value
// over a spec read with --from: the command line wins over the file.
struct spec_field {
  CLI::Option* option;
  spec_copy copy;
};

template <typename T>
spec_copy copier(T edit::device_spec::*member) {
  return [member](edit::device_spec& to, const edit::device_spec& from) { to.*member = from.*member; };
}

// `--product-code` is "product_code" in the JSON description.
std::string json_key(std::string option) {
  option.erase(0, option.find_first_not_of('-'));
  std::replace(option.begin(), option.end(), '-', '_');
  return option;
}

struct new_options {
  edit::device_spec spec;
  std::vector<spec_copy> given;         // the facts given on the command line
  std::vector<std::string> given_keys;  // their JSON keys
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
  if (!opt.from.empty()) {
    // Read as every input is (io/read_file.hpp): a directory, a device or an
    // unreadable path is refused with why, `-` is standard input.
    const auto from = read_or_report(opt.from);
    if (!from) return exit_failure;
    // The file is a template: whatever the command line says wins, so a
    // build can pin the date or one file serve a family of products.
    auto spec = edit::spec_from_json(std::string(from->text()), opt.given_keys);
    if (!spec) {
      print_error(spec.error().what());
      return exit_failure;
    }
    for (const auto& copy : opt.given) copy(*spec, opt.spec);
    opt.spec = std::move(spec.value());
  }
  const auto text = edit::make_eds(opt.spec, opt.eol == "crlf" ? "\r\n" : "\n");
  if (!text) {
    print_error(text.error().what());
    return exit_failure;
  }
  // Whatever was asked for, the result must check clean before it is written.
  const auto a = edit::analyze(opt.output.empty() ? "<new>" : opt.output, *text);
  std::string report;
  for (const auto& d : a->diags)
    render_text(*a->source, d, text_style{use_color(color_mode::auto_detect, stderr)}, report);
  write_all(stderr, report);
  if (a->errors() > 0 && !opt.force) {
    print_error("the new file would have the errors above; nothing written (--force writes anyway)");
    return exit_findings;
  }
  return write_result(opt.output.empty() ? std::string("-") : opt.output, *text);
}

}  // namespace

void register_new(CLI::App& app, command_action& run) {
  auto opt = std::make_shared<new_options>();
  auto fields = std::make_shared<std::vector<spec_field>>();
  auto& s = opt->spec;
  auto* cmd = app.add_subcommand("new", "Write a complete, valid, formatted EDS for a new device");
  auto* from = takes(cmd->add_option("--from", opt->from,
                                     "Read the device description from a JSON file (docs/authoring.md); options "
                                     "given with it replace the file's values"),
                     arg_kind::json);
  // Text facts; the numbers are 16-bit (identity) or sizes of up to 65535 bytes.
  const auto add = [&](const std::string& name, auto member, const std::string& help) {
    auto* o = takes(cmd->add_option(name, s.*member, help), arg_kind::text);
    fields->push_back({o, copier(member)});
    return o;
  };
  const auto add_u16 = [&](const std::string& name, std::uint32_t edit::device_spec::*member, const std::string& help) {
    auto* o = add_number(cmd, name, s.*member, 0u, 65535u, help);
    fields->push_back({o, copier(member)});
    return o;
  };
  auto* vendor = add_u16("--vendor", &edit::device_spec::vendor, "Vendor ID (ODVA-assigned)");
  auto* type = add_u16("--product-type", &edit::device_spec::product_type,
                       "Product type (7 discrete I/O, 100 vendor specific...)");
  auto* code = add_u16("--product-code", &edit::device_spec::product_code, "Product code");
  auto* name = add("--name", &edit::device_spec::name, "Product name");
  add("--vendor-name", &edit::device_spec::vendor_name, "Vendor name (default: \"Vendor <id>\")");
  add("--product-type-name", &edit::device_spec::product_type_name, "Product type text (default: the usual name)");
  add("--catalog", &edit::device_spec::catalog, "Catalog number");
  add("--description", &edit::device_spec::description, "[File] DescText");
  add("--revision", &edit::device_spec::revision, "Device revision major.minor (default 1.1)");
  fields->push_back({add_choice(cmd, "--network", s.network, {"devicenet", "ethernetip"},
                                "The device's network (default: devicenet)"),
                     copier(&edit::device_spec::network)});
  auto* input = add_u16("--input-bytes", &edit::device_spec::input, "Input bytes (produced by the device)");
  add_u16("--output-bytes", &edit::device_spec::output, "Output bytes (consumed by the device)");
  // The spelling before --input-bytes, kept for scripts (hidden). The old
  // --output N became -o's long form, which every other command uses.
  auto* old_input = add_u16("--input", &edit::device_spec::input, "")->group("");
  add("--connections", &edit::device_spec::connections,
      "DeviceNet connections, first is the default: poll,strobe,cos,cyclic")
      ->delimiter(',');
  add("--input-name", &edit::device_spec::input_name, "Name of the input data");
  add("--output-name", &edit::device_spec::output_name, "Name of the output data");
  add("--input-help", &edit::device_spec::input_help, "Help text of the input data");
  add("--output-help", &edit::device_spec::output_help, "Help text of the output data");
  add("--date", &edit::device_spec::date, "Creation date mm-dd-yyyy (default: today), for reproducible builds");
  add("--time", &edit::device_spec::time, "Creation time hh:mm:ss (default: 00:00:00 with --date, else now)");
  add_choice(cmd, "--eol", opt->eol, {"lf", "crlf"}, "Line endings (default: lf)");
  auto* output =
      takes(cmd->add_option("-o,--output", opt->output, "Write the file here ('-': standard output, the default)"),
            arg_kind::output);
  auto* old_output = cmd->add_option("--output-file", opt->output)->group("");  // -o's old long form (hidden)
  cmd->add_flag("--force", opt->force, "Write even when the result has errors");
  add_example(cmd,
              "edsc new --vendor 65535 --product-type 7 --product-code 2 --name 'Sensor' --input-bytes 3 -o sensor.eds",
              "start the EDS of a new DeviceNet node");
  struct spelling {
    CLI::Option *old_option, *option;
    const char *old_name, *name;
  };
  const std::vector<spelling> renamed{{old_input, input, "--input", "--input-bytes"},
                                      {old_output, output, "--output-file", "-o/--output"}};
  cmd->callback([&run, opt, fields, renamed, vendor, type, code, name, from] {
    // Both spellings at once would leave one of the two values unused.
    for (const auto& r : renamed)
      if (r.old_option->count() > 0 && r.option->count() > 0)
        throw CLI::ValidationError(fmt::format("{} is the old spelling of {}: give one of them", r.old_name, r.name));
    if (from->count() == 0) {
      for (auto* o : {vendor, type, code, name})
        if (o->count() == 0) throw CLI::RequiredError(o->get_name() + " (or --from)");
    }
    for (const auto& f : *fields)
      if (f.option->count() > 0) {
        opt->given.push_back(f.copy);
        opt->given_keys.push_back(json_key(f.option->get_name()));
      }
    run = [opt] { return run_new(*opt); };
  });
}

}  // namespace edsc::driver
