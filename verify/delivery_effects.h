// What a rule's delivery does to another port's container (docs/language.md#delivery-events):
// the feeds of delivery events run in the same task as the delivery, so the next decision of
// any port they feed already sees them. The resource check (verify/resource_checks.h) uses it
// for two decisions in a row: one rule delivers, then a rule of the other port decides.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "verify/data_query.h"

namespace arbc::verify {

struct DeliveryEffect {
  std::string event;  // the event, in `port`'s container
  // Present after every delivery of the rule that uses the resource: its predicate holds on
  // every such command (asked of the data encoding). Otherwise the delivery may leave the
  // event either way, and the check takes both.
  bool must_set = false;
};

// The delivery events that `rule`'s deliveries (those whose command satisfies `uses`; every one
// without it) feed into `port`'s container, among `events` (the ones that port's rules read).
// Unknown answers and bodies the data encoding cannot read give `must_set = false`.
std::vector<DeliveryEffect> delivery_effects(const model::App& app, DataQuery& data,
                                             const model::Connection& rule, const std::string& port,
                                             const std::vector<std::string>& events,
                                             const model::BodyExpr* uses);

}  // namespace arbc::verify
