#include "verify/cube_shortcut.h"

namespace arbc::verify {
namespace {

// Complementary literals: an event one cube requires and the other forbids (same length).
bool clash(const Cube& a, const Cube& b) {
  for (size_t w = 0; w < a.required.size(); ++w) {
    if ((a.required[w] & b.forbidden[w]) | (a.forbidden[w] & b.required[w])) return true;
  }
  return false;
}

}  // namespace

CubeShortcut::CubeShortcut(const PortScope& scope) {
  for (const std::string& e : scope.events) index_.intern(e);
  for (const ScopedRule& r : scope.rules) {
    RuleCube c;
    if (std::optional<Cube> cube = as_cube(r.effective_guard, index_)) {
      c.is_cube = true;
      c.contradictory = cube->contradictory();
      c.cube = std::move(*cube);
    }
    cubes_.push_back(std::move(c));
  }
  words_ = (index_.size() + 63) / 64;
  for (RuleCube& c : cubes_) {
    c.cube.required.resize(static_cast<size_t>(words_), 0);
    c.cube.forbidden.resize(static_cast<size_t>(words_), 0);
  }
  for (const DomainConstraint& d : scope.domain) {
    domain_.push_back(CompiledConstraint::compile(d.formula, index_));
  }
}

bool CubeShortcut::domain_holds(const std::vector<uint64_t>& present) const {
  EventMask mask;
  for (int id = 0; id < index_.size(); ++id) {
    if (present[static_cast<size_t>(id >> 6)] >> (id & 63) & 1) mask.set(id);
  }
  for (const CompiledConstraint& d : domain_) {
    if (!d.evaluate(mask)) return false;
  }
  return true;
}

Known CubeShortcut::can_hold(int i) const {
  const RuleCube& c = cubes_[static_cast<size_t>(i)];
  if (!c.is_cube) return Known::Unknown;
  if (c.contradictory) return Known::No;
  return domain_holds(c.cube.required) ? Known::Yes : Known::Unknown;
}

Known CubeShortcut::can_hold_together(int i, int j) const {
  const RuleCube& a = cubes_[static_cast<size_t>(i)];
  const RuleCube& b = cubes_[static_cast<size_t>(j)];
  if (!a.is_cube || !b.is_cube) return Known::Unknown;
  if (a.contradictory || b.contradictory) return Known::No;
  if (clash(a.cube, b.cube)) return Known::No;
  std::vector<uint64_t> both(static_cast<size_t>(words_));
  for (size_t w = 0; w < both.size(); ++w) both[w] = a.cube.required[w] | b.cube.required[w];
  if (domain_.empty()) return Known::Yes;  // no constraint on the state: the witness stands
  return domain_holds(both) ? Known::Yes : Known::Unknown;
}

bool CubeShortcut::pairwise_disjoint() const {
  auto never_together = [](const RuleCube& a, const RuleCube& b) {
    return a.contradictory || b.contradictory || clash(a.cube, b.cube);
  };
  for (size_t i = 0; i < cubes_.size(); ++i) {
    for (size_t j = i + 1; j < cubes_.size(); ++j) {
      if (!cubes_[i].is_cube || !cubes_[j].is_cube || !never_together(cubes_[i], cubes_[j]))
        return false;
    }
  }
  return true;
}

}  // namespace arbc::verify
