#include <cctype>
#include <map>
#include <optional>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "diag/help_uri.hpp"
#include "diag/report.hpp"
#include "edsc_version.hpp"

namespace edsc {

namespace {

using json = nlohmann::ordered_json;

const char* sarif_level(severity s) {
  switch (s) {
    case severity::error: return "error";
    case severity::warning: return "warning";
    case severity::note: return "note";
  }
  return "error";
}

// The base relative paths are resolved against: the working directory the
// paths were given in.
constexpr const char* src_root = "SRCROOT";

// A path as a URI path: unreserved characters and '/' kept, the rest
// percent-encoded (UTF-8 bytes included).
std::string encode_path(const std::string& path) {
  std::string out;
  for (const unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      out.push_back(static_cast<char>(c));
    } else {
      out += fmt::format("%{:02X}", c);
    }
  }
  return out;
}

// The working directory as an absolute file URI ending in '/', as
// originalUriBaseIds requires; none when it cannot be known.
std::optional<std::string> working_directory_uri() {
  std::string buf(4096, '\0');
  if (::getcwd(buf.data(), buf.size()) == nullptr) return std::nullopt;
  buf.resize(std::char_traits<char>::length(buf.c_str()));
  if (buf.empty() || buf.front() != '/') return std::nullopt;
  std::string uri = "file://" + encode_path(buf);
  if (uri.back() != '/') uri.push_back('/');
  return uri;
}

// An absolute path is a file:// URI on its own; a relative one stays a
// relative reference, resolved against SRCROOT when the run defines it.
json artifact_location(const std::string& path, bool have_root) {
  if (!path.empty() && path.front() == '/') return json{{"uri", "file://" + encode_path(path)}};
  json loc{{"uri", encode_path(path)}};
  if (have_root) loc["uriBaseId"] = src_root;
  return loc;
}

// The rule's id as the Pascal-case "friendly name" SARIF asks for:
// param-data-size -> ParamDataSize.
std::string friendly_name(std::string_view id) {
  std::string out;
  bool upper = true;
  for (const char c : id) {
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      upper = true;
      continue;
    }
    out.push_back(upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c);
    upper = false;
  }
  return out;
}

json region_of(const source_file& src, span s) {
  const auto a = src.position(s.begin);
  const auto b = src.position(s.end);
  return json{{"startLine", a.line},   {"startColumn", a.column}, {"endLine", b.line},
              {"endColumn", b.column}, {"byteOffset", s.begin},   {"byteLength", s.size()}};
}

json location_of(const source_file& src, span s, bool have_root) {
  return json{{"physicalLocation",
               {{"artifactLocation", artifact_location(src.path(), have_root)}, {"region", region_of(src, s)}}}};
}

json rules_json(std::map<diag_id, std::size_t>& index) {
  json rules = json::array();
  for (const auto& r : all_rules()) {
    index[r.id] = rules.size();
    rules.push_back(json{
        {"id", r.name},
        {"name", friendly_name(r.name)},
        {"shortDescription", {{"text", r.summary}}},
        {"fullDescription", {{"text", r.explanation}}},
        {"help",
         {{"text", fmt::format("{}\n\nBad:\n{}\n\nGood:\n{}", r.explanation, r.bad, r.good)},
          {"markdown", fmt::format("{}\n\nBad:\n```\n{}\n```\n\nGood:\n```\n{}\n```", r.explanation, r.bad, r.good)}}},
        {"helpUri", rule_help_uri(r.name)},
        {"defaultConfiguration", {{"level", sarif_level(r.default_level)}}},
        {"properties", {{"tags", json::array({r.group})}}}});
  }
  return rules;
}

}  // namespace

std::string render_sarif(const std::vector<file_report>& files) {
  std::map<diag_id, std::size_t> rule_index;
  const auto root = working_directory_uri();
  const bool have_root = root.has_value();
  json driver{{"name", "edsc"},
              {"version", EDSC_VERSION_STRING},
              {"informationUri", docs_base_uri() + "cli.md"},
              {"rules", rules_json(rule_index)}};
  json results = json::array();
  for (const auto& f : files) {
    if (!f.source) continue;
    const auto& src = *f.source;
    for (const auto& d : f.diags) {
      json r{{"ruleId", rule_of(d.id).name},
             {"ruleIndex", rule_index[d.id]},
             {"level", sarif_level(d.level)},
             {"message", {{"text", d.message}}},
             {"locations", json::array({location_of(src, d.where, have_root)})}};
      if (!d.notes.empty()) {
        json related = json::array();
        for (std::size_t i = 0; i < d.notes.size(); ++i) {
          auto loc = location_of(src, d.notes[i].where, have_root);
          loc["id"] = i;
          loc["message"] = {{"text", d.notes[i].message}};
          related.push_back(std::move(loc));
        }
        r["relatedLocations"] = std::move(related);
      }
      if (!d.fixits.empty()) {
        json replacements = json::array();
        for (const auto& fx : d.fixits) {
          replacements.push_back(
              json{{"deletedRegion", {{"byteOffset", fx.range.begin}, {"byteLength", fx.range.size()}}},
                   {"insertedContent", {{"text", fx.replacement}}}});
        }
        r["fixes"] = json::array(
            {json{{"description", {{"text", "apply the certain fix"}}},
                  {"artifactChanges", json::array({json{{"artifactLocation", artifact_location(src.path(), have_root)},
                                                        {"replacements", std::move(replacements)}}})}}});
      }
      results.push_back(std::move(r));
    }
  }
  json run{{"tool", {{"driver", std::move(driver)}}}};
  if (have_root) run["originalUriBaseIds"] = {{src_root, {{"uri", *root}}}};
  run["columnKind"] = "unicodeCodePoints";
  run["results"] = std::move(results);
  json out{{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
           {"version", "2.1.0"},
           {"runs", json::array({std::move(run)})}};
  return out.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace edsc
