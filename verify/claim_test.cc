#include "verify/claim_test.h"

#include <utility>

#include "core/duration_literal.h"
#include "core/join.h"
#include "core/json_text.h"

namespace arbc::verify {

namespace {

// A message `c` accepts from a fresh monitor; nullopt with *why_not when none can be given.
std::optional<Value> witness(const model::Connection& c, DataQuery& data, std::string* why_not) {
  std::string opaque = data.opaque_reason(c);
  if (!opaque.empty()) {
    *why_not = "'" + c.name + "' is opaque for data (" + opaque + ")";
    return std::nullopt;
  }
  DataWitness w;
  Answer a = data.ask({{&c, nullptr}}, &w, nullptr);
  if (a != Answer::Sat) {
    *why_not = a == Answer::Unsat
                   ? "'" + c.name + "' accepts no message"
                   : "no message found for '" + c.name + "' (" + data.unknown_reason() + ")";
    return std::nullopt;
  }
  if (!w.assumed_state[0].empty()) {
    *why_not = "'" + c.name + "' accepts only with monitor state " + join(w.assumed_state[0]);
    return std::nullopt;
  }
  return w.messages[0];
}

// Runs the test: it must break its claim on the app it came from.
bool breaks_claim(const model::TestCase& test, const TestReplayer* replayer,
                  const std::string& kept_because, std::string* why_not) {
  if (!replayer) return true;
  std::string err;
  std::optional<std::string> failure = replayer->judge(test, &err);
  if (!failure)
    *why_not = "its replay on the runtime could not be run (" + err + ")";
  else if (failure->empty())
    *why_not = "its replay on the runtime keeps the claim (" +
               (kept_because.empty()
                    ? std::string("a monitor of the same source may change the events before "
                                  "the decision")
                    : kept_because) +
               "), so the test would pass on this app";
  return failure && !failure->empty();
}

}  // namespace

DataQuery& ReplayData::data() {
  if (!data_) {
    ctx_ = std::make_unique<z3::context>();
    if (watchdog_) watchdog_->watch_also(*ctx_);
    data_ = std::make_unique<DataQuery>(app_, *ctx_, list_bound_, deadline_);
  }
  return *data_;
}

std::optional<model::TestCase> decision_test(const DecisionReplay& r, DataQuery& data,
                                             const TestReplayer* replayer, std::string* why_not) {
  model::TestCase test;
  test.name = r.name;
  // The state first: the steps of one instant run in the order written
  // (docs/testing.md#how-tests-run), so the rules decide in it. A hold's activity event
  // (act_RULE) is the runtime's: a test cannot set it (sema: unknown-event).
  for (const std::string& e : r.state.present) {
    bool activity = false;
    for (const model::Connection& c : data.app().connections) activity |= c.activity_event == e;
    if (activity) {
      *why_not = "its state has " + e + " present, which a test cannot `set`";
      return std::nullopt;
    }
    model::TestStep s;
    s.kind = model::TestStep::Kind::Set;
    s.event = e;
    test.steps.push_back(std::move(s));
  }
  std::vector<std::string> sources;  // one message per source
  for (size_t i = 0; i < r.rules.size(); ++i) {
    const model::Connection& c = *r.rules[i];
    bool shared = false;
    for (const std::string& s : sources) shared |= s == c.source;
    if (shared && !r.message_per_rule) continue;
    std::optional<Value> message = r.messages[i];
    if (!message) message = witness(c, data, why_not);
    if (!message) return std::nullopt;
    model::TestStep s;
    s.port = c.source;
    s.value = std::move(*message);
    if (const model::Port* p = data.app().find_port(c.source)) s.type = p->type;
    test.steps.push_back(std::move(s));
    sources.push_back(c.source);
  }
  test.expectations.push_back(r.claim);
  if (!breaks_claim(test, replayer, r.kept_because, why_not)) return std::nullopt;
  return test;
}

model::Expectation exclusive_claim(const std::string& port) {
  model::Expectation e;
  e.kind = model::Expectation::Kind::Exclusive;
  e.port = port;
  e.text = "exclusive " + port;
  return e;
}

model::Expectation resource_claim(const std::string& name) {
  model::Expectation e;
  e.kind = model::Expectation::Kind::Resource;
  e.resource = name;
  e.text = "resource " + name;
  return e;
}

model::Expectation assert_claim(const std::string& port, const model::Assertion& a) {
  model::Expectation e;
  e.kind = model::Expectation::Kind::Assert;
  e.port = port;
  e.assertion = a;
  e.text = model::assertion_text(port, a);  // as the runtime check names it
  return e;
}

const char* const kDecisionTestHeader =
    "// A counterexample `arbc verify` found, kept as a regression test: it expects the claim\n"
    "// itself over these inputs, so `arbc test --no-verify FILE` fails on that app and passes\n"
    "// once it is fixed. The counterexample's event state is given directly (`set`), then\n"
    "// messages the rules accept.\n";

std::string counterexample_file_text(const model::TestCase& replay, const std::string& claim,
                                     const std::string& spec_path, const std::string& header) {
  std::string out = header;
  // The name quotes the claim, which may hold a string literal: written as a spec string, quotes
  // and backslashes escaped (as a value's strings are, spec_value_text).
  out += "tests for \"" + spec_path + "\";\n\ntest ";
  append_json_string(out, replay.name);
  out += " {\n";
  for (const model::TestStep& s : replay.steps) {
    out += "  at " + duration_literal(s.t) + " ";
    switch (s.kind) {
      case model::TestStep::Kind::Input:
        out += s.port + " <- " + spec_value_text(s.value, s.type.get()) + ";\n";
        break;
      case model::TestStep::Kind::Set:
        out += "set " + s.event + ";\n";
        break;
      case model::TestStep::Kind::Unset:
        out += "unset " + s.event + ";\n";
        break;
    }
  }
  out += "  expect " + claim + ";\n";
  return out + "}\n";
}

}  // namespace arbc::verify
