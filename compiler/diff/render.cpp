// The differences as text (compiler style, grouped) and as JSON (docs/diff.md,
// docs/diff-json.schema.json).
#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "diff/diff.hpp"
#include "emit/json_values.hpp"

namespace edsc::diff {

namespace {

constexpr group all_groups[] = {group::identity, group::io, group::parameters, group::connections, group::other};

// Control bytes would drive the terminal: shown as <XX>. Text that is not
// UTF-8 is read as Windows-1252, as in the JSON.
std::string safe(std::string_view s) {
  std::string out;
  for (const char ch : emit::detail::to_utf8(s)) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7F)
      out += fmt::format("<{:02X}>", c);
    else
      out += ch;
  }
  return out;
}

std::string location(const source_file& src, std::uint32_t offset) {
  const auto pos = src.position(offset);
  return fmt::format("{}:{}:{}", src.path(), pos.line, pos.column);
}

// Words wrapped to `width` columns after `indent`.
std::string wrap(std::string_view text, std::string_view indent, std::size_t width = 100) {
  std::string out, line(indent);
  std::size_t i = 0;
  while (i < text.size()) {
    auto j = text.find(' ', i);
    if (j == std::string_view::npos) j = text.size();
    const auto word = text.substr(i, j - i);
    if (line.size() > indent.size() && line.size() + 1 + word.size() > width) {
      out += line + '\n';
      line = std::string(indent.size(), ' ');
    } else if (line.size() > indent.size()) {
      line += ' ';
    }
    line += word;
    i = j + 1;
  }
  return out + line + '\n';
}

std::string identity_text(const identity_key& k) {
  auto n = [](const std::optional<std::uint64_t>& v) { return v ? fmt::format("{}", *v) : std::string("?"); };
  return fmt::format("vendor {}, device type {}, product code {}, revision {}.{}", n(k.vendor), n(k.device_type),
                     n(k.product_code), n(k.major), n(k.minor));
}

const char* colour_of(impact i) {
  switch (i) {
    case impact::breaking: return "\033[1;31m";
    case impact::additive: return "\033[1;32m";
    case impact::cosmetic: return "\033[1;36m";
  }
  return "";
}

}  // namespace

std::string render_text(const result& r, const analysis& before, const analysis& after, const text_options& style) {
  const char* bold = style.color ? "\033[1m" : "";
  const char* reset = style.color ? "\033[0m" : "";
  std::string out;
  if (r.differences.empty()) {
    return fmt::format("{} and {}: no difference between the two models\n", before.source->path(),
                       after.source->path());
  }
  const auto& k = r.keys;
  out += fmt::format("{}identity{}: {}{}\n", bold, reset, identity_text(k.before),
                     k.exact_match && k.compatible_match && identity_text(k.before) == identity_text(k.after)
                         ? " (unchanged)"
                         : " -> " + identity_text(k.after));
  out += fmt::format(
      "{}keying{}: a scanner configured with the old file says {} when keyed to exact match, {} when "
      "keyed to compatible revision\n",
      bold, reset, k.exact_match ? "Match" : "Mismatch", k.compatible_match ? "Match" : "Mismatch");
  for (const auto g : all_groups) {
    bool header = false;
    for (const auto& d : r.differences) {
      if (d.in != g) continue;
      if (!header) {
        out += fmt::format("\n{}{}{}\n", bold, title(g), reset);
        header = true;
      }
      const bool in_new = d.after.present();
      const auto where = in_new ? location(*after.source, d.after.offset) : location(*before.source, d.before.offset);
      out += fmt::format("{}{}:{} {}{}:{} {}{}: {} [{}]{}\n", bold, where, reset, style.color ? colour_of(d.level) : "",
                         to_string(d.level), reset, bold, safe(d.subject), safe(d.message), d.kind, reset);
      if (in_new && d.before.present())
        out += fmt::format("  {}: was here\n", location(*before.source, d.before.offset));
      if (!d.consequence.empty()) out += wrap(safe(d.consequence), "  = ");
    }
  }
  out += fmt::format("\n{}: {} breaking, {} additive, {} cosmetic\n", plural(r.differences.size(), "difference"),
                     r.count(impact::breaking), r.count(impact::additive), r.count(impact::cosmetic));
  return out;
}

std::string render_json(const result& r, const analysis& before, const analysis& after) {
  using json = nlohmann::ordered_json;
  using emit::detail::to_utf8;
  auto ident = [](const identity_key& k) {
    auto n = [](const std::optional<std::uint64_t>& v) { return v ? json(*v) : json(nullptr); };
    json j;
    j["vendor"] = n(k.vendor);
    j["device_type"] = n(k.device_type);
    j["product_code"] = n(k.product_code);
    j["major_revision"] = n(k.major);
    j["minor_revision"] = n(k.minor);
    return j;
  };
  auto place = [](const source_file& src, const side& s) {
    if (!s.present()) return json(nullptr);
    const auto pos = src.position(s.offset);
    json j;
    j["line"] = pos.line;
    j["column"] = pos.column;
    j["value"] = to_utf8(s.value);
    return j;
  };
  json j;
  j["format"] = "edsc-diff";
  j["version"] = json_format_version;
  j["old"] = to_utf8(before.source->path());
  j["new"] = to_utf8(after.source->path());
  json keying;
  keying["old"] = ident(r.keys.before);
  keying["new"] = ident(r.keys.after);
  keying["exact_match"] = r.keys.exact_match;
  keying["compatible_revision"] = r.keys.compatible_match;
  j["keying"] = std::move(keying);
  json summary;
  summary["breaking"] = r.count(impact::breaking);
  summary["additive"] = r.count(impact::additive);
  summary["cosmetic"] = r.count(impact::cosmetic);
  j["summary"] = std::move(summary);
  json diffs = json::array();
  for (const auto& d : r.differences) {
    json e;
    e["group"] = to_string(d.in);
    e["impact"] = to_string(d.level);
    e["kind"] = d.kind;
    e["subject"] = to_utf8(d.subject);
    e["message"] = to_utf8(d.message);
    e["consequence"] = to_utf8(d.consequence);
    e["old"] = place(*before.source, d.before);
    e["new"] = place(*after.source, d.after);
    diffs.push_back(std::move(e));
  }
  j["differences"] = std::move(diffs);
  return j.dump(2) + '\n';
}

}  // namespace edsc::diff
