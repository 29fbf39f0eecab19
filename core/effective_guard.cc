#include "core/effective_guard.h"

#include <algorithm>

namespace arbc::model {

Constraint effective_guard(std::span<const Connection* const> into, const Connection& rule) {
  std::vector<Constraint> parts{rule.constraint};
  // The runtime sets the activity event as the rule delivers, whatever its monitor does: a
  // delivery's decision state includes it (docs/design.md#priorities-and-holds).
  if (!rule.activity_event.empty()) parts.push_back(Constraint::event_ref(rule.activity_event));
  if (rule.opaque) return Constraint::conjunction(std::move(parts));
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
  return Constraint::conjunction(std::move(parts));
}

Constraint effective_guard(const App& app, std::string_view port, const Connection& rule) {
  return effective_guard(app.connections_into(port), rule);
}

}  // namespace arbc::model
