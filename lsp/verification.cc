#include "lsp/verification.h"

#include "compiler/lower/compile_spec.h"
#include "core/join.h"
#include "verify/temporal/rates.h"
#include "verify/temporal/report_text.h"
#include "verify/verify.h"

namespace arbc::lsp {

namespace {

std::string state_text(const verify::EventState& s) {
  return "event state: " + (s.present.empty() ? std::string("none") : join(s.present)) +
         " present; " + (s.absent.empty() ? std::string("none") : join(s.absent)) + " absent";
}

bool same_place(const model::SourceLocation& a, const model::SourceLocation& b) {
  return a.line == b.line && a.column == b.column;
}

// The rule `f` names as rules[i], by its arbitrated port and name: two ports may each have a
// rule of that name. Null when the finding does not say the port.
const model::Connection* named_rule(const model::App& app, const verify::Finding& f, size_t i) {
  const std::string& port = f.rule_port(i);
  if (port.empty()) return nullptr;
  for (const model::Connection& c : app.connections)
    if (c.name == f.rules[i] && c.destination == port) return &c;
  return nullptr;
}

// The finding at its own location; and one diagnostic on every other rule of a conflict
// between rules (a counterexample of a port: its first rule is the finding's location; a
// resource two rules both use, reported at the resource), so each rule shows it, with notes
// at the other rule and, when elsewhere, the finding.
void add_finding(const model::App& app, const verify::Finding& f, std::vector<Diagnostic>& out) {
  Diagnostic d = verify::to_diagnostic(f);
  if (f.counterexample) d.message += "\n" + state_text(*f.counterexample);
  out.push_back(d);
  bool assert_on_rule = f.check == verify::kCheckAssert && f.rules.size() == 1;
  if (!assert_on_rule &&
      (f.rules.size() < 2 || (!f.counterexample && f.check != verify::kCheckResource)))
    return;
  std::vector<const model::Connection*> rules;
  bool at_a_rule = false;  // the finding's own location is one of its rules
  for (size_t i = 0; i < f.rules.size(); ++i) {
    rules.push_back(named_rule(app, f, i));
    at_a_rule |= rules[i] && same_place(rules[i]->loc, f.loc);
  }
  for (size_t i = 0; i < rules.size(); ++i) {
    if (!rules[i] || same_place(rules[i]->loc, f.loc)) continue;
    Diagnostic other = d;
    other.loc = rules[i]->loc;
    std::vector<Diagnostic> back;
    for (size_t j = 0; j < rules.size(); ++j) {
      if (j == i || !rules[j]) continue;
      Diagnostic n;
      n.severity = Severity::Note;
      n.loc = rules[j]->loc;
      n.message = "the other rule: '" + f.rules[j] + "'";
      if (rules[j]->destination != rules[i]->destination)
        n.message += " (into " + rules[j]->destination + ")";
      back.push_back(std::move(n));
    }
    if (!at_a_rule) {
      Diagnostic n;
      n.severity = Severity::Note;
      n.loc = f.loc;
      n.message = "also reported here";
      back.push_back(std::move(n));
    }
    other.notes.insert(other.notes.begin(), back.begin(), back.end());
    out.push_back(std::move(other));
  }
}

// A property over time that is violated or undecided, at the property: what the CLI prints
// (the trace, its replay and tests file, the assumptions) as lines the editor's float wraps,
// with the rates it relies on as related places.
void add_temporal(const verify::TemporalResult& t, std::vector<Diagnostic>& out) {
  using Outcome = verify::TemporalResult::Outcome;
  if (t.outcome != Outcome::Violated && t.outcome != Outcome::Unknown) return;
  Diagnostic d;
  d.severity = t.outcome == Outcome::Violated ? Severity::Error : Severity::Warning;
  d.id = t.outcome == Outcome::Violated ? verify::kCheckTemporal : verify::kCheckUnknown;
  d.loc = t.property.loc;
  d.message = verify::temporal::temporal_editor_message(t);
  for (const model::SourceRate& rate : t.rates) {
    Diagnostic n;
    n.severity = Severity::Note;
    n.loc = rate.loc;
    n.message = verify::temporal::rate_words(rate);
    d.notes.push_back(std::move(n));
  }
  out.push_back(std::move(d));
}

}  // namespace

Verification verify_text(const std::string& text, int version, const std::string& file,
                         const std::string& script_dir, ParserGate& gate, double timeout_seconds,
                         const MakeReplayers& make_replayers) {
  Verification v;
  v.version = version;
  lower::CompiledSpec compiled =
      gate.run(file, [&] { return lower::compile_spec_text(text, file, script_dir); });
  if (!compiled.ok) {
    v.summary = "not verified: the spec has errors";
    return v;
  }
  verify::VerifyOptions options;
  options.timeout_seconds = timeout_seconds;
  Replayers replayers;
  if (make_replayers) replayers = make_replayers(compiled.lowered);
  options.runner = replayers.monitors.get();
  options.test_replayer = replayers.runs.get();
  std::string err;
  std::optional<verify::VerifyReport> report =
      verify::verify_app(compiled.lowered->app, options, &err);
  if (!report) {
    Diagnostic d;
    d.loc.file = file;
    d.message = "not verified: " + err;
    v.summary = d.message;
    v.diagnostics.push_back(std::move(d));
    return v;
  }
  const model::App& app = compiled.lowered->app;
  for (const verify::PortResult& p : report->ports)
    for (const verify::Finding& f : p.findings) add_finding(app, f, v.diagnostics);
  for (const verify::Finding& f : report->app_findings) add_finding(app, f, v.diagnostics);
  for (const verify::ResourceResult& r : report->resources)
    for (const verify::Finding& f : r.findings) add_finding(app, f, v.diagnostics);
  for (const verify::TemporalResult& t : report->temporal) add_temporal(t, v.diagnostics);
  v.summary = std::string(verify::verdict_name(report->verdict)) + ": " +
              std::to_string(report->ports.size()) + " arbitrated ports, " +
              std::to_string(report->count(Severity::Error)) + " errors, " +
              std::to_string(report->count(Severity::Warning)) + " warnings";
  return v;
}

}  // namespace arbc::lsp
