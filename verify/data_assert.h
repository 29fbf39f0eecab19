// Asserts over data (docs/checks.md#assert-over-data): `assert M.p: RULE -> PRED;` where PRED
// reads `emitted`, the value RULE delivers to M.p. Proved when no message RULE accepts in an
// event state where it is selected makes it deliver a value for which PRED is not true;
// refuted with the event state and a concrete message, replayed through the Lua monitors.
#pragma once

#include <optional>
#include <string>

#include "verify/data_query.h"
#include "verify/port_solver.h"
#include "verify/report.h"
#include "verify/verify.h"

namespace arbc::verify {

struct DataAssertOutcome {
  std::optional<Finding> finding;  // refuted, not provable (opaque), or internal
  std::string unknown;             // non-empty: what could not be decided (the solver's answer)
  std::string unknown_reason;
  // Refuted and replayed: the message that makes the rule deliver a value the assert rejects,
  // in the finding's counterexample state (the kept test's step).
  std::optional<Value> message;
};

// `rule` is the assert's rule, index `rule_index` in `solver`'s port scope.
DataAssertOutcome check_data_assert(const PortScope& scope, int rule_index,
                                    const model::Assertion& a, PortSolver& solver, DataQuery& data,
                                    const MonitorRunner* runner);

}  // namespace arbc::verify
