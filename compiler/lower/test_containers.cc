#include "compiler/lower/test_containers.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/check_ids.h"
#include "core/event_facts.h"

namespace arbc::lower {

namespace {

bool test_sets(const model::TestCase& test, const std::string& event) {
  return std::any_of(test.steps.begin(), test.steps.end(), [&](const model::TestStep& s) {
    return s.kind == model::TestStep::Kind::Set && s.event == event;
  });
}

// The containers `event` can be present in while `test` runs, as harness/test_runner.cc runs it:
// a test `on RULE` runs that rule alone into its port (no feed, no other rule), so only the
// rule's own sets and the test's `set` steps reach that one container; a whole-app test has
// what lowering puts into each arbitrated port, and a `set` step goes into every container.
std::vector<std::string> containers_of(const model::App& app, const model::TestCase& test,
                                       const std::string& event) {
  bool set_by_test = test_sets(test, event);
  if (!test.rule.empty()) {
    for (const model::Connection& c : app.connections) {
      if (c.kind != model::ConnectionKind::Rule || c.name != test.rule) continue;
      bool sets = c.opaque || c.set_on_delivery(event) ||
                  std::find(c.sets.begin(), c.sets.end(), event) != c.sets.end();
      if (sets || set_by_test) return {c.destination};
    }
    return {};
  }
  std::vector<std::string> held = model::ports_holding(app, event);
  // Only the test's own entries: the same in every container, so any one reads them.
  if (held.empty() && set_by_test && !app.arbitrated_ports.empty())
    return {app.arbitrated_ports.front().port};
  return held;
}

// Whether every container of `ports` holds `event` as one fact (delivery events: set in the
// task of the delivery, with no decision in between), so a bare form still means one thing.
bool one_fact_everywhere(const model::App& app, const std::string& event,
                         const std::vector<std::string>& ports) {
  for (const std::string& p : ports)
    if (!model::one_fact(app, event, ports.front(), p)) return false;
  return true;
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// The expectation as written with `in PORT` before its `at D`.
std::string with_container(const model::Expectation& e, const std::string& port) {
  size_t at = e.text.rfind(" at ");
  std::string text =
      at == std::string::npos ? e.text : e.text.substr(0, at) + " in " + port + e.text.substr(at);
  return "expect " + text + ";";
}

Diagnostic container_error(const model::Expectation& e, std::string message, std::string note) {
  Diagnostic d;
  d.loc = e.loc;
  d.message = std::move(message);
  d.id = diag::TestContainer.text();
  Diagnostic n;
  n.severity = Severity::Note;
  n.message = std::move(note);
  d.notes.push_back(std::move(n));
  return d;
}

// `where`: each event that lives in several containers, with them.
Diagnostic ambiguous(const model::Expectation& e,
                     const std::map<std::string, std::vector<std::string>>& where) {
  std::string what;
  std::vector<std::string> common = where.begin()->second;  // a port to suggest: one in all
  for (const auto& entry : where) {
    // Named, not bound: clang 14 cannot capture a structured binding in a lambda.
    const std::string& event = entry.first;
    const std::vector<std::string>& ports = entry.second;
    what += (what.empty() ? "'" : "; '") + event + "' lives in " + std::to_string(ports.size()) +
            " event containers (" + joined(ports) + ")";
    std::erase_if(common, [&](const std::string& p) {
      return std::find(ports.begin(), ports.end(), p) == ports.end();
    });
  }
  std::string port = common.empty() ? where.begin()->second.front() : common.front();
  return container_error(e,
                         what + ", one fact in each, which can differ: say which container " +
                             "this expectation reads",
                         "write `" + with_container(e, port) + "` (each arbitrated port holds " +
                             "its own events, and its rules read them there)");
}

Diagnostic nowhere(const model::App& app, const model::TestCase& test, const model::Expectation& e,
                   const std::string& event) {
  if (!test.rule.empty()) {
    return container_error(e,
                           "'" + event + "' is never present in this test: it runs rule '" +
                               test.rule +
                               "' alone, whose body does not set it, and no step sets it",
                           "give it with `at D set " + event +
                               ";`, or test the whole app (without `on " + test.rule + "`)");
  }
  std::vector<std::string> ports;
  for (const model::ArbitratedPort& p : app.arbitrated_ports) ports.push_back(p.port);
  return container_error(
      e,
      "'" + event +
          "' is never present in any event container: no rule sets it, and no arbitrated port "
          "reads it, so no feed carries it",
      "read it in a `when` of the port it is about, or give it with `at D set " + event +
          ";`; the containers are those of " + (ports.empty() ? "no port" : joined(ports)));
}

}  // namespace

void resolve_test_containers(const model::App& app, std::vector<model::TestCase>& tests,
                             std::vector<Diagnostic>& diagnostics) {
  for (model::TestCase& test : tests) {
    for (model::Expectation& e : test.expectations) {
      if (e.kind != model::Expectation::Kind::State) continue;
      std::set<std::string> events;
      e.state.collect_events(events);
      std::map<std::string, std::vector<std::string>> several;
      for (const std::string& event : events) {
        if (!e.port.empty()) {
          e.containers[event] = e.port;
          continue;
        }
        std::vector<std::string> ports = containers_of(app, test, event);
        if (ports.size() == 1 || (!ports.empty() && one_fact_everywhere(app, event, ports)))
          e.containers[event] = ports.front();
        else if (ports.empty())
          diagnostics.push_back(nowhere(app, test, e, event));
        else
          several[event] = ports;
      }
      if (!several.empty()) diagnostics.push_back(ambiguous(e, several));
    }
  }
}

}  // namespace arbc::lower
