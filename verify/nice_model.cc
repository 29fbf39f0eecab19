#include "verify/nice_model.h"

#include "verify/lua_number.h"

namespace arbc::verify {

namespace {

using K = SymValue::Kind;

// The simpler values to try for a leaf, simplest first.
std::vector<z3::expr> candidates(const SymValue& leaf, const z3::model& m) {
  z3::context& ctx = leaf.scalar.ctx();
  std::vector<z3::expr> out;
  if (leaf.kind == K::List) {
    // Fewest elements: each length below the model's, up to a few dozen; then lengths a
    // witness can be written with (a length need not be bounded: docs/checks.md#message-data).
    int64_t len = lua::int_of(m.eval(leaf.scalar, true));
    for (int64_t k = 0; k < len && k <= 32; ++k) out.push_back(leaf.scalar == lua::int_val(ctx, k));
    for (int64_t k : {int64_t{256}, kMaxWitnessElements})
      if (len > k) out.push_back(leaf.scalar <= lua::int_val(ctx, k));
    return out;
  }
  if (leaf.kind == K::Int) {
    for (int64_t k : {0, 1, -1}) out.push_back(leaf.scalar == lua::int_val(ctx, k));
    out.push_back(leaf.scalar >= lua::int_val(ctx, -1000) &&
                  leaf.scalar <= lua::int_val(ctx, 1000));
    return out;
  }
  for (double d : {0.0, 1.0, -1.0})  // the same bits: 0.0, not -0.0
    out.push_back(leaf.scalar == lua::float_val(ctx, d));
  SymValue limit(K::Float, lua::float_val(ctx, 1e6));
  SymValue low(K::Float, lua::float_val(ctx, -1e6));
  z3::expr rounded(ctx, Z3_mk_fpa_round_to_integral(ctx, Z3_mk_fpa_rne(ctx), leaf.scalar));
  out.push_back(lua::equal(leaf, {K::Float, rounded}) && lua::less_equal(low, leaf) &&
                lua::less_equal(leaf, limit));
  // Then a few binary digits after the point (0.4375 rather than 0.437507629394986): x * 2^k is
  // exact for these magnitudes, so it is integral iff x has at most k such digits.
  for (double scale : {16.0, 1024.0}) {
    z3::expr scaled = lua::arith('*', leaf, {K::Float, lua::float_val(ctx, scale)}).scalar;
    z3::expr whole(ctx, Z3_mk_fpa_round_to_integral(ctx, Z3_mk_fpa_rne(ctx), scaled));
    out.push_back(lua::equal({K::Float, scaled}, {K::Float, whole}) && lua::less_equal(low, leaf) &&
                  lua::less_equal(leaf, limit));
  }
  SymValue huge(K::Float, lua::float_val(ctx, 1e300));
  out.push_back(lua::less_equal({K::Float, lua::float_val(ctx, -1e300)}, leaf) &&
                lua::less_equal(leaf, huge));
  return out;
}

// Pulls each leaf of a value to the simplest value the question allows, keeping what it
// settled while it moves the next ones.
class Simplifier {
 public:
  Simplifier(z3::solver& solver, const z3::expr_vector& assumptions, z3::model model,
             SolverTimeout& timeout, const SettleModel& settle)
      : solver_(solver),
        assumptions_(assumptions),
        model_(std::move(model)),
        timeout_(timeout),
        settle_(settle) {}

  // A list's length first (then pinned), then only the elements the message has.
  void value(const SymValue& v) {
    if (v.numeric()) return leaf(v);
    if (v.kind != K::List) {
      for (const SymValue& item : v.items) value(item);
      return;
    }
    leaf({K::List, v.scalar});
    int64_t len = lua::int_of(model_.eval(v.scalar, true));
    solver_.add(v.scalar == lua::int_val(v.scalar.ctx(), len));
    for (size_t k = 0; k < v.items.size() && static_cast<int64_t>(k) < len; ++k) value(v.items[k]);
    for (size_t j = 0; j < v.tail.size() && static_cast<int64_t>(v.items.size() + j) < len; ++j)
      value(v.tail[j]);  // the stand-ins past the capacity in the witness (sym_value.h)
  }

  const z3::model& model() const { return model_; }

 private:
  void leaf(const SymValue& v) {
    for (const z3::expr& c : candidates(v, model_)) {
      if (model_.eval(c, true).is_true() || holds_with(c)) {
        solver_.add(c);  // keep it so while the others move
        return;
      }
    }
  }

  // Whether the question stays satisfiable with c, in a model the caller accepts (then the
  // model is the new one).
  bool holds_with(const z3::expr& c) {
    bool sat = false;
    try {
      solver_.push();
      solver_.add(c);
      std::string unknown;  // a candidate the solver cannot settle is not taken
      sat = check(solver_, timeout_, &unknown, &assumptions_) == z3::sat;
      if (sat) {
        std::optional<z3::model> m = solver_.get_model();
        if (settle_) m = settle_(*m);
        sat = m.has_value();
        if (sat) model_ = *m;
      }
      solver_.pop();
    } catch (const z3::exception&) {
      return false;  // push or pop interrupted past the deadline: keep the model it has
    }
    return sat;
  }

  z3::solver& solver_;
  const z3::expr_vector& assumptions_;
  z3::model model_;
  SolverTimeout& timeout_;
  const SettleModel& settle_;
};

}  // namespace

z3::model nicer_model(z3::solver& solver, const z3::expr_vector& assumptions,
                      const std::vector<const SymValue*>& values, z3::model model,
                      SolverTimeout& timeout, const SettleModel& settle) {
  solver.push();
  Simplifier s(solver, assumptions, std::move(model), timeout, settle);
  for (const SymValue* v : values) s.value(*v);
  z3::model out = s.model();
  solver.pop();
  return out;
}

}  // namespace arbc::verify
