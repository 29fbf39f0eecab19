#include "compiler/codegen/yarp_target.h"

#include <map>

#include "compiler/codegen/monitor_writer.h"
#include "compiler/codegen/yarp_app_xml.h"
#include "compiler/codegen/yarp_monitor.h"
#include "compiler/codegen/yarp_names.h"
#include "compiler/frontend/lua_syntax.h"
#include "compiler/lower/lowered_app.h"
#include "core/check_ids.h"

namespace arbc::codegen {

namespace {

// Two spec ports that end up with one YARP name (an override equal to another's default).
bool unique_port_names(const model::App& app, const YarpNames& names, Diagnostic* d) {
  std::map<std::string, std::string> seen;
  for (const model::Module& m : app.modules) {
    for (const model::Port& p : m.ports) {
      std::string q = m.name + "." + p.name, y = names.port(q);
      auto [it, fresh] = seen.emplace(y, q);
      if (fresh) continue;
      d->loc = p.loc;
      d->id = diag::Codegen.text();
      d->message = "ports " + it->second + " and " + q + " would both be the YARP port " + y +
                   "; name one of them in the deployment file's \"topics\"";
      return false;
    }
  }
  return true;
}

// A delivery event (docs/language.md#delivery-events) is set in the task of a delivery into
// another port. On YARP each arbitrator runs in the process of its port's module and keeps its
// events there, so no monitor can set an event where another module's arbitrator reads it.
bool no_delivery_events(const model::App& app, std::vector<Diagnostic>& out) {
  bool ok = true;
  for (const model::Event& e : app.events) {
    const model::Port* p = app.find_port(e.source);
    if (!p || p->direction != model::Direction::In) continue;
    Diagnostic d;
    d.loc = e.loc;
    d.id = diag::Codegen.text();
    d.message = "delivery event '" + e.name + "' (what " + e.source +
                " delivers) cannot be built for YARP: each YARP arbitrator keeps its events in "
                "its own module's process, where no other port's delivery can set them; build "
                "for the embedded runtime or DDS, or leave the event out of this target's spec";
    out.push_back(std::move(d));
    ok = false;
  }
  return ok;
}

// One `codegen` error per connection that `why` gives a message for; false if there is one.
template <typename Why>
bool refuse_connections(const model::App& app, std::vector<Diagnostic>& out, Why why) {
  bool ok = true;
  for (const model::Connection& c : app.connections) {
    std::string message = why(c);
    if (message.empty()) continue;
    out.push_back(
        make_diagnostic(Severity::Error, c.loc, std::move(message), diag::Codegen.text()));
    ok = false;
  }
  return ok;
}

// `then set` / `then unset` (docs/language.md#events-set-on-delivery) change the port's events
// in the task of the delivery, before any other decision; a YARP arbitrator has no such step
// (its monitors run as each message is read), and an unset there removes only the caller's
// own entry, not another rule's.
bool no_delivery_effects(const model::App& app, std::vector<Diagnostic>& out) {
  return refuse_connections(app, out, [](const model::Connection& c) -> std::string {
    if (c.delivery_sets.empty() && c.delivery_unsets.empty()) return "";
    return "rule '" + c.name +
           "' sets or unsets events as it delivers (`then ...`), which cannot be built for "
           "YARP: a YARP arbitrator has no step between a delivery and the next decision; "
           "build for the embedded runtime or DDS";
  });
}

bool calls_age(const model::BodyExpr& e) {
  if (e.op == model::BodyExpr::Op::Call && e.builtin == Builtin::Age) return true;
  for (const model::BodyExpr& a : e.args)
    if (calls_age(a)) return true;
  return false;
}

bool calls_age(const model::Body& body) {
  for (const model::BodyStmt& s : body)
    if (calls_age(s.expr) || calls_age(s.then_body) || calls_age(s.else_body)) return true;
  return false;
}

// age() (docs/language.md#message-age): the proof has the rules that judge one message read one
// clock, the instant it arrived, which the embedded runtime gives them; on YARP each monitor
// reads yarp.now() when it runs, in its own module's process, so two rules could read two.
bool no_ages(const model::App& app, std::vector<Diagnostic>& out) {
  return refuse_connections(app, out, [](const model::Connection& c) -> std::string {
    if (!c.body || !calls_age(*c.body)) return "";
    return "'" + c.name +
           "' calls age(), which cannot be built for YARP: the proof has the "
           "rules that judge one message read one clock, and each YARP monitor reads its "
           "own; build for the embedded runtime or DDS";
  });
}

}  // namespace

bool YarpTarget::configure(const TargetOptions& options, std::string*) {
  options_ = options;
  return true;
}

CodegenResult YarpTarget::generate(const lower::LoweredApp& lowered) const {
  CodegenResult result;
  const model::App& app = lowered.app;
  YarpNames names(app, options_.port_names);
  Diagnostic clash;
  if (!unique_port_names(app, names, &clash)) {
    result.diagnostics.push_back(clash);
    result.bad_input = true;
  }
  if (!no_delivery_events(app, result.diagnostics) || !no_ages(app, result.diagnostics) ||
      !no_delivery_effects(app, result.diagnostics)) {
    result.bad_input = true;
    return result;
  }
  SpecLines lines(lowered.spec_text);
  frontend::LuaSyntaxChecker lua;
  std::vector<OutputFile> monitors;
  for (const YarpLink& link : names.links()) {
    if (link.monitor.empty()) continue;
    std::string text = write_yarp_monitor(lowered, link, names, lines, result.diagnostics);
    std::string path = yarp_monitor_path(app, link), error;
    if (!lua.check(text, path, &error)) {
      Diagnostic d;
      d.loc = app.connections[link.parts[0]].loc;
      d.id = diag::Codegen.text();
      d.message = "internal error: the YARP monitor generated for '" + link.id +
                  "' is not valid Lua (" + error + "); please report this with the spec";
      result.diagnostics.push_back(std::move(d));
    }
    monitors.push_back({path, std::move(text)});
  }
  result.files.push_back({app.name + ".xml", yarp_application_xml(app, names)});
  result.files.push_back({"ports.json", yarp_port_map(app, names)});
  for (OutputFile& f : monitors) result.files.push_back(std::move(f));
  result.ok = result.diagnostics.empty();
  return result;
}

}  // namespace arbc::codegen
