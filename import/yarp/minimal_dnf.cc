#include "import/yarp/minimal_dnf.h"

#include <algorithm>
#include <bit>
#include <set>
#include <utility>

namespace arbc::yarp {
namespace {

struct Implicant {
  unsigned value = 0;  // the bits that matter
  unsigned free = 0;   // bits that do not matter
  auto operator<=>(const Implicant&) const = default;
  bool covers(unsigned state) const { return (state & ~free) == value; }
};

// All prime implicants: merge pairs that differ in one bit until nothing merges.
std::vector<Implicant> prime_implicants(const std::vector<unsigned>& states) {
  std::set<Implicant> current, primes;
  for (unsigned s : states) current.insert({s, 0});
  while (!current.empty()) {
    std::set<Implicant> next, merged;
    for (auto a = current.begin(); a != current.end(); ++a) {
      for (auto b = std::next(a); b != current.end(); ++b) {
        unsigned diff = a->value ^ b->value;
        if (a->free != b->free || (diff & (diff - 1)) != 0 || diff == 0) continue;
        next.insert({a->value & ~diff, a->free | diff});
        merged.insert(*a);
        merged.insert(*b);
      }
    }
    for (const Implicant& i : current) {
      if (!merged.count(i)) primes.insert(i);
    }
    current = std::move(next);
  }
  return {primes.begin(), primes.end()};
}

}  // namespace

Constraint minimal_dnf(const std::vector<std::string>& events,
                       const std::vector<unsigned>& true_states) {
  std::vector<Implicant> primes = prime_implicants(true_states);
  std::set<unsigned> uncovered(true_states.begin(), true_states.end());
  std::vector<Constraint> terms;
  while (!uncovered.empty()) {
    // The prime that covers most of what is left (ties: fewest literals, then order).
    auto best = std::max_element(primes.begin(), primes.end(), [&](const auto& a, const auto& b) {
      auto count = [&](const Implicant& p) {
        return std::count_if(uncovered.begin(), uncovered.end(),
                             [&](unsigned s) { return p.covers(s); });
      };
      long ca = count(a), cb = count(b);
      if (ca != cb) return ca < cb;
      return std::popcount(a.free) < std::popcount(b.free);
    });
    std::vector<Constraint> literals;
    for (size_t i = 0; i < events.size(); ++i) {
      if (best->free & (1u << i)) continue;
      Constraint e = Constraint::event_ref(events[i]);
      literals.push_back(best->value & (1u << i) ? e : Constraint::negate(e));
    }
    terms.push_back(Constraint::conjunction(std::move(literals)));
    std::erase_if(uncovered, [&](unsigned s) { return best->covers(s); });
  }
  return Constraint::disjunction(std::move(terms));
}

}  // namespace arbc::yarp
