// Counterexample messages a person can read (docs/checks.md#message-data). A model of the
// machine's arithmetic (verify/lua_number.h) is any satisfying assignment of bits: a witness
// that needs one short list and one number above 0.4 comes back as four elements of NaNs and
// 4.19e232. Before a witness is printed, each value of the message is pulled, one at a time and
// while the question stays satisfiable, to the simplest value that still answers it: lists to
// their fewest elements, ints to 0, 1, -1 or a small int, floats to 0.0, 1.0, -1.0, an integral
// float, one with few binary digits (0.4375) or at least a finite one. What it cannot simplify (a
// NaN or 0.3333333333333333 that the question needs) stays as the solver found it. Costs solver
// calls only for a refutation.
#pragma once

#include <z3++.h>

#include <functional>
#include <optional>
#include <vector>

#include "verify/solver_timeout.h"
#include "verify/sym_value.h"

namespace arbc::verify {

// A model of `solver` under `assumptions` (the solver's last answer was sat, `model` its model)
// in which the leaves of `values` are as simple as the question allows. The solver is left as
// it was (every constraint added here is popped).
// A caller whose encoding abstracts something gives `settle`: the model it turns the solver's
// into (one that agrees with what is abstracted), or none; a candidate is taken only then.
using SettleModel = std::function<std::optional<z3::model>(const z3::model&)>;
z3::model nicer_model(z3::solver& solver, const z3::expr_vector& assumptions,
                      const std::vector<const SymValue*>& values, z3::model model,
                      SolverTimeout& timeout, const SettleModel& settle = nullptr);

}  // namespace arbc::verify
