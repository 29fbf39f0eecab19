#include "core/effective_guard.h"

#include <algorithm>

namespace arbc::model {

namespace {

// The parts of E_c after G_c and act_c: the events c's monitor sets or unsets before the
// decision on every accepting path.
void add_monitor_effects(std::span<const Connection* const> into, const Connection& rule,
                         std::vector<Constraint>& parts) {
  if (rule.opaque) return;
  for (const std::string& e : rule.must_set) parts.push_back(Constraint::event_ref(e));
  for (const std::string& e : rule.must_unset) {
    // A `script` rule may set any event: its `sets` are only the names it passes to setEvent
    // as literals, and a name it computes keeps the event present after this unset.
    bool set_elsewhere = std::any_of(into.begin(), into.end(), [&](const Connection* other) {
      return other != &rule && (other->opaque || std::find(other->sets.begin(), other->sets.end(),
                                                           e) != other->sets.end());
    });
    if (!set_elsewhere) parts.push_back(Constraint::negate(Constraint::event_ref(e)));
  }
}

}  // namespace

Constraint effective_guard(std::span<const Connection* const> into, const Connection& rule) {
  std::vector<Constraint> parts{rule.constraint};
  // The runtime sets the activity event as the rule delivers, whatever its monitor does: a
  // delivery's decision state includes it (docs/design.md#priorities-and-holds).
  if (!rule.activity_event.empty()) parts.push_back(Constraint::event_ref(rule.activity_event));
  add_monitor_effects(into, rule, parts);
  return Constraint::conjunction(std::move(parts));
}

Constraint decision_guard(std::span<const Connection* const> into, const Connection& rule) {
  std::vector<Constraint> parts{rule.constraint};
  add_monitor_effects(into, rule, parts);
  return parts.size() == 1 ? rule.constraint : Constraint::conjunction(std::move(parts));
}

Constraint effective_guard(const App& app, std::string_view port, const Connection& rule) {
  return effective_guard(app.connections_into(port), rule);
}

}  // namespace arbc::model
