#include "verify/cube_shortcut.h"

namespace arbc::verify {
namespace {

void set_bit(std::vector<uint64_t>& bits, int id) {
  bits[static_cast<size_t>(id >> 6)] |= uint64_t{1} << (id & 63);
}

}  // namespace

CubeShortcut::CubeShortcut(const PortScope& scope) {
  for (const std::string& e : scope.events) index_.intern(e);
  words_ = (index_.size() + 63) / 64;
  for (const ScopedRule& r : scope.rules) {
    Cube cube;
    cube.pos.assign(static_cast<size_t>(words_), 0);
    cube.neg.assign(static_cast<size_t>(words_), 0);
    const Constraint& g = r.effective_guard;
    std::vector<const Constraint*> literals;
    if (g.op == Constraint::Op::And) {
      for (const Constraint& a : g.args) literals.push_back(&a);
    } else if (g.op != Constraint::Op::True) {
      literals.push_back(&g);
    }
    cube.is_cube = true;
    for (const Constraint* l : literals) {
      if (l->op == Constraint::Op::Event) {
        set_bit(cube.pos, index_.find(l->event));
      } else if (l->op == Constraint::Op::Not && l->args[0].op == Constraint::Op::Event) {
        set_bit(cube.neg, index_.find(l->args[0].event));
      } else {
        cube.is_cube = false;
        break;
      }
    }
    for (int w = 0; cube.is_cube && w < words_; ++w) {
      cube.contradictory |=
          (cube.pos[static_cast<size_t>(w)] & cube.neg[static_cast<size_t>(w)]) != 0;
    }
    cubes_.push_back(std::move(cube));
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
  const Cube& c = cubes_[static_cast<size_t>(i)];
  if (!c.is_cube) return Known::Unknown;
  if (c.contradictory) return Known::No;
  return domain_holds(c.pos) ? Known::Yes : Known::Unknown;
}

Known CubeShortcut::can_hold_together(int i, int j) const {
  const Cube& a = cubes_[static_cast<size_t>(i)];
  const Cube& b = cubes_[static_cast<size_t>(j)];
  if (!a.is_cube || !b.is_cube) return Known::Unknown;
  if (a.contradictory || b.contradictory) return Known::No;
  std::vector<uint64_t> both(static_cast<size_t>(words_));
  for (size_t w = 0; w < both.size(); ++w) {
    if ((a.pos[w] & b.neg[w]) | (a.neg[w] & b.pos[w])) return Known::No;
    both[w] = a.pos[w] | b.pos[w];
  }
  if (domain_.empty()) return Known::Yes;  // no constraint on the state: the witness stands
  return domain_holds(both) ? Known::Yes : Known::Unknown;
}

bool CubeShortcut::pairwise_disjoint() const {
  auto clash = [this](const Cube& a, const Cube& b) {
    if (a.contradictory || b.contradictory) return true;
    for (size_t w = 0; w < static_cast<size_t>(words_); ++w) {
      if ((a.pos[w] & b.neg[w]) | (a.neg[w] & b.pos[w])) return true;
    }
    return false;
  };
  for (size_t i = 0; i < cubes_.size(); ++i) {
    for (size_t j = i + 1; j < cubes_.size(); ++j) {
      if (!cubes_[i].is_cube || !cubes_[j].is_cube || !clash(cubes_[i], cubes_[j])) return false;
    }
  }
  return true;
}

}  // namespace arbc::verify
