#include "compiler/docs/decision_table.h"

#include <map>
#include <set>

#include "core/compiled_constraint.h"
#include "core/effective_guard.h"

namespace arbc::docs {

namespace {

// A cube maps an event to its required presence.
using Cube = std::map<std::string, bool>;

bool merge(const Cube& a, const Cube& b, Cube* out) {
  *out = a;
  for (const auto& [event, value] : b) {
    auto [it, inserted] = out->emplace(event, value);
    if (!inserted && it->second != value) return false;
  }
  return true;
}

// Expands c (negated when `negate`) into cubes; stops growing past `cap`.
std::vector<Cube> expand(const Constraint& c, bool negate, size_t cap, bool* truncated) {
  using Op = Constraint::Op;
  switch (c.op) {
    case Op::True:
    case Op::False:
      return (c.op == Op::True) != negate ? std::vector<Cube>{Cube{}} : std::vector<Cube>{};
    case Op::Event:
      return {Cube{{c.event, !negate}}};
    case Op::Not:
      return expand(c.args[0], !negate, cap, truncated);
    case Op::And:
    case Op::Or: {
      // De Morgan: a negated conjunction is a disjunction of negations.
      bool conjunctive = (c.op == Op::And) != negate;
      if (!conjunctive) {
        std::vector<Cube> out;
        for (const Constraint& a : c.args) {
          for (Cube& cube : expand(a, negate, cap, truncated)) {
            if (out.size() >= cap) {
              *truncated = true;
              return out;
            }
            out.push_back(std::move(cube));
          }
        }
        return out;
      }
      std::vector<Cube> acc{Cube{}};
      for (const Constraint& a : c.args) {
        std::vector<Cube> next;
        for (const Cube& right : expand(a, negate, cap, truncated)) {
          for (const Cube& left : acc) {
            Cube merged;
            if (!merge(left, right, &merged)) continue;
            if (next.size() >= cap) {
              *truncated = true;
              break;
            }
            next.push_back(std::move(merged));
          }
        }
        acc = std::move(next);
      }
      return acc;
    }
  }
  return {};
}

std::string cube_text(const Cube& cube) {
  if (cube.empty()) return "true";
  std::string s;
  for (const auto& [event, value] : cube) {
    if (!s.empty()) s += " and ";
    if (!value) s += "not ";
    s += event;
  }
  return s;
}

}  // namespace

std::string dnf_text(const Constraint& c, size_t max_cubes) {
  bool truncated = false;
  std::vector<Cube> cubes = expand(c, false, max_cubes, &truncated);
  if (cubes.empty()) return "false";
  std::string s;
  for (const Cube& cube : cubes) {
    if (!s.empty()) s += " or ";
    s += cube_text(cube);
  }
  if (truncated) s += " or ...";
  return s;
}

DecisionTable decision_table(const model::App& app, const model::ArbitratedPort& port) {
  return decision_table(port, app.connections_into(port.port));
}

DecisionTable decision_table(const model::ArbitratedPort& port,
                             std::span<const model::Connection* const> into) {
  DecisionTable table;
  table.port = port.port;
  std::vector<Constraint> guards;
  std::set<std::string> events;
  for (const std::string& name : port.rules) {
    for (const model::Connection* c : into) {
      if (c->name != name || c->kind != model::ConnectionKind::Rule) continue;
      guards.push_back(model::effective_guard(into, *c));
      guards.back().collect_events(events);
      table.rules.push_back({name, guards.back().to_string(), dnf_text(guards.back())});
    }
  }
  table.events.assign(events.begin(), events.end());
  table.tabulated = static_cast<int>(table.events.size()) <= kMaxTableEvents;
  if (!table.tabulated) return table;

  // The runtime's own evaluator decides each state, so the table shows what would run.
  EventIndex index;
  for (const std::string& e : table.events) index.intern(e);
  std::vector<CompiledConstraint> compiled;
  for (const Constraint& g : guards) compiled.push_back(CompiledConstraint::compile(g, index));
  size_t n = table.events.size();
  for (size_t state = 0; state < (size_t{1} << n); ++state) {
    DecisionRow row;
    EventMask mask;
    for (size_t i = 0; i < n; ++i) {
      bool present = (state >> (n - 1 - i)) & 1;  // first column is the most significant bit
      row.present.push_back(present);
      if (present) mask.set(static_cast<int>(i));
    }
    for (size_t r = 0; r < compiled.size(); ++r)
      if (compiled[r].evaluate(mask)) row.selected.push_back(table.rules[r].rule);
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace arbc::docs
