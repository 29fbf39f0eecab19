#include "verify/port_solver.h"

#include <algorithm>

#include "verify/temporal/constraint_expr.h"

namespace arbc::verify {

PortSolver::PortSolver(const PortScope& scope, z3::context& ctx, Clock::time_point deadline)
    : scope_(scope),
      ctx_(ctx),
      solver_(ctx_, "QF_FD"),
      timeout_(deadline),
      all_events_(ctx_),
      holds_(ctx_) {
  for (const std::string& e : scope_.events) {
    event_vars_.push_back(ctx_.bool_const(e.c_str()));
    all_events_.push_back(event_vars_.back());
  }
  for (const DomainConstraint& d : scope_.domain) {
    if (d.is_invariant) {
      solver_.add(encode(d.formula));
      continue;
    }
    z3::expr_vector group(ctx_);
    for (const std::string& e : d.group) group.push_back(encode(Constraint::event_ref(e)));
    if (group.size() > 1) solver_.add(z3::atmost(group, 1));
  }
  for (size_t i = 0; i < scope_.rules.size(); ++i) {
    z3::expr h = ctx_.bool_const(("holds!" + std::to_string(i)).c_str());
    solver_.add(h == encode(scope_.rules[i].effective_guard));
    holds_.push_back(h);
  }
}

z3::expr PortSolver::encode(const Constraint& c) {
  return temporal::constraint_expr(c, ctx_, [this](const std::string& event) {
    auto it = std::lower_bound(scope_.events.begin(), scope_.events.end(), event);
    // Every event of the scope's formulas is in scope_.events (port_scope.cc collects them).
    return event_vars_[static_cast<size_t>(it - scope_.events.begin())];
  });
}

Answer PortSolver::run(const z3::expr_vector& assumptions) {
  ++queries_;
  switch (verify::check(solver_, timeout_, &unknown_reason_, &assumptions)) {
    case z3::sat:
      return last_ = Answer::Sat;
    case z3::unsat:
      return last_ = Answer::Unsat;
    default:
      return last_ = Answer::Unknown;
  }
}

Answer PortSolver::at_least_two_hold() {
  if (holds_.size() < 2) return last_ = Answer::Unsat;
  // Not only check() sees the watchdog's interrupt (solver_watchdog.h): push() past the deadline
  // throws "canceled" too, which was an internal error, exit 3 (`verify --timeout 1e-9`, about
  // one run in five). Past the deadline nothing more is asked: the answer is unknown.
  try {
    solver_.push();
    solver_.add(z3::atleast(holds_, 2));
    Answer a = run(z3::expr_vector(ctx_));
    solver_.pop();
    return a;
  } catch (const z3::exception& e) {
    unknown_reason_ =
        stopped_by_deadline(e.msg()) ? "timeout" : std::string("solver error: ") + e.msg();
    return last_ = Answer::Unknown;
  }
}

Answer PortSolver::holds_with(int rule, const Constraint& also) {
  try {
    solver_.push();
    solver_.add(encode(also));
    z3::expr_vector assumptions(ctx_);
    assumptions.push_back(holds_[rule]);
    Answer a = run(assumptions);
    solver_.pop();
    return a;
  } catch (const z3::exception& e) {  // as in at_least_two_hold
    unknown_reason_ =
        stopped_by_deadline(e.msg()) ? "timeout" : std::string("solver error: ") + e.msg();
    return last_ = Answer::Unknown;
  }
}

Answer PortSolver::can_hold(int rule) {
  z3::expr_vector assumptions(ctx_);
  assumptions.push_back(holds_[rule]);
  return run(assumptions);
}

Answer PortSolver::overlapping_pairs(const std::function<Known(int, int)>& known,
                                     std::vector<std::pair<int, int>>& pairs) {
  int n = static_cast<int>(holds_.size());
  for (int i = 0; i < n; ++i) {
    std::vector<int> candidates, found;
    for (int j = i + 1; j < n; ++j) {
      switch (known(i, j)) {
        case Known::Yes:
          found.push_back(j);
          break;
        case Known::No:
          break;
        case Known::Unknown:
          candidates.push_back(j);
          break;
      }
    }
    while (!candidates.empty()) {
      // One query finds every partner of i that holds in the model at once.
      z3::expr_vector partners(ctx_);
      for (int j : candidates) partners.push_back(holds_[j]);
      solver_.push();
      solver_.add(holds_[i]);
      solver_.add(z3::mk_or(partners));
      Answer a = run(z3::expr_vector(ctx_));
      if (a == Answer::Sat) {
        z3::model m = solver_.get_model();
        std::vector<int> rest;
        for (int j : candidates) {
          (m.eval(holds_[j], true).is_true() ? found : rest).push_back(j);
        }
        candidates = std::move(rest);
      }
      solver_.pop();
      if (a == Answer::Unknown) return last_ = Answer::Unknown;
      if (a == Answer::Unsat) break;
    }
    std::sort(found.begin(), found.end());
    for (int j : found) pairs.emplace_back(i, j);
  }
  return last_ = pairs.empty() ? Answer::Unsat : Answer::Sat;
}

std::vector<std::string> PortSolver::present_events(const z3::model& m) {
  std::vector<std::string> present;
  for (size_t k = 0; k < event_vars_.size(); ++k) {
    if (m.eval(event_vars_[k], true).is_true()) present.push_back(scope_.events[k]);
  }
  return present;
}

std::optional<std::vector<std::string>> PortSolver::minimal_state(const std::vector<int>& must_hold,
                                                                  const std::vector<int>& must_fail,
                                                                  const Constraint* extra_false) {
  solver_.push();
  for (int i : must_hold) solver_.add(holds_[i]);
  for (int i : must_fail) solver_.add(!holds_[i]);
  if (extra_false) solver_.add(!encode(*extra_false));
  std::optional<std::vector<std::string>> best;
  Answer a = run(z3::expr_vector(ctx_));
  if (a == Answer::Sat) best = present_events(solver_.get_model());
  // Shrink: ask for a state with fewer events present until there is none.
  while (a == Answer::Sat && !best->empty()) {
    solver_.add(z3::atmost(all_events_, static_cast<unsigned>(best->size() - 1)));
    a = run(z3::expr_vector(ctx_));
    if (a == Answer::Sat) best = present_events(solver_.get_model());
  }
  solver_.pop();
  if (a == Answer::Unknown) {
    last_ = Answer::Unknown;
    return std::nullopt;  // a state exists but may not be minimal: do not report it as such
  }
  last_ = best ? Answer::Sat : Answer::Unsat;
  return best;
}

}  // namespace arbc::verify
