// The result of lowering a checked spec (docs/lowering.md): the core model
// (core/app_model.h) that app.json, the verifier and the runtime read, plus one monitor
// plan per connection that code generation turns into Lua. Plans point into the checked AST,
// which the LoweredApp keeps alive.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compiler/frontend/ast.h"
#include "core/app_model.h"
#include "core/constraint.h"

namespace arbc::lower {

// `events from M.p { e = "flag" }`: one status flag copied into a port's container.
struct StatusFlagFeed {
  std::string event;
  std::string flag;                // the module's own flag name
  std::optional<double> lifetime;  // seconds; none: until a message lacks the flag
  model::SourceLocation loc;       // the `events from` entry
};

// `event e = M.p : PRED [for D]`: a derived event recomputed on each message.
struct DerivedFeed {
  std::string event;
  const ast::Expr* predicate = nullptr;
  std::optional<double> lifetime;  // `for D`: set for D, never unset; none: unset when false
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

  // Rule / Connect
  const ast::Block* body = nullptr;  // null or empty: accept everything, deliver unchanged
  std::optional<ScriptSource> script;
};

struct LoweredApp {
  std::shared_ptr<const ast::Spec> spec;  // owns what the plans point into
  std::string spec_text;                  // the spec's source, quoted in monitor comments
  model::App app;
  std::vector<MonitorPlan> monitors;  // parallel to app.connections
};

}  // namespace arbc::lower
