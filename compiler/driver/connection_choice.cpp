// The connection a user names, and the file it is read from
// (connection_choice.hpp).
#include "driver/connection_choice.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "connections/fields.hpp"
#include "diag/render_text.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "lower/lower.hpp"

namespace edsc::driver::connection_choice {

namespace {

// A name as the EDS writes it, without the blanks some vendors pad it with
// ("Exclusive Owner ").
std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

bool names(const connections::connection_setting& s, std::string_view which) {
  std::string_view n = which;
  // One rule with --set's parameter names: any case, `_` for a blank.
  using connections::same_name;
  if (n.size() > 10 && same_name(n.substr(0, 10), "connection")) n.remove_prefix(10);
  if (!n.empty() && n.find_first_not_of("0123456789") == std::string_view::npos && n.size() <= 9)
    return std::stoul(std::string(n)) == s.number;
  return same_name(trimmed(which), trimmed(s.name));
}

std::string listed(const std::vector<connections::connection_setting>& all) {
  std::string out;
  for (const auto& s : all) out += fmt::format("{}Connection{} \"{}\"", out.empty() ? "" : ", ", s.number, s.name);
  return out;
}

int report(const source_file& src, diag_id id, span where, std::string message) {
  std::string out;
  render_text(src, make_diagnostic(id, where, std::move(message)),
              text_style{use_color(color_mode::auto_detect, stderr)}, out);
  write_all(stderr, out);
  return exit_findings;
}

bool report_syntax(const source_file& src, const diagnostics& diags) {
  std::string out;
  for (const auto& d : diags)
    if (d.level == severity::error && rule_of(d.id).group == "syntax")
      render_text(src, d, text_style{use_color(color_mode::auto_detect, stderr)}, out);
  write_all(stderr, out);
  return !out.empty();
}

result<std::unique_ptr<connection_file>, int> read_connections(const std::string& path) {
  auto f = std::make_unique<connection_file>();
  f->src = read_or_report(path);
  if (!f->src) return fail(int{exit_failure});
  const auto& src = *f->src;
  f->parsed = parse(src);
  if (report_not_text(f->parsed, src)) return fail(int{exit_findings});
  if (report_syntax(src, f->parsed.diags)) {
    print_error(fmt::format("{}: no settings: fix the syntax errors above first", src.path()));
    return fail(int{exit_findings});
  }
  diagnostics diags;
  f->dev = lower(f->parsed.tree, diags);
  f->all = connections::describe_connections(f->dev);
  if (f->all.empty())
    return fail(report(src, diag_id::settings_no_connections, {0, 0},
                       "no ConnectionN in [Connection Manager]: the EDS describes no EtherNet/IP connection"));
  return f;
}

result<const connections::connection_setting*, int> pick(const connection_file& f, std::string_view which) {
  const auto it = std::find_if(f.all.begin(), f.all.end(), [&](const auto& s) { return names(s, which); });
  if (it == f.all.end())
    return fail(report(*f.src, diag_id::settings_unknown_connection, f.all.front().at,
                       fmt::format("no connection '{}' here; the file has {}", which, listed(f.all))));
  return &*it;
}

}  // namespace edsc::driver::connection_choice
