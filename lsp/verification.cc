#include "lsp/verification.h"

#include "compiler/lower/compile_spec.h"
#include "core/join.h"
#include "verify/verify.h"

namespace arbc::lsp {

namespace {

std::string state_text(const verify::EventState& s) {
  return "event state: " + (s.present.empty() ? std::string("none") : join(s.present)) +
         " present; " + (s.absent.empty() ? std::string("none") : join(s.absent)) + " absent";
}

// One diagnostic per rule the finding involves (the first at the finding's own location).
void add_finding(const model::App& app, const verify::Finding& f, std::vector<Diagnostic>& out) {
  Diagnostic d = verify::to_diagnostic(f);
  if (!f.counterexample) {
    out.push_back(std::move(d));
    return;
  }
  d.message += "\n" + state_text(*f.counterexample);
  out.push_back(d);
  for (size_t i = 1; i < f.rules.size(); ++i) {
    for (const model::Connection& c : app.connections) {
      if (c.name != f.rules[i] || (!f.port.empty() && c.destination != f.port)) continue;
      if (c.loc.line == f.loc.line && c.loc.column == f.loc.column) continue;
      Diagnostic other = d;
      other.loc = c.loc;
      Diagnostic back;
      back.severity = Severity::Note;
      back.loc = f.loc;
      back.message = "the other rule: '" + f.rules[0] + "'";
      other.notes.insert(other.notes.begin(), back);
      out.push_back(std::move(other));
    }
  }
}

}  // namespace

Verification verify_text(const std::string& text, int version, const std::string& file,
                         const std::string& script_dir, ParserGate& gate, double timeout_seconds) {
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
  v.summary = std::string(verify::verdict_name(report->verdict)) + ": " +
              std::to_string(report->ports.size()) + " arbitrated ports, " +
              std::to_string(report->count(Severity::Error)) + " errors, " +
              std::to_string(report->count(Severity::Warning)) + " warnings";
  return v;
}

}  // namespace arbc::lsp
