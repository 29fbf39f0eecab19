#include "verify/lua_number.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace arbc::verify::lua {

namespace {

using K = SymValue::Kind;

z3::expr wrap(z3::context& ctx, Z3_ast a) {
  ctx.check_error();
  return z3::expr(ctx, a);
}

z3::expr rne(z3::context& ctx) { return wrap(ctx, Z3_mk_fpa_rne(ctx)); }

// An int converted to a double rounding to nearest (ties to even, C's cast), toward -inf or
// toward +inf: the two directed ones bracket the int, which is what exact comparisons need.
enum class Round { Nearest, Down, Up };
z3::expr int_to_float(const z3::expr& i, Round r) {
  z3::context& ctx = i.ctx();
  z3::expr mode = wrap(ctx, r == Round::Nearest ? Z3_mk_fpa_rne(ctx)
                            : r == Round::Down  ? Z3_mk_fpa_rtn(ctx)
                                                : Z3_mk_fpa_rtp(ctx));
  return wrap(ctx, Z3_mk_fpa_to_fp_signed(ctx, mode, i, float_sort(ctx)));
}

z3::expr is_negative(const z3::expr& f) { return wrap(f.ctx(), Z3_mk_fpa_is_negative(f.ctx(), f)); }
z3::expr is_zero(const z3::expr& f) { return wrap(f.ctx(), Z3_mk_fpa_is_zero(f.ctx(), f)); }
z3::expr is_nan(const z3::expr& f) { return wrap(f.ctx(), Z3_mk_fpa_is_nan(f.ctx(), f)); }
z3::expr float_lt(const z3::expr& a, const z3::expr& b) {
  return wrap(a.ctx(), Z3_mk_fpa_lt(a.ctx(), a, b));
}
z3::expr float_leq(const z3::expr& a, const z3::expr& b) {
  return wrap(a.ctx(), Z3_mk_fpa_leq(a.ctx(), a, b));
}
z3::expr float_eq(const z3::expr& a, const z3::expr& b) {
  return wrap(a.ctx(), Z3_mk_fpa_eq(a.ctx(), a, b));
}

bool both_ints(const SymValue& a, const SymValue& b) {
  return a.kind == K::Int && b.kind == K::Int;
}

// C's fmod on doubles from IEEE's remainder r = x - n*y (n the nearest integer to x/y, ties to
// even): fmod truncates the quotient instead, so where r's sign differs from x's (n rounded away
// from zero) fmod is r plus |y| toward x's sign. That sum is fmod's exact value, a double, so
// rounding leaves it exact. NaN, an infinite x, a zero y and x = +-0 come out of r as fmod's.
z3::expr float_fmod(const z3::expr& x, const z3::expr& y) {
  z3::context& ctx = x.ctx();
  z3::expr r = wrap(ctx, Z3_mk_fpa_rem(ctx, x, y));
  z3::expr ay = wrap(ctx, Z3_mk_fpa_abs(ctx, y));
  z3::expr step = z3::ite(is_negative(x), wrap(ctx, Z3_mk_fpa_neg(ctx, ay)), ay);
  z3::expr fixed = wrap(ctx, Z3_mk_fpa_add(ctx, rne(ctx), r, step));
  z3::expr keep = is_nan(r) || is_zero(r) || is_negative(r) == is_negative(x);
  return z3::ite(keep, r, fixed);
}

uint64_t bv_bits(const z3::expr& numeral) {
  uint64_t u = 0;
  Z3_get_numeral_uint64(numeral.ctx(), numeral, &u);
  return u;
}

}  // namespace

z3::sort float_sort(z3::context& ctx) { return z3::sort(ctx, Z3_mk_fpa_sort_64(ctx)); }

z3::expr int_val(z3::context& ctx, int64_t v) { return ctx.bv_val(v, 64); }

z3::expr float_val(z3::context& ctx, double v) {
  z3::sort s = float_sort(ctx);
  if (std::isnan(v)) return wrap(ctx, Z3_mk_fpa_nan(ctx, s));
  if (std::isinf(v)) return wrap(ctx, Z3_mk_fpa_inf(ctx, s, v < 0));
  if (v == 0) return wrap(ctx, Z3_mk_fpa_zero(ctx, s, std::signbit(v)));
  return wrap(ctx, Z3_mk_fpa_numeral_double(ctx, v, s));
}

z3::expr int_const(z3::context& ctx, const std::string& name) {
  return ctx.bv_const(name.c_str(), 64);
}

z3::expr float_const(z3::context& ctx, const std::string& name) {
  return ctx.constant(name.c_str(), float_sort(ctx));
}

z3::expr sized_int_const(z3::context& ctx, const std::string& name, const Type& t) {
  if (t.bits >= 64) return int_const(ctx, name);
  z3::expr narrow = ctx.bv_const(name.c_str(), static_cast<unsigned>(t.bits));
  unsigned wider = static_cast<unsigned>(64 - t.bits);
  return t.is_unsigned ? z3::zext(narrow, wider) : z3::sext(narrow, wider);
}

z3::expr sized_float_const(z3::context& ctx, const std::string& name, const Type& t) {
  if (t.bits >= 64) return float_const(ctx, name);
  z3::expr single = ctx.fpa_const(name.c_str(), 8, 24);
  // Widening a binary32 to binary64 is exact: the rounding mode never applies. The mode and the
  // sort are held before the call: a raw term is freed at Z3's next call, and C++ may evaluate
  // arguments in any order (tests/code_shape/z3_raw_terms.py).
  z3::expr mode = rne(ctx);
  z3::sort wide = float_sort(ctx);
  return wrap(ctx, Z3_mk_fpa_to_fp_float(ctx, mode, single, wide));
}

z3::expr to_float(const SymValue& v) {
  return v.kind == K::Int ? int_to_float(v.scalar, Round::Nearest) : v.scalar;
}

SymValue arith(char op, const SymValue& a, const SymValue& b) {
  if (both_ints(a, b)) {
    const z3::expr &x = a.scalar, &y = b.scalar;
    return {K::Int, op == '+' ? x + y : op == '-' ? x - y : x * y};
  }
  z3::context& ctx = a.scalar.ctx();
  z3::expr x = to_float(a), y = to_float(b);
  Z3_ast r = op == '+'   ? Z3_mk_fpa_add(ctx, rne(ctx), x, y)
             : op == '-' ? Z3_mk_fpa_sub(ctx, rne(ctx), x, y)
                         : Z3_mk_fpa_mul(ctx, rne(ctx), x, y);
  return {K::Float, wrap(ctx, r)};
}

SymValue divide(const SymValue& a, const SymValue& b) {
  z3::context& ctx = a.scalar.ctx();
  return {K::Float, wrap(ctx, Z3_mk_fpa_div(ctx, rne(ctx), to_float(a), to_float(b)))};
}

SymValue negate(const SymValue& a) {
  if (a.kind == K::Int) return {K::Int, -a.scalar};  // bvneg: -INT64_MIN is INT64_MIN
  return {K::Float, wrap(a.scalar.ctx(), Z3_mk_fpa_neg(a.scalar.ctx(), a.scalar))};
}

SymValue abs(const SymValue& a) {
  // Lua's math.abs of an int: 0u - n when n < 0, so abs(INT64_MIN) is INT64_MIN.
  if (a.kind == K::Int) return {K::Int, z3::ite(a.scalar < 0, -a.scalar, a.scalar)};
  return {K::Float, wrap(a.scalar.ctx(), Z3_mk_fpa_abs(a.scalar.ctx(), a.scalar))};
}

SymValue fmod(const SymValue& a, const SymValue& b, z3::expr* raises) {
  z3::context& ctx = a.scalar.ctx();
  if (both_ints(a, b)) {
    *raises = b.scalar == 0;
    // C's % truncates toward zero with the dividend's sign: bvsrem. Lua answers 0 for a
    // divisor of -1 (INT64_MIN % -1 would trap in C); bvsrem gives 0 there too.
    return {K::Int, z3::srem(a.scalar, b.scalar)};
  }
  *raises = ctx.bool_val(false);
  return {K::Float, float_fmod(to_float(a), to_float(b))};
}

SymValue sqrt(const SymValue& a) {
  z3::context& ctx = a.scalar.ctx();
  return {K::Float, wrap(ctx, Z3_mk_fpa_sqrt(ctx, rne(ctx), to_float(a)))};
}

SymValue norm(const SymValue& x, const SymValue& y, const SymValue& z) {
  SymValue sum = arith('+', arith('+', arith('*', x, x), arith('*', y, y)), arith('*', z, z));
  return sqrt(sum);
}

z3::expr norm_facts(const z3::expr& r, const z3::expr& x, const z3::expr& y, const z3::expr& z) {
  return is_nan(r) == (is_nan(x) || is_nan(y) || is_nan(z)) && (is_nan(r) || !is_negative(r));
}

z3::expr float_abs(const z3::expr& a) { return wrap(a.ctx(), Z3_mk_fpa_abs(a.ctx(), a)); }

z3::expr norm_monotone(const z3::expr& r, const std::vector<z3::expr>& c,
                       const std::vector<z3::expr>& p_abs, const z3::expr& n) {
  z3::context& ctx = r.ctx();
  z3::expr any_nan = ctx.bool_val(false), below = ctx.bool_val(true), above = ctx.bool_val(true);
  for (size_t k = 0; k < c.size(); ++k) {
    any_nan = any_nan || is_nan(c[k]);
    below = below && float_leq(float_abs(c[k]), p_abs[k]);
    above = above && float_leq(p_abs[k], float_abs(c[k]));
  }
  return z3::implies(!any_nan && below, float_leq(r, n)) &&
         z3::implies(!any_nan && above, float_leq(n, r));
}

bool same_numeral(const z3::expr& a, const z3::expr& b) {
  return wrap(a.ctx(), Z3_mk_eq(a.ctx(), a, b)).simplify().is_true();
}

// An int i against a double f, exactly: with lo and hi the doubles nearest i from below and
// above (both i when i is a double), i < f iff lo < f, since no double lies strictly between
// lo and i; i <= f iff hi <= f; f < i iff f < hi; f <= i iff f <= lo; i == f iff lo == f == hi.
z3::expr less(const SymValue& a, const SymValue& b) {
  if (both_ints(a, b)) return a.scalar < b.scalar;
  if (a.kind == K::Int) return float_lt(int_to_float(a.scalar, Round::Down), b.scalar);
  if (b.kind == K::Int) return float_lt(a.scalar, int_to_float(b.scalar, Round::Up));
  return float_lt(a.scalar, b.scalar);
}

z3::expr less_equal(const SymValue& a, const SymValue& b) {
  if (both_ints(a, b)) return a.scalar <= b.scalar;
  if (a.kind == K::Int) return float_leq(int_to_float(a.scalar, Round::Up), b.scalar);
  if (b.kind == K::Int) return float_leq(a.scalar, int_to_float(b.scalar, Round::Down));
  return float_leq(a.scalar, b.scalar);
}

z3::expr equal(const SymValue& a, const SymValue& b) {
  if (both_ints(a, b)) return a.scalar == b.scalar;
  if (a.kind == K::Int || b.kind == K::Int) {
    const SymValue& i = a.kind == K::Int ? a : b;
    const z3::expr& f = a.kind == K::Int ? b.scalar : a.scalar;
    return float_eq(int_to_float(i.scalar, Round::Down), f) &&
           float_eq(int_to_float(i.scalar, Round::Up), f);
  }
  return float_eq(a.scalar, b.scalar);
}

bool is_float_numeral(const z3::expr& e) {
  if (!e.is_app()) return false;
  switch (e.decl().decl_kind()) {
    case Z3_OP_FPA_NUM:
    case Z3_OP_FPA_NAN:
    case Z3_OP_FPA_PLUS_INF:
    case Z3_OP_FPA_MINUS_INF:
    case Z3_OP_FPA_PLUS_ZERO:
    case Z3_OP_FPA_MINUS_ZERO:
      return true;
    default:
      return false;
  }
}

int64_t int_of(const z3::expr& numeral) { return static_cast<int64_t>(bv_bits(numeral)); }

double float_of(const z3::expr& numeral) {
  z3::context& ctx = numeral.ctx();
  if (Z3_fpa_is_numeral_nan(ctx, numeral)) return std::numeric_limits<double>::quiet_NaN();
  int sign = 0;
  Z3_fpa_get_numeral_sign(ctx, numeral, &sign);
  if (Z3_fpa_is_numeral_inf(ctx, numeral))
    return sign ? -std::numeric_limits<double>::infinity()
                : std::numeric_limits<double>::infinity();
  if (Z3_fpa_is_numeral_zero(ctx, numeral)) return sign ? -0.0 : 0.0;
  uint64_t exponent = bv_bits(wrap(ctx, Z3_fpa_get_numeral_exponent_bv(ctx, numeral, true)));
  uint64_t significand = bv_bits(wrap(ctx, Z3_fpa_get_numeral_significand_bv(ctx, numeral)));
  uint64_t bits = (static_cast<uint64_t>(sign != 0) << 63) | ((exponent & 0x7ff) << 52) |
                  (significand & ((uint64_t{1} << 52) - 1));
  double d = 0;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

}  // namespace arbc::verify::lua
