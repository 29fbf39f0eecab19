#include "compiler/docs/monitor_summary.h"

#include "core/duration_literal.h"
#include "core/join.h"

namespace arbc::docs {

namespace {

// Whether the body has a statement of kind `kind`, at any depth (inside `if` and `every`).
bool has_statement(const model::Body& body, model::BodyStmt::Kind kind) {
  for (const model::BodyStmt& s : body) {
    if (s.kind == kind || has_statement(s.then_body, kind) || has_statement(s.else_body, kind))
      return true;
  }
  return false;
}

}  // namespace

std::string monitor_summary(const model::Connection& c) {
  std::vector<std::string> parts;
  if (c.kind == model::ConnectionKind::Feed) {
    parts.push_back("feeds " + join(c.sets) + " into the container; never delivers");
  } else {
    if (c.opaque) parts.push_back("hand-written script");
    // From the rule's body: `accept` may refuse a message, `emit` delivers another value.
    if (c.body && has_statement(*c.body, model::BodyStmt::Kind::Accept)) parts.push_back("filters");
    if (c.body && has_statement(*c.body, model::BodyStmt::Kind::Emit))
      parts.push_back("transforms");
    if (!c.sets.empty()) parts.push_back("sets " + join(c.sets));
    if (!c.unsets.empty()) parts.push_back("unsets " + join(c.unsets));
    // Times as the spec writes them (`throttle 500ms`).
    if (c.throttle) parts.push_back("at most one delivery per " + duration_literal(*c.throttle));
    if (c.trig_interval) parts.push_back("runs every " + duration_literal(*c.trig_interval));
  }
  if (parts.empty()) {
    if (c.monitor.empty()) {
      parts.push_back("none");
    } else {
      parts.push_back(c.body ? "passes every message through unchanged" : "a monitor");
    }
  }
  return join(parts);
}

}  // namespace arbc::docs
