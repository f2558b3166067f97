#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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

// A relative path as a URI reference: keep unreserved characters and '/'.
std::string uri_of(const std::string& path) {
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

json region_of(const source_file& src, span s) {
  const auto a = src.position(s.begin);
  const auto b = src.position(s.end);
  return json{{"startLine", a.line},
              {"startColumn", a.column},
              {"endLine", b.line},
              {"endColumn", b.column},
              {"byteOffset", s.begin},
              {"byteLength", s.size()}};
}

json location_of(const source_file& src, span s) {
  return json{{"physicalLocation",
               {{"artifactLocation", {{"uri", uri_of(src.path())}}}, {"region", region_of(src, s)}}}};
}

json rules_json(std::map<diag_id, std::size_t>& index) {
  json rules = json::array();
  for (const auto& r : all_rules()) {
    index[r.id] = rules.size();
    rules.push_back(json{
        {"id", r.name},
        {"shortDescription", {{"text", r.summary}}},
        {"fullDescription", {{"text", r.explanation}}},
        {"help",
         {{"text", fmt::format("{}\n\nBad:\n{}\n\nGood:\n{}", r.explanation, r.bad, r.good)},
          {"markdown", fmt::format("{}\n\nBad:\n```\n{}\n```\n\nGood:\n```\n{}\n```", r.explanation, r.bad, r.good)}}},
        {"defaultConfiguration", {{"level", sarif_level(r.default_level)}}},
        {"properties", {{"tags", json::array({r.group})}}}});
  }
  return rules;
}

}  // namespace

std::string render_sarif(const std::vector<file_report>& files) {
  std::map<diag_id, std::size_t> rule_index;
  json driver{{"name", "edsc"},
              {"version", EDSC_VERSION_STRING},
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
             {"locations", json::array({location_of(src, d.where)})}};
      if (!d.notes.empty()) {
        json related = json::array();
        for (std::size_t i = 0; i < d.notes.size(); ++i) {
          auto loc = location_of(src, d.notes[i].where);
          loc["id"] = i;
          loc["message"] = {{"text", d.notes[i].message}};
          related.push_back(std::move(loc));
        }
        r["relatedLocations"] = std::move(related);
      }
      if (!d.fixits.empty()) {
        json replacements = json::array();
        for (const auto& fx : d.fixits) {
          replacements.push_back(json{
              {"deletedRegion", {{"byteOffset", fx.range.begin}, {"byteLength", fx.range.size()}}},
              {"insertedContent", {{"text", fx.replacement}}}});
        }
        r["fixes"] = json::array({json{
            {"description", {{"text", "apply the certain fix"}}},
            {"artifactChanges",
             json::array({json{{"artifactLocation", {{"uri", uri_of(src.path())}}},
                               {"replacements", std::move(replacements)}}})}}});
      }
      results.push_back(std::move(r));
    }
  }
  json run{{"tool", {{"driver", std::move(driver)}}},
           {"columnKind", "unicodeCodePoints"},
           {"results", std::move(results)}};
  json out{{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
           {"version", "2.1.0"},
           {"runs", json::array({std::move(run)})}};
  return out.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace edsc
