#include "verify/temporal/assumption.h"

#include "core/duration_literal.h"
#include "core/time_text.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {

std::vector<model::Assumption> assumptions_about(const model::App& app, const std::string& port) {
  std::vector<model::Assumption> about;
  for (const model::Assumption& a : app.assumptions)
    if (a.port == port) about.push_back(a);
  return about;
}

bool add_port_assumptions(const model::App& app, PortShape& shape, std::string* err) {
  for (const model::Assumption& a : assumptions_about(app, shape.port)) {
    PortShape::Assumed assumed{a, rule_index(shape, a.after),
                               a.until.empty() ? -1 : rule_index(shape, a.until)};
    const std::string& missing = assumed.after < 0 ? a.after : a.until;
    if (assumed.after < 0 || (!a.until.empty() && assumed.until < 0)) {
      *err = "the assumption at line " + std::to_string(a.loc.line) + " names rule '" + missing +
             "', which " + shape.port + " does not have";
      return false;
    }
    shape.assumptions.push_back(std::move(assumed));
  }
  return true;
}

z3::expr Unrolling::armed_before(int on, int off, int k) const {
  std::vector<z3::expr>& terms = armed_[{on, off}];
  if (terms.empty()) {
    // Any state: one free Boolean per monitor, so a precedence property and an assumption that
    // follow the same pair of rules share it (their monitors are the same function of the run).
    std::string name = "armed0!" + std::to_string(on) + "!" + std::to_string(off);
    terms.push_back(start_ == Start::AnyState ? ctx_.bool_const(name.c_str())
                                              : ctx_.bool_val(false));
    // Where own delivery entries tie the state to the order of the rules' last deliveries
    // (Unrolling::constrain_own_deliveries_at_start), the monitor is that order's function too:
    // armed when `on` delivered after `off`'s last delivery (or `off` never delivered).
    if (start_ == Start::AnyState && has_own_deliveries()) {
      z3::expr later = off < 0 || off == on ? ctx_.bool_val(true)
                                            : !delivered_before_start(off) ||
                                                  order_before_start(off) < order_before_start(on);
      solver_.add(terms[0] == (delivered_before_start(on) && later));
    }
  }
  while (static_cast<int>(terms.size()) <= k) {
    int i = static_cast<int>(terms.size()) - 1;
    z3::expr stays = off < 0 ? terms[i] : terms[i] && !del_[i][static_cast<size_t>(off)];
    terms.push_back(del_[i][static_cast<size_t>(on)] || stays);
  }
  return terms[static_cast<size_t>(k)];
}

// At step k's decision the assumed event is present only while its monitor is armed, or, for
// the timed form, not less than D after a delivery of its rule (the rule's last delivery
// before the first step included, from any state). The event's entries belong to feeds (the
// front end refuses an assumption about an event that monitor code sets), so this constrains
// the environment, not the app.
void Unrolling::add_assumptions(int k) {
  for (const PortShape::Assumed& a : shape_.assumptions) {
    z3::expr absent = !present_at_decision(a.assumption.event, k);
    if (!a.assumption.absent_for) {
      solver_.add(z3::implies(!armed_before(a.after, a.until, k), absent));
      continue;
    }
    z3::expr d = nanos_term(ctx_, *a.assumption.absent_for);
    for (int i = 0; i < k; ++i)
      solver_.add(z3::implies(del_[i][static_cast<size_t>(a.after)] && t_[k] - t_[i] < d, absent));
    solver_.add(z3::implies(
        delivered_before_start(a.after) && t_[k] - last_delivery_before_start(a.after) < d,
        absent));
  }
}

}  // namespace arbc::verify::temporal
