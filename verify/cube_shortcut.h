// Answers without the solver what a concrete state settles (a speed-up, never a change of
// verdict). Most effective guards are cubes (conjunctions of literals):
//   - a cube with both e and not e can never hold;
//   - two cubes with complementary literals never hold together, whatever the domain;
//   - the state "exactly the cube's positive events present" is a witness that the cube holds,
//     if the domain (invariants, exclusive groups) holds in it, checked with the runtime's
//     evaluator.
// Everything else is left to the solver. With 1,000 rules this replaces ~1,000 dead-rule
// queries and most pair queries by bit operations.
#pragma once

#include <cstdint>
#include <vector>

#include "core/compiled_constraint.h"
#include "verify/port_scope.h"

namespace arbc::verify {

enum class Known { Unknown, No, Yes };

class CubeShortcut {
 public:
  explicit CubeShortcut(const PortScope& scope);

  // Can rule i hold? Yes / No when settled without the solver.
  Known can_hold(int i) const;
  // Can rules i and j hold together?
  Known can_hold_together(int i, int j) const;
  // True when every pair of rules has complementary literals, so no two can ever hold
  // together: the port is exclusive whatever the domain, with no solver query.
  bool pairwise_disjoint() const;

 private:
  // A rule's effective guard as a cube (core's as_cube), with its contradiction precomputed.
  struct RuleCube {
    bool is_cube = false;
    bool contradictory = false;
    Cube cube;  // required / forbidden over the scope's events, words_ words each
  };
  bool domain_holds(const std::vector<uint64_t>& present) const;

  EventIndex index_;  // the scope's events, in scope order
  std::vector<RuleCube> cubes_;
  std::vector<CompiledConstraint> domain_;
  int words_ = 0;
};

}  // namespace arbc::verify
