// edsc explain CODE...: a reply's status codes in words, with what usually
// causes each and what to look at in the EDS (cip/explain.hpp, from the
// columns of cip/codes.def); with --eds and --connection, the field of that
// connection each extended status points at, with its numbers
// (connections/status_site.hpp).
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cip/explain.hpp"
#include "connections/status_site.hpp"
#include "driver/choice.hpp"
#include "driver/cli_model.hpp"
#include "driver/commands.hpp"
#include "driver/connection_choice.hpp"
#include "driver/output.hpp"

namespace edsc::driver {

namespace {

struct explain_cli {
  std::vector<std::string> codes;
  std::string format = "text";
  std::string eds, which;                 // --eds FILE --connection N|NAME
  std::optional<std::uint16_t> accepted;  // --additional: the reply's word after the extended status
};

// Where each status points in the EDS, beside it; none for a status the EDS
// plays no part in, and for every status without --eds.
struct located {
  connections::status_site site;
  line_col at;
};
using sites = std::vector<std::optional<located>>;

// A status code as typed, a whole number as every option takes one (0 to
// 0xFFFF); the error says why `typed` is none.
result<std::uint16_t, std::string> code_of(const std::string& typed) {
  const auto v = whole_number(typed);
  if (!v || *v < 0 || *v > 0xFFFF)
    return fail(
        fmt::format("'{}' is not a status code: a whole number from 0 to 0xFFFF, decimal or hexadecimal "
                    "with 0x (general statuses up to 0xFF, extended ones above)",
                    typed));
  return static_cast<std::uint16_t>(*v);
}

// `label` and `text`, the text's words wrapped at 80 columns under its first.
std::string wrapped(std::string_view label, std::string_view text) {
  constexpr std::size_t width = 80;
  std::string out(label);
  std::size_t column = label.size(), at = 0;
  bool line_empty = true;
  while (at < text.size()) {
    const auto end = std::min(text.find(' ', at), text.size());
    const auto word = text.substr(at, end - at);
    if (!line_empty && column + 1 + word.size() > width) {
      out += '\n' + std::string(label.size(), ' ');
      column = label.size();
      line_empty = true;
    }
    if (!line_empty) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    line_empty = false;
    at = end + 1;
  }
  return out + '\n';
}

std::string_view kind_words(cip::status_kind k) {
  return k == cip::status_kind::general ? "general status" : "extended status";
}

std::string render_text(const std::vector<cip::status_explanation>& all, const sites& here, std::string_view file) {
  std::string out;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& e = all[i];
    if (!e.known()) continue;
    if (!out.empty()) out += '\n';
    out += fmt::format("{} {} ({})\n", cip::hex_of(e), e.words, kind_words(e.kind));
    out += wrapped("  cause: ", e.cause);
    if (!e.eds.empty()) out += wrapped("  EDS:   ", e.eds);
    if (const auto& h = here[i])
      out += wrapped("  here:  ", fmt::format("{} line {}, {}: {}", file, h->at.line, h->site.field, h->site.words));
  }
  return out;
}

// One object a status, the same keys for each; null where a code is unknown
// or the EDS plays no part.
// With --eds, each object gains `here`: the field and line, or null.
std::string render_json(const std::vector<cip::status_explanation>& all, const sites& here, bool with_eds,
                        std::string_view file) {
  auto list = nlohmann::ordered_json::array();
  const auto text_or_null = [](std::string_view s) {
    return s.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(std::string(s));
  };
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& e = all[i];
    list.push_back({{"kind", e.kind == cip::status_kind::general ? "general" : "extended"},
                    {"code", e.code},
                    {"hex", cip::hex_of(e)},
                    {"known", e.known()},
                    {"words", text_or_null(e.words)},
                    {"cause", text_or_null(e.cause)},
                    {"eds", text_or_null(e.eds)}});
    if (!with_eds) continue;
    const auto& h = here[i];
    list.back()["here"] = h ? nlohmann::ordered_json{{"file", file},
                                                     {"line", h->at.line},
                                                     {"column", h->at.column},
                                                     {"field", h->site.field},
                                                     {"words", h->site.words}}
                            : nlohmann::ordered_json();
  }
  return nlohmann::ordered_json{{"statuses", list}}.dump(2) + "\n";
}

// --eds and --connection go together; --additional with them, after a
// status that carries the size the device accepts. Says why not, or empty.
std::string usage_problem(const explain_cli& cli, const std::vector<cip::status_explanation>& all) {
  if (cli.eds.empty() != cli.which.empty())
    return "--eds and --connection go together: a status is read against one connection of one EDS";
  if (cli.accepted && cli.eds.empty())
    return "--additional goes with --eds and --connection: it is compared with what the EDS says";
  const auto takes = [](const cip::status_explanation& e) {
    return e.kind == cip::status_kind::extended && connections::takes_accepted_size(cip::extended_status{e.code});
  };
  if (cli.accepted && std::none_of(all.begin(), all.end(), takes))
    return "--additional is the size the device accepts, which only the extended statuses 0x0126, 0x0127 and "
           "0x0128 carry";
  return {};
}

// Each extended status against the connection named.
sites sites_of(const explain_cli& cli, const std::vector<cip::status_explanation>& all,
               const connection_choice::connection_file& f, const connections::connection_setting& s) {
  sites out(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].kind != cip::status_kind::extended) continue;
    const cip::extended_status status{all[i].code};
    const auto accepted = connections::takes_accepted_size(status) ? cli.accepted : std::nullopt;
    if (auto site = connections::status_site_of(f.dev, f.src.get(), s, status, accepted))
      out[i] = located{*site, f.src->position(site->where.begin)};
  }
  return out;
}

int run_explain(const explain_cli& cli) {
  std::vector<std::uint16_t> codes;
  for (const auto& w : cli.codes) {
    const auto c = code_of(w);
    if (!c) {
      print_error(c.error());
      return exit_failure;
    }
    codes.push_back(c.value());
  }
  const auto read = cip::explain_codes(codes);
  if (!read) {
    print_error(read.error().what());
    return exit_failure;
  }
  const auto& all = read.value();
  if (const auto why = usage_problem(cli, all); !why.empty()) {
    print_error(why);
    return exit_failure;
  }
  sites here(all.size());
  std::string file;
  if (!cli.eds.empty()) {
    const auto f = connection_choice::read_connections(cli.eds);
    if (!f) return f.error();
    const auto s = connection_choice::pick(*f.value(), cli.which);
    if (!s) return s.error();
    here = sites_of(cli, all, *f.value(), *s.value());
    file = f.value()->src->path();
  }
  const auto text =
      cli.format == "json" ? render_json(all, here, !cli.eds.empty(), file) : render_text(all, here, file);
  if (!write_all(stdout, text) || std::fflush(stdout) != 0) return exit_failure;
  int status = exit_ok;
  for (const auto& e : all)
    if (!e.known()) {
      print_error(fmt::format("unknown {} {}", kind_words(e.kind), cip::hex_of(e)));
      status = exit_findings;
    }
  return status;
}

}  // namespace

void register_explain(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<explain_cli>();
  auto* cmd = app.add_subcommand("explain", "Say what a CIP status means, what usually causes it, what to check");
  takes(cmd->add_option("codes", cli->codes,
                        "Status codes (decimal or 0x hex): a general status, or 0x01 then an extended status")
            ->type_name("CODE"),
        arg_kind::text)
      ->required();
  add_choice(cmd, "--format", cli->format, {"text", "json"}, "What to write: text (default) or JSON");
  takes(cmd->add_option("--eds", cli->eds, "The EDS the connection was configured from (with --connection)")
            ->type_name("FILE"),
        arg_kind::eds);
  takes(
      cmd->add_option("--connection", cli->which,
                      "The connection refused: its number N (or ConnectionN) or its name, as edsc connection takes it")
          ->type_name("N|NAME"),
      arg_kind::text);
  add_number(cmd, "--additional", cli->accepted, std::uint16_t{0}, std::uint16_t{0xFFFF},
             "The reply's additional status word after 0x0126, 0x0127 or 0x0128: the size the device accepts");
  add_example(cmd, "edsc explain 0x01 0x0127", "a refused Forward_Open: the general status, then the extended one");
  add_example(cmd, "edsc explain 0x01 0x0127 --additional 0x0022 --eds device.eds --connection 1",
              "the same against Connection1 of device.eds: its O->T size field and numbers, and the size the device "
              "accepts");
  add_example(cmd, "edsc explain 0x05", "a general status alone");
  add_example(cmd, "edsc explain --format json 0x01 0x0127", "the same as JSON");
  cmd->callback([&run, cli] { run = [cli] { return run_explain(*cli); }; });
}

}  // namespace edsc::driver
