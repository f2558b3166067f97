#include <nlohmann/json.hpp>

#include "diag/report.hpp"
#include "edsc_version.hpp"

namespace edsc {

namespace {

using json = nlohmann::ordered_json;

json position_json(const source_file& src, std::uint32_t offset) {
  const auto p = src.position(offset);
  return json{{"offset", offset}, {"line", p.line}, {"column", p.column}};
}

json range_json(const source_file& src, span s) {
  return json{{"start", position_json(src, s.begin)}, {"end", position_json(src, s.end)}};
}

// Source text is bytes in any 8-bit encoding; JSON strings must be UTF-8.
// Invalid sequences are replaced rather than failing the whole report.
std::string dump(const json& j) { return j.dump(2, ' ', false, json::error_handler_t::replace); }

}  // namespace

std::string render_json(const std::vector<file_report>& files, const report_totals& totals) {
  json out;
  out["format"] = "edsc-diagnostics";
  out["version"] = 1;
  out["tool"] = json{{"name", "edsc"}, {"version", EDSC_VERSION_STRING}};
  json jfiles = json::array();
  for (const auto& f : files) {
    if (!f.source) continue;
    const auto& src = *f.source;
    json jdiags = json::array();
    for (const auto& d : f.diags) {
      json jd;
      jd["id"] = rule_of(d.id).name;
      jd["severity"] = to_string(d.level);
      jd["message"] = d.message;
      jd["range"] = range_json(src, d.where);
      json notes = json::array();
      for (const auto& n : d.notes) notes.push_back(json{{"message", n.message}, {"range", range_json(src, n.where)}});
      jd["notes"] = std::move(notes);
      json fixes = json::array();
      for (const auto& fx : d.fixits) {
        fixes.push_back(json{{"range", range_json(src, fx.range)}, {"replacement", fx.replacement}});
      }
      jd["fixits"] = std::move(fixes);
      jdiags.push_back(std::move(jd));
    }
    jfiles.push_back(json{{"path", src.path()}, {"diagnostics", std::move(jdiags)}});
  }
  out["files"] = std::move(jfiles);
  out["summary"] =
      json{{"files", totals.files}, {"errors", totals.errors}, {"warnings", totals.warnings}, {"notes", totals.notes}};
  return dump(out) + "\n";
}

}  // namespace edsc
