// SARIF 2.1.0 (docs/verify-json.md, "SARIF"): one result per finding, for code scanning.
#include <cctype>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "core/artifact_path.h"
#include "core/check_ids.h"
#include "verify/report_format.h"
#include "verify/temporal/counterexample.h"
#include "verify/temporal/rates.h"
#include "verify/temporal/report_text.h"

namespace arbc::verify {
namespace {

using Json = nlohmann::ordered_json;

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
    {kCheckTemporalBound,
     "A response's window cannot close within --temporal-bound messages at the given rates."},
    {kCheckListBound, "A rule accepts no message whose lists have at most --list-bound elements."},
    {kCheckVacuous,
     "A property over time reads an event nothing can put into its port's container: it says "
     "nothing."},
    {kCheckUnfed, "A constraint or assert reads an event nothing sets into the port's container."},
    {kCheckUnused, "An event is set but nothing reads it."},
    {kCheckOwnership, "A monitor unsets an event it never sets."},
    {kCheckComplete, "On a complete port, some state selects no rule."},
    {kCheckAssert, "A rule can deliver while its asserted property is false."},
    {kCheckUnknown, "The solver could not decide a check (timeout or resource limit)."},
    {kCheckInternal, "Z3 and the runtime's constraint evaluator disagree (a bug in arbc)."},
    {kCheckResource, "Two ports of a resource can each receive a command that uses it."},
    {kCheckTemporal, "A property over time is violated by a timed trace the runtime replays."},
};

// A file as a SARIF `uri`: a URI reference (RFC 3986) to the path as artifacts name it
// (core/artifact_path.h). A byte that may not stand in a path segment as it is, a space or a
// non-ASCII byte, is percent-encoded; so is ':', which would make the first segment a scheme.
std::string uri_reference(const std::string& file) {
  static const std::string kPlain = "-._~!$&'()*+,;=@/";
  std::string out;
  for (unsigned char c : artifact_path(file)) {
    if (std::isalnum(c) && c < 0x80) {
      out += static_cast<char>(c);
    } else if (kPlain.find(static_cast<char>(c)) != std::string::npos) {
      out += static_cast<char>(c);
    } else {
      static const char kHex[] = "0123456789ABCDEF";
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

Json sarif_location(const model::SourceLocation& loc) {
  Json phys;
  phys["artifactLocation"] = {{"uri", uri_reference(loc.file)}};
  if (loc.line > 0) {
    Json region{{"startLine", loc.line}};
    if (loc.column > 0) region["startColumn"] = loc.column;
    if (loc.end_line > 0) region["endLine"] = loc.end_line;
    if (loc.end_column > 0) region["endColumn"] = loc.end_column;
    phys["region"] = region;
  }
  return Json{{"physicalLocation", phys}};
}

// Rules for the diagnostic ids of bad inputs (front-end ids, `io`, `app-json`), described by the
// id registry; each once, after the proof's checks.
void add_input_rules(const std::vector<InputReport>& inputs, Json& rules) {
  std::set<std::string> listed;
  for (const CheckDoc& c : kChecks) listed.insert(c.id);
  for (const InputReport& in : inputs) {
    std::vector<Diagnostic> all = in.errors;
    all.insert(all.end(), in.warnings.begin(), in.warnings.end());
    for (const Diagnostic& d : all) {
      if (!listed.insert(d.id).second) continue;
      std::string meaning = "a diagnostic of arbc";
      for (const frontend::CheckId& id : frontend::all_check_ids())
        if (id.id == d.id) meaning = std::string(id.meaning);
      rules.push_back({{"id", d.id}, {"shortDescription", {{"text", meaning}}}});
    }
  }
}

// A diagnostic of the front end as a result: a bad input's (it was not verified, whatever the
// level says), or a warning about a spec that was verified (`lapsing-permission`).
Json diagnostic_result(const Diagnostic& d) {
  Json r;
  r["ruleId"] = d.id;
  r["level"] = sarif_level(d.severity);
  std::string text = d.message;
  for (const Diagnostic& n : d.notes) text += "\n" + n.message;
  r["message"] = {{"text", text}};
  r["locations"] = Json::array();
  if (!d.loc.file.empty()) r["locations"].push_back(sarif_location(d.loc));
  Json related = Json::array();
  for (const Diagnostic& n : d.notes) {
    if (n.loc.file.empty()) continue;
    Json l = sarif_location(n.loc);
    l["id"] = static_cast<int>(related.size());
    l["message"] = {{"text", n.message}};
    related.push_back(l);
  }
  if (!related.empty()) r["relatedLocations"] = related;
  return r;
}

// A finding whose rules go into different ports (a resource's pair): a related location per
// rule, at the rule, naming it with its port as a logical location ("PickAndPlace.cmd.take";
// a rule's name is unique only within its port). A note already at the rule gets the name.
void add_rule_locations(const Finding& f, Json& related) {
  for (size_t i = 0; i < f.rule_ports.size() && i < f.rules.size(); ++i) {
    Json logical = Json::array({{{"name", f.rules[i]},
                                 {"fullyQualifiedName", f.rule_ports[i] + "." + f.rules[i]},
                                 {"kind", "function"}}});
    model::SourceLocation loc = i < f.rule_locs.size() ? f.rule_locs[i] : model::SourceLocation{};
    Json* at = nullptr;
    if (!loc.file.empty()) {
      Json physical = sarif_location(loc)["physicalLocation"];
      for (Json& l : related)
        if (!at && l.contains("physicalLocation") && l.at("physicalLocation") == physical &&
            !l.contains("logicalLocations"))
          at = &l;
    }
    if (!at) {
      Json l = loc.file.empty() ? Json::object() : sarif_location(loc);
      l["id"] = static_cast<int>(related.size());
      l["message"] = {{"text", "rule '" + f.rules[i] + "' of " + f.rule_ports[i]}};
      related.push_back(std::move(l));
      at = &related.back();
    }
    (*at)["logicalLocations"] = std::move(logical);
  }
}

}  // namespace

// A violated (or undecided) property over time as a result; nullopt when it holds up to the
// bound, which is no finding.
std::optional<Json> temporal_result(const TemporalResult& t) {
  // A vacuous property is reported by its `vacuous` finding.
  if (t.outcome == TemporalResult::Outcome::HoldsToBound ||
      t.outcome == TemporalResult::Outcome::Proved || t.outcome == TemporalResult::Outcome::Vacuous)
    return std::nullopt;
  bool violated = t.outcome == TemporalResult::Outcome::Violated;
  Json r;
  r["ruleId"] = violated ? kCheckTemporal : kCheckUnknown;
  r["level"] = "error";
  r["message"] = {{"text", temporal::temporal_message(t)}};
  r["locations"] = Json::array();
  if (!t.property.loc.file.empty()) r["locations"].push_back(sarif_location(t.property.loc));
  // The rates (`given M.p every D`) the verdict relies on, where the spec states them.
  for (const model::SourceRate& rate : t.rates) {
    Json related = sarif_location(rate.loc);
    related["message"] = {{"text", temporal::rate_words(rate)}};
    r["relatedLocations"].push_back(std::move(related));
  }
  if (violated && t.replay_test) {  // Violated means replayed (verify/temporal/confirm.h)
    r["properties"]["test"] =
        temporal::test_file_text(*t.replay_test, t.property, temporal::spec_name(t.property));
  }
  return r;
}

std::string format_sarif(const std::vector<InputReport>& inputs, const std::string& tool_version) {
  Json rules = Json::array();
  for (const CheckDoc& c : kChecks) {
    // Not `helpUri`: SARIF wants an absolute URI there, and the page is a file of arbc's
    // repository, whose address arbc cannot know.
    rules.push_back(
        {{"id", c.id},
         {"shortDescription", {{"text", c.text}}},
         {"help", {{"text", std::string("docs/checks.md#") + c.id + " in arbc's documentation"}}}});
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
    add_rule_locations(f, related);
    if (!related.empty()) r["relatedLocations"] = related;
    if (f.counterexample) {
      r["properties"] = {
          {"counterexample",
           {{"present", f.counterexample->present}, {"absent", f.counterexample->absent}}}};
    }
    if (!f.messages.empty()) r["properties"]["messages"] = messages_json(f.messages);
    results.push_back(std::move(r));
  };
  add_input_rules(inputs, rules);
  // Proved verdicts that hold only for lists of at most N elements: a proof is no result in
  // SARIF, so the run's property bag names them (docs/checks.md#list-bound).
  Json bounded = Json::array();
  for (const InputReport& in : inputs) {
    for (const PortResult& p : in.report.ports)
      if (p.verdict == Verdict::Proved && p.list_bound)
        bounded.push_back({{"port", p.port}, {"list_bound", p.list_bound}});
    for (const ResourceResult& r : in.report.resources)
      if (r.verdict == Verdict::Proved && r.list_bound)
        bounded.push_back({{"resource", r.name}, {"list_bound", r.list_bound}});
  }
  for (const InputReport& in : inputs) {
    for (const Diagnostic& d : in.errors) results.push_back(diagnostic_result(d));
    for (const Diagnostic& d : in.warnings) results.push_back(diagnostic_result(d));
    for (const PortResult& p : in.report.ports) {
      for (const Finding& f : p.findings) add(f);
    }
    for (const Finding& f : in.report.app_findings) add(f);
    for (const ResourceResult& r : in.report.resources)
      for (const Finding& f : r.findings) add(f);
    for (const TemporalResult& t : in.report.temporal)
      if (std::optional<Json> r = temporal_result(t)) results.push_back(std::move(*r));
  }
  Json driver{{"name", "arbc"}, {"version", tool_version}, {"rules", rules}};
  Json root{{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
            {"version", "2.1.0"},
            {"runs", Json::array({{{"tool", {{"driver", driver}}}, {"results", results}}})}};
  if (!bounded.empty()) root["runs"][0]["properties"]["proved_for_bounded_lists"] = bounded;
  return root.dump(2) + "\n";
}

}  // namespace arbc::verify
