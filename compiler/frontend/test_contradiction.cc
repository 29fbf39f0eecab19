#include "compiler/frontend/test_contradiction.h"

namespace arbc::frontend {

namespace {

struct Span {
  Nanos from, to;
};

// A window's instants; without one, the whole test.
Span span_of(const ast::TestWindow& w) {
  if (!w.present) return {Nanos(0), kNever};
  if (!w.to.expr) return {w.from.nanos, w.from.nanos};
  return {w.from.nanos, w.to.nanos};
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
