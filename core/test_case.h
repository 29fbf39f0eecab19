// A test of an app (`test "name" { ... }` in a spec, docs/testing.md), after the front end
// checked it: timed inputs, events given directly, and expectations, all with values and
// times resolved. `arbc test` runs these on the embedded runtime in simulated time.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/constraint.h"
#include "core/instant.h"
#include "core/value.h"

namespace arbc::model {

struct TestStep {
  enum class Kind { Input, Set, Unset };
  Kind kind = Kind::Input;
  Nanos t{0};
  std::string port;  // Input: "Module.port", an out-port
  Value value;       // Input
  // Input: the port's type, where the step was made by arbc (a counterexample), so that its
  // value is written back as the spec writes it (a uint64 above 2^63 - 1 is held as its bits,
  // core/type.h); null for steps read from a spec, which need no writing.
  TypePtr type;
  std::string event;  // Set, Unset
  SourceLocation loc;
};

struct Expectation {
  // Delivers, DeliversNothing: the rule delivers (nothing) in the window, whatever it drops.
  // Property: the property over time holds over the whole run (its windows that end after the
  // run are not judged).
  // Exclusive, Assert: a claim about single decisions (the port's exclusivity, an assert over
  // events) holds at every decision of the run, judged as the runtime checks judge it
  // (runtime/decision_watch.h). Resource: no two of the resource's ports receive a command that
  // uses it in one event state (runtime/delivery_watch.h).
  enum class Kind {
    Receives,
    Nothing,
    Drops,
    Delivers,
    DeliversNothing,
    Property,
    State,
    Exclusive,
    Assert,
    Resource
  };
  Kind kind = Kind::Receives;
  // Receives, Nothing: "Module.port", an in-port; Exclusive, Assert: arbitrated; State: the
  // port of `in M.p`, empty for the bare form.
  std::string port;
  std::optional<Value> value;  // Receives: none means any value
  std::string connection;      // Drops, Delivers, DeliversNothing: the rule
  std::string reason;          // Drops: empty means any reason
  Constraint state;            // State
  // State: for each event of `state`, the arbitrated port whose container it is read in (each
  // port holds its own events: core/event_facts.h). Set by lowering, for every event.
  std::map<std::string, std::string> containers;
  std::optional<TemporalProperty> property;  // Property (none: sema reported its port)
  std::optional<Assertion> assertion;        // Assert
  std::string resource;                      // Resource: its name
  // The window, both ends included; without one, the whole test.
  Nanos from{0}, to = kNever;
  std::string text;  // the expectation as written, for failure messages
  SourceLocation loc;
};

struct TestCase {
  std::string name;
  std::string rule;             // `on RULE`: the rule tested alone; empty: the whole app
  std::vector<TestStep> steps;  // in the order written (same-instant steps keep it)
  std::vector<Expectation> expectations;
  SourceLocation loc;
};

}  // namespace arbc::model
