#include "driver/usage_error.hpp"

#include <cctype>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "driver/suggest.hpp"

namespace edsc::driver {

namespace {

// CLI11's texts are read, not trusted to have a shape: a part that is not
// where it should be leaves the text as it was.
struct reading {
  const CLI::App& cmd;
  const std::string& what;

  // The text after `before` up to `after` (to the end when `after` is empty).
  [[nodiscard]] std::optional<std::string> between(std::string_view before, std::string_view after) const {
    const auto from = what.find(before);
    if (from == std::string::npos) return std::nullopt;
    const auto start = from + before.size();
    if (after.empty()) return what.substr(start);
    const auto end = what.find(after, start);
    if (end == std::string::npos) return std::nullopt;
    return what.substr(start, end - start);
  }
  [[nodiscard]] std::size_t number_after(std::string_view label) const {
    const auto n = between(label, "");
    return n ? static_cast<std::size_t>(std::strtoull(n->c_str(), nullptr, 10)) : 0;
  }
  // An option as --help names it ("-o/--output"), a positional by its name;
  // `name` as CLI11 wrote it when the command has no such option.
  [[nodiscard]] std::string shown(const std::string& name) const {
    const auto* opt = cmd.get_option_no_throw(name);
    if (opt == nullptr) return name;
    std::string out;
    for (const auto& s : opt->get_snames()) out += (out.empty() ? "-" : "/-") + s;
    for (const auto& l : opt->get_lnames()) out += (out.empty() ? "--" : "/--") + l;
    return out.empty() ? opt->get_name(true) : out;
  }
};

// "net map"; "edsc" at the top.
std::string path_of(const CLI::App& cmd) {
  std::string path;
  for (const auto* c = &cmd; c->get_parent() != nullptr; c = c->get_parent())
    path = path.empty() ? c->get_name() : c->get_name() + " " + path;
  return path.empty() ? "edsc" : path;
}

// "edsc net map --help".
std::string help_command(const CLI::App& cmd) {
  const auto path = path_of(cmd);
  return path == "edsc" ? "edsc --help" : "edsc " + path + " --help";
}

// An option's help text, its first letter in lower case unless it starts a
// word in capitals ("EDS files").
std::string description_of(const CLI::Option* opt) {
  std::string h = opt == nullptr ? "" : opt->get_description();
  if (h.size() > 1 && std::isupper(static_cast<unsigned char>(h[0])) && !std::isupper(static_cast<unsigned char>(h[1])))
    h[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(h[0])));
  return h;
}

std::string words_list(const std::vector<std::string>& words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i)
    out += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return out;
}

// "A subcommand is required", "X is required".
std::string missing(const reading& r) {
  const auto name = r.what.substr(0, r.what.rfind(" is required"));
  const auto path = path_of(r.cmd);
  if (name == "A subcommand") {
    std::vector<std::string> names;
    for (const auto* s : r.cmd.get_subcommands([](const CLI::App* a) { return !a->get_group().empty(); }))
      names.push_back(s->get_name());
    if (names.size() > 5) return fmt::format("{} needs a command ({} lists them)", path, help_command(r.cmd));
    return fmt::format("{} needs a command: {}", path, words_list(names));
  }
  const auto help = description_of(r.cmd.get_option_no_throw(name));
  return fmt::format("{} needs {}{}", path, r.shown(name), help.empty() ? "" : ": " + help);
}

// ArgumentMismatch: too many values, too few, none.
std::optional<std::string> value_count(const reading& r) {
  if (const auto name = r.between(" arguments to ", ", got ")) {
    const bool exactly = r.what.starts_with("Expected exactly ");
    const auto want = r.number_after(exactly ? "exactly " : "at least ");
    return fmt::format("{} takes {}{}, given {}", r.shown(*name), exactly ? "" : "at least ", plural(want, "value"),
                       r.number_after(", got "));
  }
  if (const auto name = r.between("", " was given a disallowed flag override"))
    return fmt::format("{} takes no value", r.shown(*name));
  const auto name = r.between("", ": ");
  if (!name) return std::nullopt;
  const auto got = r.number_after(" received ");
  if (r.between(": At Most ", "")) {
    const auto most = r.number_after(": At Most ");
    if (most == 1) return fmt::format("{} is given {}; give it once", r.shown(*name), plural(got, "time"));
    return fmt::format("{} takes at most {}, given {}", r.shown(*name), plural(most, "value"), got);
  }
  if (r.between(": At least ", ""))
    return fmt::format("{} takes at least {}, given {}", r.shown(*name), plural(r.number_after(": At least "), "value"),
                       got);
  if (const auto type = r.between(" required ", " missing"))
    return fmt::format("{} needs a value{}", r.shown(*name), type->empty() ? "" : fmt::format(" ({})", *type));
  return std::nullopt;
}

// ConversionError: a value the option's type does not read.
std::optional<std::string> conversion(const reading& r) {
  if (const auto name = r.between("Could not convert: ", " = ")) {
    const auto* opt = r.cmd.get_option_no_throw(*name);
    const auto value = r.between(" = ", "").value_or("");
    if (opt != nullptr && opt->get_items_expected_max() == 0)
      return fmt::format("{} takes no value (given '{}')", r.shown(*name), value);
    return fmt::format("{}: '{}' is not a valid value", r.shown(*name), value);
  }
  if (const auto value = r.between("The value ", " is not an allowed value for "))
    return fmt::format("{}: '{}' is not allowed", r.shown(*r.between(" is not an allowed value for ", "")), *value);
  if (const auto name = r.between("", ": ")) return fmt::format("{} takes no value", r.shown(*name));
  return std::nullopt;
}

// The words no option or positional took.
std::string extras(const reading& r) {
  std::vector<std::string> words;
  for (const auto* c = &r.cmd; c != nullptr && words.empty(); c = c->get_parent()) words = c->remaining(false);
  if (words.empty()) words.push_back(r.between(": ", "").value_or(r.what));
  std::string list;
  for (const auto& w : words) list += (list.empty() ? "'" : ", '") + w + "'";
  return fmt::format("unexpected {} {} ({} lists what it takes)", noun(words.size(), "argument", "arguments"), list,
                     help_command(r.cmd));
}

// `-q=3`: CLI11 reads -q, then the word '-=3'. A short flag given a value
// is said as --json=maybe is.
std::optional<std::string> short_flag_value(const reading& r, int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--") break;
    if (arg.size() < 3 || arg[0] != '-' || arg[1] == '-' || arg[2] != '=') continue;
    const auto name = std::string("-") + arg[1];
    const auto* opt = r.cmd.get_option_no_throw(name);
    if (opt != nullptr && opt->get_items_expected_max() == 0)
      return fmt::format("{} takes no value (given '{}')", r.shown(name), arg.substr(3));
  }
  return std::nullopt;
}

// By type, not by get_name(): CLI11 names some errors after the command
// that threw them.
template <typename T>
bool is(const CLI::ParseError& e) {
  return dynamic_cast<const T*>(&e) != nullptr;
}

std::optional<std::string> rewritten(const CLI::ParseError& e, const reading& r) {
  if (is<CLI::RequiredError>(e)) return missing(r);
  if (is<CLI::ArgumentMismatch>(e)) return value_count(r);
  if (is<CLI::ConversionError>(e)) return conversion(r);
  if (is<CLI::ExtrasError>(e)) return extras(r);
  if (is<CLI::ExcludesError>(e) || is<CLI::RequiresError>(e)) {
    const bool excludes = is<CLI::ExcludesError>(e);
    const auto a = r.between("", excludes ? " excludes " : " requires ");
    const auto b = r.between(excludes ? " excludes " : " requires ", "");
    if (!a || !b) return std::nullopt;
    if (excludes) return fmt::format("{} and {} cannot be given together", r.shown(*a), r.shown(*b));
    return fmt::format("{} needs {}", r.shown(*a), r.shown(*b));
  }
  if (is<CLI::ValidationError>(e)) {
    // "NAME: " and the validator's own words ("'x' is not one of text|json|sarif").
    if (const auto name = r.between("", ": ")) return r.shown(*name) + r.what.substr(name->size());
  }
  return std::nullopt;  // the others cannot come from edsc's options
}

}  // namespace

std::string usage_message(const CLI::ParseError& e, const CLI::App& app, int argc, const char* const* argv) {
  if (auto hint = option_hint(app, argc, argv)) return *hint;
  const std::string what = e.what();
  const reading r{command_named(app, argc, argv), what};
  if (is<CLI::ExtrasError>(e))
    if (auto flag = short_flag_value(r, argc, argv)) return *flag;
  return rewritten(e, r).value_or(what);
}

}  // namespace edsc::driver
