// The JSON report (schema: docs/verify-json.md). Its paths are named as in artifacts
// (core/artifact_path.h): the report is read by other tools, maybe on other machines.
#include <nlohmann/json.hpp>

#include "core/artifact_path.h"
#include "verify/report_format.h"
#include "verify/temporal/counterexample.h"
#include "verify/temporal/report_text.h"

namespace arbc::verify {
namespace {

using Json = nlohmann::ordered_json;

Json location_json(const model::SourceLocation& loc) {
  if (loc.file.empty() && loc.line == 0) return nullptr;
  return Json{{"file", artifact_path(loc.file.str())},
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
  // Each rule's arbitrated port: a rule's name is unique only within its port, and a resource
  // finding's rules go into different ports.
  j["rule_ports"] = Json::array();
  for (size_t i = 0; i < f.rules.size(); ++i)
    j["rule_ports"].push_back(f.rule_port(i).empty() ? Json(nullptr) : Json(f.rule_port(i)));
  j["event"] = f.event.empty() ? Json(nullptr) : Json(f.event);
  j["message"] = f.message;
  j["location"] = location_json(f.loc);
  if (f.counterexample) {
    j["counterexample"] = {{"present", f.counterexample->present},
                           {"absent", f.counterexample->absent}};
  } else {
    j["counterexample"] = nullptr;
  }
  if (!f.messages.empty()) j["messages"] = messages_json(f.messages);
  j["notes"] = Json::array();
  for (const Note& n : f.notes) {
    j["notes"].push_back({{"message", n.message}, {"location", location_json(n.loc)}});
  }
  return j;
}

// A diagnostic of a bad input (the spec's errors, an app.json that does not load).
Json diagnostic_json(const Diagnostic& d) {
  Json j;
  j["id"] = d.id;
  j["severity"] = severity_name(d.severity);
  j["message"] = d.message;
  j["location"] = location_json(d.loc);
  j["notes"] = Json::array();
  for (const Diagnostic& n : d.notes)
    j["notes"].push_back({{"message", n.message}, {"location", location_json(n.loc)}});
  return j;
}

// An input that was not verified: verdict "error", no ports, its diagnostics.
Json bad_input_json(const InputReport& in) {
  Json j;
  j["input"] = artifact_path(in.input);
  j["app"] = "";
  j["spec_file"] = "";
  j["verdict"] = "error";
  j["ports"] = Json::array();
  j["findings"] = Json::array();
  j["diagnostics"] = Json::array();
  int errors = 0, warnings = 0;
  for (const Diagnostic& d : in.errors) {
    j["diagnostics"].push_back(diagnostic_json(d));
    errors += d.severity == Severity::Error;
    warnings += d.severity == Severity::Warning;
  }
  j["errors"] = errors;
  j["warnings"] = warnings;
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
  if (!p.feeds.empty()) j["feeds"] = p.feeds;
  j["events"] = p.events;
  j["invariants"] = p.invariants;
  j["exclusive_groups"] = p.exclusive_groups;
  j["asserts"] = p.asserts;
  j["overlapping_pairs"] = p.overlapping_pairs;
  j["reported_pairs"] = p.reported_pairs;
  j["unknown_reason"] = p.unknown_reason.empty() ? Json(nullptr) : Json(p.unknown_reason);
  if (!p.exclusive_by_data.empty()) j["exclusive_by_data"] = p.exclusive_by_data;
  if (!p.exclusive_by_delivery.empty()) j["exclusive_by_delivery"] = p.exclusive_by_delivery;
  j["list_bound"] = p.list_bound ? Json(p.list_bound) : Json(nullptr);
  j["findings"] = Json::array();
  for (const Finding& f : p.findings) j["findings"].push_back(finding_json(f));
  if (stats) j["stats"] = {{"seconds", p.seconds}, {"solver_queries", p.solver_queries}};
  return j;
}

// A property over time: its verdict with the bound, and a violation's timed trace.
Json temporal_json(const TemporalResult& t) {
  static const char* kOutcome[] = {"holds-up-to-bound", "violated", "unknown", "proved", "vacuous"};
  Json j;
  j["kind"] = model::temporal_kind_name(t.property.kind);
  j["port"] = t.property.port;
  j["rule"] = t.property.rule;  // "" for a stability and a response answered by a port
  switch (t.property.kind) {
    case model::TemporalProperty::Kind::Spacing:
      j["window"] = seconds_of(t.property.window);
      if (!t.property.other.empty()) j["after"] = t.property.other;
      break;
    case model::TemporalProperty::Kind::Absence:
      j["event"] = t.property.event;
      break;
    case model::TemporalProperty::Kind::Precedence:
      j["after"] = t.property.other;
      break;
    case model::TemporalProperty::Kind::Response:
      if (t.property.event.empty()) j["after"] = t.property.other;
      if (!t.property.event.empty()) j["event"] = t.property.event;
      j["stops"] = t.property.stops;
      j["window"] = seconds_of(t.property.window);
      j["while"] = t.property.condition.to_string();
      break;
    case model::TemporalProperty::Kind::Stability:
      j["window"] = seconds_of(t.property.window);
      break;
  }
  j["location"] = location_json(t.property.loc);
  j["outcome"] = kOutcome[static_cast<int>(t.outcome)];
  j["bound"] = t.bound;
  j["proof"] = t.proof.empty() ? Json(nullptr) : Json(t.proof);
  j["induction_k"] = t.induction_k ? Json(t.induction_k) : Json(nullptr);
  j["faithful"] = t.faithful;
  // The environment assumptions the verdict is under (docs/language.md#environment-assumptions).
  j["assumptions"] = Json::array();
  for (const model::Assumption& a : t.assumptions) {
    j["assumptions"].push_back(
        {{"event", a.event},
         {"after", a.after},
         {"until", a.until.empty() ? Json(nullptr) : Json(a.until)},
         {"absent_for", a.absent_for ? Json(seconds_of(*a.absent_for)) : Json(nullptr)},
         {"location", location_json(a.loc)}});
  }
  j["replayed"] = t.replayed;
  j["unknown_reason"] = t.unknown_reason.empty() ? Json(nullptr) : Json(t.unknown_reason);
  if (t.property.kind == model::TemporalProperty::Kind::Response ||
      t.property.kind == model::TemporalProperty::Kind::Stability || !t.rates.empty()) {
    // The environment rates the verdict relies on (`given M.p every D`).
    j["rates"] = Json::array();
    for (const model::SourceRate& r : t.rates)
      j["rates"].push_back(
          {{"port", r.port}, {"every", seconds_of(r.period)}, {"location", location_json(r.loc)}});
    j["explanation"] = t.explanation.empty() ? Json(nullptr) : Json(t.explanation);
    j["rated_span"] = t.rated_span > Nanos(0) ? Json(seconds_of(t.rated_span)) : Json(nullptr);
    j["window_bound"] = t.window_bound > 0 ? Json(t.window_bound) : Json(nullptr);
  }
  j["trace"] = Json::array();
  for (const TraceStep& s : t.trace) {
    j["trace"].push_back({{"t", seconds_of(s.time)},
                          {"source", s.source},
                          {"connection", s.connection},
                          {"feed", s.feed},
                          {"accepted", s.accepted},
                          {"delivered", s.delivered},
                          {"set", s.set},
                          {"unset", s.unset}});
  }
  // The counterexample as a tests file beside the spec (`arbc test` replays it).
  j["test"] = t.replayed ? Json(temporal::test_file_text(*t.replay_test, t.property,
                                                         temporal::spec_name(t.property)))
                         : Json(nullptr);
  return j;
}

}  // namespace

nlohmann::ordered_json messages_json(const std::vector<MessageExample>& messages) {
  Json out = Json::array();
  for (const MessageExample& m : messages)
    out.push_back({{"source", m.source}, {"value", m.value}, {"replay", m.replay}});
  return out;
}

std::string format_json(const std::vector<InputReport>& inputs, bool stats) {
  Json root;
  root["schema"] = "arbc-verify/1";
  bool refuted = false, unknown = false, bad = false;
  root["inputs"] = Json::array();
  for (const InputReport& in : inputs) {
    if (in.bad_input()) {
      root["inputs"].push_back(bad_input_json(in));
      bad = true;
      continue;
    }
    const VerifyReport& r = in.report;
    Json j;
    j["input"] = artifact_path(in.input);
    j["app"] = r.app;
    j["spec_file"] = artifact_path(r.spec_file);
    j["verdict"] = verdict_name(r.verdict);
    j["ports"] = Json::array();
    for (const PortResult& p : r.ports) j["ports"].push_back(port_json(p, stats));
    j["findings"] = Json::array();
    for (const Finding& f : r.app_findings) j["findings"].push_back(finding_json(f));
    if (!r.resources.empty()) {
      j["resources"] = Json::array();
      for (const ResourceResult& res : r.resources) {
        Json rj;
        rj["name"] = res.name;
        rj["verdict"] = verdict_name(res.verdict);
        rj["ports"] = res.ports;
        rj["location"] = location_json(res.loc);
        rj["pairs"] = res.pairs;
        rj["exclusive_by_events"] = res.exclusive_by_events;
        rj["exclusive_by_data"] = res.exclusive_by_data;
        rj["list_bound"] = res.list_bound ? Json(res.list_bound) : Json(nullptr);
        rj["unknown_reason"] =
            res.unknown_reason.empty() ? Json(nullptr) : Json(res.unknown_reason);
        rj["findings"] = Json::array();
        for (const Finding& f : res.findings) rj["findings"].push_back(finding_json(f));
        j["resources"].push_back(std::move(rj));
      }
    }
    if (!r.assumptions.empty()) j["assumptions"] = r.assumptions;
    // Only when the app has properties over time, so other reports keep their bytes.
    if (!r.temporal.empty()) {
      j["temporal"] = Json::array();
      for (const TemporalResult& t : r.temporal) j["temporal"].push_back(temporal_json(t));
    }
    j["diagnostics"] = Json::array();
    for (const Diagnostic& d : in.warnings) j["diagnostics"].push_back(diagnostic_json(d));
    j["errors"] = r.count(Severity::Error);
    j["warnings"] = r.count(Severity::Warning) + static_cast<int>(in.warnings.size());
    if (stats) j["stats"] = {{"seconds", r.seconds}, {"solver_queries", r.solver_queries}};
    refuted |= r.verdict == Verdict::Refuted;
    unknown |= r.verdict == Verdict::Unknown;
    root["inputs"].push_back(std::move(j));
  }
  // Bad input outranks every proof verdict, as exit code 2 outranks 1.
  root["verdict"] = bad ? "error" : refuted ? "refuted" : unknown ? "unknown" : "proved";
  return root.dump(2) + "\n";
}

}  // namespace arbc::verify
