// One Z3 solver per arbitrated port (docs/design.md#the-proof).
//
// The solver holds the port's domain (exclusive groups, invariants) and, for each rule i, an
// indicator h_i <=> E_i. Every check is then a query under assumptions or in a push/pop frame,
// so Z3 keeps what it learnt between queries. A shared deadline bounds the whole run: a query
// that cannot finish in the time left answers Unknown, and unknown never passes.
#pragma once

#include <z3++.h>

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "verify/cube_shortcut.h"
#include "verify/port_scope.h"
#include "verify/solver_timeout.h"

namespace arbc::verify {

using Clock = std::chrono::steady_clock;

enum class Answer { Sat, Unsat, Unknown };

class PortSolver {
 public:
  // `ctx` is shared by all ports of a run: creating a Z3 context costs tens of milliseconds.
  PortSolver(const PortScope& scope, z3::context& ctx, Clock::time_point deadline);

  // Can at least two rules hold in one decision state?
  Answer at_least_two_hold();
  // Can rule i hold at all?
  Answer can_hold(int rule);
  // Can rule i hold in a state where `also` (over the scope's events) holds too?
  Answer holds_with(int rule, const Constraint& also);
  // All pairs (i, j), i < j, of rules that can hold together, in lexicographic order; Unknown
  // when a query gave no answer (the pairs found so far are kept). `known` settles pairs
  // without a query where it can (see CubeShortcut).
  Answer overlapping_pairs(const std::function<Known(int, int)>& known,
                           std::vector<std::pair<int, int>>& pairs);

  // A state with the fewest events present in which the given rules hold, the rules in
  // `must_fail` do not hold, and `extra_false` (e.g. an assert's property) is false. Sorted
  // present events; nullopt when no such state exists or the solver gave no answer (see
  // last_answer()).
  std::optional<std::vector<std::string>> minimal_state(const std::vector<int>& must_hold,
                                                        const std::vector<int>& must_fail,
                                                        const Constraint* extra_false = nullptr);

  Answer last_answer() const { return last_; }
  std::string unknown_reason() const { return unknown_reason_; }
  int queries() const { return queries_; }

 private:
  z3::expr encode(const Constraint& c);
  Answer run(const z3::expr_vector& assumptions);
  std::vector<std::string> present_events(const z3::model& m);

  const PortScope& scope_;
  z3::context& ctx_;
  z3::solver solver_;
  SolverTimeout timeout_;
  std::vector<z3::expr> event_vars_;  // parallel to scope_.events
  z3::expr_vector all_events_;
  z3::expr_vector holds_;  // h_i, parallel to scope_.rules
  Answer last_ = Answer::Unsat;
  std::string unknown_reason_;
  int queries_ = 0;
};

}  // namespace arbc::verify
