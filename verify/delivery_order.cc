#include "verify/delivery_order.h"

#include <algorithm>

#include "core/join.h"

namespace arbc::verify {

namespace {

bool lists(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// Every entry of `e` in the port is one a delivery sets: no monitor sets it, no script.
bool only_deliveries_set(const std::string& e, std::span<const model::Connection* const> into) {
  return std::none_of(into.begin(), into.end(), [&](const model::Connection* c) {
    return c->opaque || (lists(c->sets, e) && !c->set_on_delivery(e));
  });
}

Constraint substitute(const Constraint& c, const model::Connection& d,
                      std::span<const model::Connection* const> into) {
  switch (c.op) {
    case Constraint::Op::True:
    case Constraint::Op::False:
      return c;
    case Constraint::Op::Event:
      if (lists(d.delivery_sets, c.event)) return Constraint::constant(true);
      if (lists(d.delivery_unsets, c.event) && only_deliveries_set(c.event, into))
        return Constraint::constant(false);
      return c;
    case Constraint::Op::Not:
      return Constraint::negate(substitute(c.args[0], d, into));
    case Constraint::Op::And:
    case Constraint::Op::Or: {
      std::vector<Constraint> args;
      for (const Constraint& a : c.args) args.push_back(substitute(a, d, into));
      return c.op == Constraint::Op::And ? Constraint::conjunction(std::move(args))
                                         : Constraint::disjunction(std::move(args));
    }
  }
  return c;
}

std::string effects_text(const model::Connection& c) {
  std::vector<std::string> parts;
  for (const std::string& e : c.delivery_sets) parts.push_back("sets " + e);
  for (const std::string& e : c.delivery_unsets) parts.push_back("unsets " + e);
  return parts.empty() ? "changes nothing" : join(parts, " and ");
}

}  // namespace

bool has_delivery_effects(const model::Connection& c) {
  return !c.delivery_sets.empty() || !c.delivery_unsets.empty();
}

Constraint after_delivery(const Constraint& guard, const model::Connection& deliverer,
                          std::span<const model::Connection* const> into) {
  if (!has_delivery_effects(deliverer)) return guard;
  return substitute(guard, deliverer, into);
}

DeliveryOrder delivery_order(PortSolver& solver, const PortScope& scope, int i, int j,
                             std::string* text) {
  const ScopedRule& a = scope.rules[static_cast<size_t>(i)];
  const ScopedRule& b = scope.rules[static_cast<size_t>(j)];
  if (!has_delivery_effects(*a.connection) && !has_delivery_effects(*b.connection))
    return DeliveryOrder::Overlap;
  std::vector<const model::Connection*> into;
  for (const ScopedRule& r : scope.rules) into.push_back(r.connection);
  // The state `first` delivers in, and `second` selected in the state that delivery leaves.
  auto after = [&](const ScopedRule& first, int first_index, const ScopedRule& second) {
    return solver.holds_with(first_index,
                             after_delivery(second.effective_guard, *first.connection, into));
  };
  auto unless_kept_out = [](Answer ans) {
    return ans == Answer::Sat ? DeliveryOrder::Overlap : DeliveryOrder::Unknown;
  };
  // The second order is asked only when the first is kept out: one order overlapping suffices.
  if (Answer ab = after(a, i, b); ab != Answer::Unsat) return unless_kept_out(ab);
  if (Answer ba = after(b, j, a); ba != Answer::Unsat) return unless_kept_out(ba);
  *text = "'" + a.connection->name + "' and '" + b.connection->name +
          "': whichever delivers first keeps the other out ('" + a.connection->name + "' " +
          effects_text(*a.connection) + ", '" + b.connection->name + "' " +
          effects_text(*b.connection) + " as it delivers)";
  return DeliveryOrder::KeepsOut;
}

}  // namespace arbc::verify
