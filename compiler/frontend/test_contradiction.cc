#include "compiler/frontend/test_contradiction.h"

#include <limits>

namespace arbc::frontend {

namespace {

struct Span {
  double from, to;
};

// A window's instants; without one, the whole test.
Span span_of(const ast::TestWindow& w) {
  if (!w.present) return {0, std::numeric_limits<double>::infinity()};
  if (!w.to.expr) return {w.from.seconds, w.from.seconds};
  return {w.from.seconds, w.to.seconds};
}

}  // namespace

std::optional<std::pair<const ast::TestExpect*, const ast::TestExpect*>> contradicting_receives(
    const ast::TestDecl& test) {
  using Kind = ast::TestExpect::Kind;
  for (const ast::TestExpect& some : test.expects) {
    if (some.kind != Kind::Receives) continue;
    for (const ast::TestExpect& none : test.expects) {
      if (none.kind != Kind::Nothing || none.port.qualified() != some.port.qualified()) continue;
      Span s = span_of(some.window), n = span_of(none.window);
      if (n.from <= s.from && s.to <= n.to) return std::make_pair(&some, &none);
    }
  }
  return std::nullopt;
}

}  // namespace arbc::frontend
