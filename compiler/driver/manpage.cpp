#include "driver/manpage.hpp"

#include <fmt/format.h>

#include "diag/catalogue.hpp"
#include "edsc_install_dirs.hpp"

namespace edsc::driver {

namespace {

// Text as roff reads it: a backslash is \e, a hyphen in an option name
// \-, and a line may not start with a control character.
std::string roff(std::string_view text) {
  std::string out;
  bool line_start = true;
  for (const char c : text) {
    if (line_start && (c == '.' || c == '\'')) out += "\\&";
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else
      out += c;
    line_start = c == '\n';
  }
  return out;
}

std::string page_name(const cli_command& c) {
  std::string name = "edsc";
  for (const char ch : c.path) name += ch == ' ' ? '-' : ch;
  if (!c.path.empty()) name.insert(4, "-");
  return name;
}

void add_synopsis(const cli_command& c, std::string& out) {
  out += fmt::format(".SH SYNOPSIS\n.B edsc{}{}\n", c.path.empty() ? "" : " ", roff(c.path));
  if (!c.subcommands.empty()) {
    out += "\\fICOMMAND\\fR [\\fIOPTIONS\\fR]\n";
    return;
  }
  out += "[\\fIOPTIONS\\fR]";
  for (const auto& o : c.options) {
    if (!o.positional) continue;
    const auto word = fmt::format("\\fI{}\\fR{}", roff(o.name), o.repeats ? "..." : "");
    out += o.required ? " " + word : " [" + word + "]";
  }
  out += "\n";
}

void add_options(const cli_command& c, std::string& out) {
  bool any = false;
  for (const auto& o : c.options) {
    if (!any) out += ".SH OPTIONS\n";
    any = true;
    std::string names;
    if (o.positional) names = fmt::format("\\fI{}\\fR", roff(o.name));
    for (const auto& n : o.shorts) names += (names.empty() ? "" : ", ") + fmt::format("\\fB{}\\fR", roff(n));
    for (const auto& n : o.longs) names += (names.empty() ? "" : ", ") + fmt::format("\\fB{}\\fR", roff(n));
    if (!o.positional && o.takes_value) names += fmt::format(" \\fI{}\\fR", roff(o.value_name));
    out += fmt::format(".TP\n{}\n{}\n", names, roff(o.help));
  }
  out += ".TP\n\\fB\\-h\\fR, \\fB\\-\\-help\\fR\nPrint the options and exit.\n";
}

const char* exit_status =
    ".SH EXIT STATUS\n"
    ".TP\n0\nSuccess: no errors (warnings allowed).\n"
    ".TP\n1\nThe input has errors (diagnostics were printed), or what was compared disagrees.\n"
    ".TP\n2\nUsage error or I/O failure: a bad option, a missing or unreadable file, an output that would "
    "overwrite an input.\n";

// What each command registered (cli_model.hpp, add_example).
void add_examples(const cli_command& c, std::string& out) {
  if (c.examples.empty()) return;
  out += ".SH EXAMPLES\n";
  for (const auto& e : c.examples) {
    std::string what = e.what;
    what[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(what[0])));
    out += fmt::format(".TP\n.B {}\n{}.\n", roff(e.command), roff(what));
  }
}

void add_see_also(const cli_command& top, const cli_command& c, std::string& out) {
  std::vector<std::string> refs;
  if (&top != &c) refs.push_back("\\fBedsc\\fR(1)");
  for (const auto& s : top.subcommands) {
    if (s.subcommands.empty()) {
      if (s.path != c.path) refs.push_back(fmt::format("\\fB{}\\fR(1)", roff(page_name(s))));
      continue;
    }
    for (const auto& n : s.subcommands)
      if (n.path != c.path) refs.push_back(fmt::format("\\fB{}\\fR(1)", roff(page_name(n))));
  }
  out += ".SH SEE ALSO\n";
  for (std::size_t i = 0; i < refs.size(); ++i) out += refs[i] + (i + 1 < refs.size() ? ",\n" : "\n");
  out += fmt::format(".PP\nThe documentation in {}/ (cli.md is the command reference).\n", roff(EDSC_INSTALL_DOCDIR));
}

std::string rule_list() {
  std::string out = ".SH DIAGNOSTICS\nEvery diagnostic edsc reports, with its default severity and group:\n";
  for (const auto& r : all_rules())
    out += fmt::format(".TP\n\\fB{}\\fR ({}, {})\n{}\n", roff(r.name), to_string(r.default_level), roff(r.group),
                       roff(r.summary));
  return out;
}

// The summary without the program's name in front ("edsc: a compiler for
// ..." at the top), since NAME already starts with it.
std::string_view summary_of(const cli_command& c) {
  std::string_view s = c.summary;
  if (s.starts_with("edsc: ")) s.remove_prefix(6);
  return s;
}

std::string page(const cli_command& top, const cli_command& c, const std::string& version) {
  const auto name = page_name(c);
  std::string upper;
  for (const char ch : name) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  std::string out = fmt::format(".TH {} 1 \"\" \"edsc {}\" \"edsc manual\"\n", roff(upper), roff(version));
  out += fmt::format(".SH NAME\n{} \\- {}\n", roff(name), roff(summary_of(c)));
  add_synopsis(c, out);
  out += ".SH DESCRIPTION\n" + roff(summary_of(c)) + ".\n";
  if (!c.subcommands.empty()) {
    out += ".SH COMMANDS\n";
    for (const auto& s : c.subcommands)
      out +=
          fmt::format(".TP\n\\fB{}\\fR\n{}. See \\fB{}\\fR(1).\n", roff(s.name), roff(s.summary), roff(page_name(s)));
  }
  add_options(c, out);
  out += exit_status;
  add_examples(c, out);
  if (c.path == "rules") out += rule_list();
  if (c.path.empty())
    out += ".SH ENVIRONMENT\n.TP\nNO_COLOR\n" +
           roff("Set to anything but the empty string, text is not coloured unless --color always asks for it.") + "\n";
  out += fmt::format(".SH FILES\n.TP\n{}/\nThe user documentation.\n", roff(EDSC_INSTALL_DOCDIR));
  if (c.path == "header")
    out += fmt::format(".TP\n{}/edsc/templates/\nThe built-in header templates, a start for --template-dir.\n",
                       roff(EDSC_INSTALL_DATADIR));
  add_see_also(top, c, out);
  return out;
}

void collect(const cli_command& top, const cli_command& c, const std::string& version,
             std::vector<std::pair<std::string, std::string>>& out) {
  out.emplace_back(page_name(c) + ".1", page(top, c, version));
  for (const auto& s : c.subcommands) collect(top, s, version, out);
}

}  // namespace

std::vector<std::pair<std::string, std::string>> man_pages(const cli_command& top, const std::string& version) {
  std::vector<std::pair<std::string, std::string>> out;
  collect(top, top, version, out);
  return out;
}

}  // namespace edsc::driver
