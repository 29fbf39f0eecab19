#include "compiler/lower/event_effects.h"

#include <map>
#include <regex>

namespace arbc::lower {

namespace {

enum class EventState { Set, Unset };

// What is known on one path through a body.
struct PathState {
  std::map<std::string, EventState> known;
  bool rejects = false;  // the path ends in `accept false`: it never accepts
};

void walk(const ast::Block& block, PathState& path, EventEffects& effects);

PathState merge(const PathState& a, const PathState& b) {
  if (a.rejects) return b;
  if (b.rejects) return a;
  PathState out;
  for (const auto& [event, state] : a.known) {
    auto it = b.known.find(event);
    if (it != b.known.end() && it->second == state) out.known[event] = state;
  }
  return out;
}

bool is_literal_false(const ast::Expr* e) {
  return e && e->kind == ast::Expr::Kind::Bool && !e->boolean;
}

void walk_stmt(const ast::Stmt& s, PathState& path, EventEffects& effects) {
  using Kind = ast::Stmt::Kind;
  switch (s.kind) {
    case Kind::Set:
      path.known[s.name] = EventState::Set;
      effects.sets.insert(s.name);
      break;
    case Kind::Unset:
      path.known[s.name] = EventState::Unset;
      effects.unsets.insert(s.name);
      break;
    case Kind::Accept:
      if (is_literal_false(s.expr.get())) path.rejects = true;
      break;
    case Kind::If: {
      PathState then_path = path, else_path = path;
      walk(s.body, then_path, effects);
      walk(s.else_body, else_path, effects);
      path = merge(then_path, else_path);
      break;
    }
    case Kind::Every: {
      PathState periodic;  // runs from trig(): not on the message's path
      walk(s.body, periodic, effects);
      break;
    }
    default:
      break;
  }
}

void walk(const ast::Block& block, PathState& path, EventEffects& effects) {
  for (const auto& s : block) {
    // A statement after an `accept false` never runs on a message, but an `every` block runs
    // from trig() whatever the message path does: what it sets is set all the same (the proof
    // had a port whose only setter was such a block never see the event:
    // tests/drt/cases/temporal-every-after-reject).
    if (path.rejects && s->kind != ast::Stmt::Kind::Every) continue;
    walk_stmt(*s, path, effects);
  }
}

}  // namespace

EventEffects body_effects(const ast::Block& body) {
  EventEffects effects;
  PathState path;
  walk(body, path, effects);
  if (path.rejects) return effects;  // never accepts: nothing holds "on every accepting path"
  for (const auto& [event, state] : path.known)
    (state == EventState::Set ? effects.must_set : effects.must_unset).insert(event);
  return effects;
}

EventEffects script_effects(const std::string& script_text) {
  EventEffects effects;
  static const std::regex call(R"((setEvent|unsetEvent)\s*\(\s*["']([A-Za-z_][A-Za-z0-9_]*)["'])");
  for (auto it = std::sregex_iterator(script_text.begin(), script_text.end(), call);
       it != std::sregex_iterator(); ++it) {
    ((*it)[1] == "setEvent" ? effects.sets : effects.unsets).insert((*it)[2]);
  }
  return effects;
}

}  // namespace arbc::lower
