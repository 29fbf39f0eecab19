// The result of lowering a checked spec (docs/lowering.md): the core model
// (core/app_model.h) that app.json, the verifier and the runtime read, plus one monitor
// plan per connection that code generation turns into Lua. Nothing here points into the AST:
// a rule's body is its connection's model::Body, the IR the proof encodes
// (docs/design.md#pipeline), and a plan adds only what a feed needs besides.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/body.h"
#include "core/constraint.h"
#include "core/test_case.h"

namespace arbc::lower {

// `events from M.p { e = "flag" }`: one status flag copied into a port's container.
struct StatusFlagFeed {
  std::string event;
  std::string flag;               // the module's own flag name
  std::optional<Nanos> lifetime;  // none: until a message lacks the flag
  model::SourceLocation loc;      // the `events from` entry
};

// `event e = M.p : PRED [for D]`: a derived event recomputed on each message.
struct DerivedFeed {
  std::string event;
  model::BodyExpr predicate;      // over the message, typed (core/body_types.h)
  std::optional<Nanos> lifetime;  // `for D`: set for D, never unset; none: unset when false
  model::SourceLocation loc;
};

// `script "file.lua";`: hand-written accept/update, inlined into the generated monitor.
struct ScriptSource {
  std::string file;  // as resolved against the spec's directory
  std::string text;
  model::SourceLocation loc;
};

struct MonitorPlan {
  enum class Kind { Feed, Rule, Connect };
  Kind kind = Kind::Rule;
  size_t connection = 0;     // index into LoweredApp::app.connections
  std::string message_name;  // what the incoming message is called in the spec (`objects`)

  // Feed
  std::vector<StatusFlagFeed> status_flags;
  std::vector<DerivedFeed> derived;

  // Rule / Connect: the body is the connection's `body` (none or empty: accept everything,
  // deliver unchanged), unless it is a hand-written script.
  std::optional<ScriptSource> script;
};

struct LoweredApp {
  std::string spec_text;  // the spec's source, quoted in monitor comments
  model::App app;
  std::vector<MonitorPlan> monitors;   // parallel to app.connections
  std::vector<model::TestCase> tests;  // the spec's `test` declarations, for `arbc test`
};

}  // namespace arbc::lower
