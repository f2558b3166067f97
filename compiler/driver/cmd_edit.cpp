#include <map>
#include <memory>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "diag/render_text.hpp"
#include "driver/commands.hpp"
#include "driver/destination.hpp"
#include "driver/output.hpp"
#include "edit/analyze.hpp"
#include "edit/edit_error.hpp"
#include "edit/editor.hpp"
#include "io/read_file.hpp"

namespace edsc::driver {

namespace {

enum class op_kind { set, add_entry, remove_entry, add_section, remove_section, resize };

struct edit_options {
  destination dest;
  bool force = false;
  std::map<op_kind, std::vector<std::string>> values;
  std::map<const CLI::Option*, op_kind> kinds;
  std::vector<std::pair<op_kind, std::string>> ops;  // in command-line order
};

edit::edited apply_op(edit::editor& ed, op_kind k, const std::string& v) {
  switch (k) {
    case op_kind::set: return ed.set(v);
    case op_kind::add_entry: return ed.add_entry(v);
    case op_kind::remove_entry: return ed.remove_entry(v);
    case op_kind::add_section: return ed.add_section(v);
    case op_kind::remove_section: return ed.remove_section(v);
    case op_kind::resize: return ed.resize(v);
  }
  return {};
}

// Findings of `after` that `before` did not have (compared by rule and
// message, since positions move when text is inserted).
diagnostics introduced(const diagnostics& before, const diagnostics& after) {
  std::multimap<std::pair<diag_id, std::string>, int> seen;
  for (const auto& d : before) seen.emplace(std::pair{d.id, d.message}, 0);
  diagnostics out;
  for (const auto& d : after) {
    const auto it = seen.find({d.id, d.message});
    if (it != seen.end())
      seen.erase(it);
    else
      out.push_back(d);
  }
  return out;
}

int run_edit(const edit_options& opt) {
  if (const int rc = opt.dest.refuse_overwrite(); rc != exit_ok) return rc;
  const auto input_file = opt.dest.read();
  if (!input_file) return exit_failure;
  const auto& src = *input_file;
  const auto before = edit::analyze(src.path(), std::string(src.text()));
  const text_style style{use_color(color_mode::auto_detect, stderr)};
  std::string report;
  // A tree with syntax errors cannot be edited reliably.
  for (const auto& d : before->syntax) render_text(*before->source, d, style, report);
  write_all(stderr, report);
  if (before->has_syntax_errors() && !opt.force) {
    print_error(fmt::format("{}: not written because of the syntax errors above; --force writes anyway",
                            opt.dest.target_name()));
    return exit_findings;
  }

  edit::editor ed(src.path(), std::string(src.text()));
  for (const auto& [kind, value] : opt.ops) {
    if (auto done = apply_op(ed, kind, value); !done) {
      print_error(done.error().what());
      return exit_failure;
    }
  }
  report.clear();
  for (const auto& line : ed.log()) report += line + "\n";

  if (!opt.ops.empty()) {
    const auto after = edit::analyze(src.path(), ed.text());
    const auto fresh = introduced(before->diags, after->diags);
    // Located in the edited text, so named after where that text goes.
    for (const auto& d : fresh) render_text(*after->source, opt.dest.target_name(), d, style, report);
    const auto old_errors = before->errors();
    if (old_errors > 0)
      report += fmt::format("note: the input already had {} (see edsc check); only new ones block the write\n",
                            plural(old_errors, "error"));
    write_all(stderr, report);
    if (count_at_least(fresh, severity::error) > 0 && !opt.force) {
      print_error(fmt::format("{}: not written: the edit introduces the errors above; --force writes anyway",
                              opt.dest.target_name()));
      return exit_findings;
    }
  }
  return opt.dest.write(ed.text());
}

}  // namespace

void register_edit(CLI::App& app, command_action& run) {
  auto opt = std::make_shared<edit_options>();
  auto* cmd = app.add_subcommand(
      "edit", "Make targeted changes to an EDS file; every byte outside the edited fields stays identical");
  opt->dest.add_options(*cmd, "The EDS file to edit");
  cmd->add_flag("--force", opt->force, "Write even when the result has errors");
  const std::pair<const char*, std::pair<op_kind, const char*>> ops[] = {
      {"--set", {op_kind::set, "Section.Keyword[.field]=value: set one field (by name or 1-based number)"}},
      {"--add-entry", {op_kind::add_entry, "Section.Keyword=fields: append an entry to a section"}},
      {"--remove-entry", {op_kind::remove_entry, "Section.Keyword: remove an entry"}},
      {"--add-section", {op_kind::add_section, "Name: add an empty section"}},
      {"--remove-section", {op_kind::remove_section, "Name: remove a section and its entries"}},
      {"--resize",
       {op_kind::resize,
        "InputN=bytes[:bits] or OutputN=...: resize DeviceNet I/O, keeping the old data set in "
        "[Variant_IO_Info]"}},
  };
  for (const auto& [name, what] : ops) {
    auto* o =
        takes(cmd->add_option(name, opt->values[what.first], what.second), arg_kind::text)->allow_extra_args(false);
    opt->kinds[o] = what.first;
  }
  add_example(cmd, "edsc edit device.eds --set Device.MajRev=2 --in-place", "change one field, nothing else");
  add_example(cmd, "edsc edit node.eds --resize Input1=3 -o node-3byte.eds", "give a DeviceNet input 3 bytes");
  cmd->callback([&run, opt, cmd] {
    // Operations run in the order they were written on the command line.
    std::map<op_kind, std::size_t> next;
    for (const auto* o : cmd->parse_order()) {
      const auto it = opt->kinds.find(o);
      if (it == opt->kinds.end()) continue;
      const auto k = it->second;
      opt->ops.emplace_back(k, opt->values[k][next[k]++]);
    }
    run = [opt] { return run_edit(*opt); };
  });
}

}  // namespace edsc::driver
