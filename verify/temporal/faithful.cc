// The faithful unrolling (PortShape::faithful): what a replay of a counterexample does, which
// the free model of docs/design.md#properties-over-time does not tie down. It does not drop an
// `every` block's effects from a rule's steps: the runtime runs every trig, and a model without
// them would miss what the trigs do (the unrolling has no step for a trig), so such a
// counterexample stays unknown rather than a run narrower than the runtime's. A counterexample the
// free model finds and the runtime does not show is searched for again under these constraints
// (verify.cc), so that only a run the runtime can make is reported as a violation.
#include <algorithm>

#include "verify/temporal/rates.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {
namespace {

// The connections into the port from `source`, in model order (the order the runtime hands a
// message to them: Runtime::from_source, connections in app.json order).
std::vector<int> from_source(const PortShape& shape, const std::string& source) {
  std::vector<int> out;
  for (size_t c = 0; c < shape.connections.size(); ++c)
    if (shape.connections[c]->source == source) out.push_back(static_cast<int>(c));
  return out;
}

}  // namespace

void Unrolling::add_faithful(int k) {
  // One message, every connection from its source, one after the other at one instant: a step
  // that is not its group's first continues the message of the step before, and the step
  // after one that is not its group's last continues it (the last step may end mid-message).
  for (size_t c = 0; c < shape_.connections.size(); ++c) {
    std::vector<int> group = from_source(shape_, shape_.connections[c]->source);
    auto at = std::find(group.begin(), group.end(), static_cast<int>(c));
    int i = static_cast<int>(at - group.begin());
    bool first = i == 0, last = i + 1 == static_cast<int>(group.size());
    if (!first) {
      z3::expr previous = k > 0 ? run_[k - 1] == group[i - 1] && t_[k - 1] == t_[k]
                                : ctx_.bool_val(start_ == Start::AnyState);
      solver_.add(z3::implies(run_[k] == static_cast<int>(c), previous));
    }
    if (!last && k > 0)
      solver_.add(z3::implies(run_[k - 1] == static_cast<int>(c),
                              run_[k] == group[i + 1] && t_[k] == t_[k - 1]));
  }
  // A rule whose monitor accepts every message accepts this one (verify/temporal/rates.h).
  for (size_t c = 0; c < shape_.connections.size(); ++c)
    if (accepts_every_message(*shape_.connections[c]))
      solver_.add(z3::implies(run_[k] == static_cast<int>(c), acc_[k]));
  // A derived event whose predicate is a constant: every message sets it (or none does, and
  // without `for` each unsets it), whatever its data.
  for (size_t q = 0; q < shape_.entries.size(); ++q) {
    const Entry& e = shape_.entries[q];
    if (!e.constant_predicate) continue;
    z3::expr running = run_[k] == e.owner;
    if (*e.constant_predicate) {
      solver_.add(z3::implies(running, set_[k][q]));
    } else {
      solver_.add(!set_[k][q]);
      if (!e.lifetime) solver_.add(z3::implies(running, unset_[k][q]));
    }
  }
}

}  // namespace arbc::verify::temporal
