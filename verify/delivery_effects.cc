#include "verify/delivery_effects.h"

#include <algorithm>

#include "core/event_facts.h"

namespace arbc::verify {

namespace {

// Whether every delivery of `rule` whose command satisfies `uses` also satisfies `predicate`:
// no accepted message gives a using command on which the predicate is false or has no value.
bool always_holds(DataQuery& data, const model::Connection& rule, const model::BodyExpr& predicate,
                  const model::BodyExpr* uses) {
  if (!data.opaque_reason(rule).empty() || !data.predicate_opaque_reason(rule, predicate).empty())
    return false;
  if (uses && !data.predicate_opaque_reason(rule, *uses).empty()) return false;
  std::vector<DataSide> sides{{&rule, &predicate, true}};
  if (uses) sides.push_back({&rule, uses, false});
  DataWitness witness;
  DataCore core;
  return data.ask(sides, &witness, &core) == Answer::Unsat;
}

}  // namespace

std::vector<DeliveryEffect> delivery_effects(const model::App& app, DataQuery& data,
                                             const model::Connection& rule, const std::string& port,
                                             const std::vector<std::string>& events,
                                             const model::BodyExpr* uses) {
  std::vector<DeliveryEffect> out;
  for (const model::Connection& f : app.connections) {
    if (f.destination != port || f.source != rule.destination || !model::is_delivery_feed(app, f))
      continue;
    for (const std::string& e : f.sets) {
      if (std::find(events.begin(), events.end(), e) == events.end()) continue;
      const model::Event* event = app.find_event(e);
      bool must = event && event->predicate && always_holds(data, rule, *event->predicate, uses);
      out.push_back({e, must});
    }
  }
  return out;
}

}  // namespace arbc::verify
