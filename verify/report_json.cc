// The JSON report (schema: docs/verify-json.md) and SARIF 2.1.0.
#include <nlohmann/json.hpp>

#include "verify/report_format.h"

namespace arbc::verify {
namespace {

using Json = nlohmann::ordered_json;

Json location_json(const model::SourceLocation& loc) {
  if (loc.file.empty() && loc.line == 0) return nullptr;
  return Json{{"file", loc.file},
              {"line", loc.line},
              {"column", loc.column},
              {"end_line", loc.end_line},
              {"end_column", loc.end_column}};
}

Json finding_json(const Finding& f) {
  Json j;
  j["check"] = f.check;
  j["severity"] = severity_name(f.severity);
  j["port"] = f.port.empty() ? Json(nullptr) : Json(f.port);
  j["rules"] = f.rules;
  j["event"] = f.event.empty() ? Json(nullptr) : Json(f.event);
  j["message"] = f.message;
  j["location"] = location_json(f.loc);
  if (f.counterexample) {
    j["counterexample"] = {{"present", f.counterexample->present},
                           {"absent", f.counterexample->absent}};
  } else {
    j["counterexample"] = nullptr;
  }
  j["notes"] = Json::array();
  for (const Note& n : f.notes) {
    j["notes"].push_back({{"message", n.message}, {"location", location_json(n.loc)}});
  }
  return j;
}

Json port_json(const PortResult& p, bool stats) {
  Json j;
  j["port"] = p.port;
  j["verdict"] = verdict_name(p.verdict);
  j["by_priority"] = p.by_priority;
  j["complete"] = p.complete;
  j["location"] = location_json(p.loc);
  j["rules"] = p.rules;
  j["events"] = p.events;
  j["invariants"] = p.invariants;
  j["exclusive_groups"] = p.exclusive_groups;
  j["asserts"] = p.asserts;
  j["overlapping_pairs"] = p.overlapping_pairs;
  j["reported_pairs"] = p.reported_pairs;
  j["unknown_reason"] = p.unknown_reason.empty() ? Json(nullptr) : Json(p.unknown_reason);
  j["findings"] = Json::array();
  for (const Finding& f : p.findings) j["findings"].push_back(finding_json(f));
  if (stats) j["stats"] = {{"seconds", p.seconds}, {"solver_queries", p.solver_queries}};
  return j;
}

const char* sarif_level(Severity s) {
  switch (s) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "none";
}

struct CheckDoc {
  const char* id;
  const char* text;
};
constexpr CheckDoc kChecks[] = {
    {kCheckExclusive, "Two rules of one arbitrated port can be selected in the same state."},
    {kCheckDead, "A rule can never be selected."},
    {kCheckUnfed, "A constraint or assert reads an event nothing sets into the port's container."},
    {kCheckUnused, "An event is set but nothing reads it."},
    {kCheckOwnership, "A monitor unsets an event it never sets."},
    {kCheckComplete, "On a complete port, some state selects no rule."},
    {kCheckAssert, "A rule can deliver while its asserted property is false."},
    {kCheckUnknown, "The solver could not decide a check (timeout or resource limit)."},
    {kCheckInternal, "Z3 and the runtime's constraint evaluator disagree (a bug in arbc)."},
};

Json sarif_location(const model::SourceLocation& loc) {
  Json phys;
  phys["artifactLocation"] = {{"uri", loc.file}};
  if (loc.line > 0) {
    Json region{{"startLine", loc.line}};
    if (loc.column > 0) region["startColumn"] = loc.column;
    if (loc.end_line > 0) region["endLine"] = loc.end_line;
    if (loc.end_column > 0) region["endColumn"] = loc.end_column;
    phys["region"] = region;
  }
  return Json{{"physicalLocation", phys}};
}

}  // namespace

std::string format_json(const std::vector<InputReport>& inputs, bool stats) {
  Json root;
  root["schema"] = "arbc-verify/1";
  bool refuted = false, unknown = false;
  root["inputs"] = Json::array();
  for (const InputReport& in : inputs) {
    const VerifyReport& r = in.report;
    Json j;
    j["input"] = in.input;
    j["app"] = r.app;
    j["spec_file"] = r.spec_file;
    j["verdict"] = verdict_name(r.verdict);
    j["ports"] = Json::array();
    for (const PortResult& p : r.ports) j["ports"].push_back(port_json(p, stats));
    j["findings"] = Json::array();
    for (const Finding& f : r.app_findings) j["findings"].push_back(finding_json(f));
    j["errors"] = r.count(Severity::Error);
    j["warnings"] = r.count(Severity::Warning);
    if (stats) j["stats"] = {{"seconds", r.seconds}, {"solver_queries", r.solver_queries}};
    refuted |= r.verdict == Verdict::Refuted;
    unknown |= r.verdict == Verdict::Unknown;
    root["inputs"].push_back(std::move(j));
  }
  root["verdict"] = refuted ? "refuted" : unknown ? "unknown" : "proved";
  return root.dump(2) + "\n";
}

std::string format_sarif(const std::vector<InputReport>& inputs, const std::string& tool_version) {
  Json rules = Json::array();
  for (const CheckDoc& c : kChecks) {
    rules.push_back({{"id", c.id},
                     {"shortDescription", {{"text", c.text}}},
                     {"helpUri", std::string("docs/checks.md#") + c.id}});
  }
  Json results = Json::array();
  auto add = [&](const Finding& f) {
    Json r;
    r["ruleId"] = f.check;
    r["level"] = sarif_level(f.severity);
    std::string text = f.message;
    for (const Note& n : f.notes) text += "\n" + n.message;
    r["message"] = {{"text", text}};
    r["locations"] = Json::array();
    if (!f.loc.file.empty()) r["locations"].push_back(sarif_location(f.loc));
    Json related = Json::array();
    for (const Note& n : f.notes) {
      if (n.loc.file.empty()) continue;
      Json l = sarif_location(n.loc);
      l["id"] = static_cast<int>(related.size());
      l["message"] = {{"text", n.message}};
      related.push_back(l);
    }
    if (!related.empty()) r["relatedLocations"] = related;
    if (f.counterexample) {
      r["properties"] = {
          {"counterexample",
           {{"present", f.counterexample->present}, {"absent", f.counterexample->absent}}}};
    }
    results.push_back(std::move(r));
  };
  for (const InputReport& in : inputs) {
    for (const PortResult& p : in.report.ports) {
      for (const Finding& f : p.findings) add(f);
    }
    for (const Finding& f : in.report.app_findings) add(f);
  }
  Json driver{{"name", "arbc"}, {"version", tool_version}, {"rules", rules}};
  Json root{{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
            {"version", "2.1.0"},
            {"runs", Json::array({{{"tool", {{"driver", driver}}}, {"results", results}}})}};
  return root.dump(2) + "\n";
}

}  // namespace arbc::verify
