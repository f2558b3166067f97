// edsc explain CODE...: a reply's status codes in words, with what usually
// causes each and what to look at in the EDS (cip/explain.hpp, from the
// columns of cip/codes.def).
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cip/explain.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"

namespace edsc::driver {

namespace {

struct explain_cli {
  std::vector<std::string> codes;
  std::string format = "text";
};

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

std::string render_text(const std::vector<cip::status_explanation>& all) {
  std::string out;
  for (const auto& e : all) {
    if (!e.known()) continue;
    if (!out.empty()) out += '\n';
    out += fmt::format("{} {} ({})\n", cip::hex_of(e), e.words, kind_words(e.kind));
    out += wrapped("  cause: ", e.cause);
    if (!e.eds.empty()) out += wrapped("  EDS:   ", e.eds);
  }
  return out;
}

// One object a status, the same keys for each; null where a code is unknown
// or the EDS plays no part.
std::string render_json(const std::vector<cip::status_explanation>& all) {
  auto list = nlohmann::ordered_json::array();
  const auto text_or_null = [](std::string_view s) {
    return s.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(std::string(s));
  };
  for (const auto& e : all)
    list.push_back({{"kind", e.kind == cip::status_kind::general ? "general" : "extended"},
                    {"code", e.code},
                    {"hex", cip::hex_of(e)},
                    {"known", e.known()},
                    {"words", text_or_null(e.words)},
                    {"cause", text_or_null(e.cause)},
                    {"eds", text_or_null(e.eds)}});
  return nlohmann::ordered_json{{"statuses", list}}.dump(2) + "\n";
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
  if (!write_all(stdout, cli.format == "json" ? render_json(all) : render_text(all)) || std::fflush(stdout) != 0)
    return exit_failure;
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
  add_example(cmd, "edsc explain 0x01 0x0127", "a refused Forward_Open: the general status, then the extended one");
  add_example(cmd, "edsc explain 0x05", "a general status alone");
  add_example(cmd, "edsc explain --format json 0x01 0x0127", "the same as JSON");
  cmd->callback([&run, cli] { run = [cli] { return run_explain(*cli); }; });
}

}  // namespace edsc::driver
