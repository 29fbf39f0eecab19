// Lua 5.4's numbers in Z3 (docs/design.md#the-proof): what a generated monitor computes on
// x86-64, one function per operator, used by every part of the proof that computes with a
// number (verify/body_encoding.h, verify/sym_value.h).
//
//   int   a 64-bit two's complement bit-vector: + - * and unary minus wrap, abs(INT64_MIN) is
//         INT64_MIN, math.fmod by 0 raises (the monitor drops the message);
//   sized integers and float32 (issue 41) are held as int and float values in their type's
//         range (sized_int_const, sized_float_const); arithmetic promotes them, as Lua does;
//   float IEEE 754 binary64 (Z3's floating-point theory): + - * / and sqrt round to nearest,
//         ties to even; NaN, infinities and -0.0 are values; comparisons with NaN are false and
//         `==` is IEEE's (0.0 == -0.0, NaN ~= NaN); math.fmod is C's fmod.
//
// Mixed operands follow Lua: arithmetic converts the int to the nearest double (ties to even)
// and computes in floats; `/` always does; comparisons and `==` compare the mathematical values
// (2^53 + 1 > 2^53 as an int against a float), never a converted int.
#pragma once

#include <z3++.h>

#include <cstdint>
#include <vector>

#include "verify/sym_value.h"

namespace arbc::verify::lua {

// The sorts and constants of the two number kinds.
z3::sort float_sort(z3::context& ctx);
z3::expr int_val(z3::context& ctx, int64_t v);
z3::expr float_val(z3::context& ctx, double v);  // exact: NaN, infinities and -0.0 included
z3::expr int_const(z3::context& ctx, const std::string& name);
z3::expr float_const(z3::context& ctx, const std::string& name);

// A value of a sized number type (core/type.h) as the machine holds it, by construction: an
// int8 is a 64-bit vector sign-extended from 8 bits (so in -128..127), a uint32 one zero-extended
// from 32, a float32 the binary64 of a binary32 (NaN, the infinities and -0.0 included). A uint64
// is all 64 bits (its bit pattern); int64 and float64 are int_const and float_const.
z3::expr sized_int_const(z3::context& ctx, const std::string& name, const Type& t);
z3::expr sized_float_const(z3::context& ctx, const std::string& name, const Type& t);

// The number as a float: an int converted to the nearest double (ties to even, as C's cast).
z3::expr to_float(const SymValue& v);

// a + b, a - b, a * b (op is '+', '-' or '*'): wrapping ints when both are ints, else floats.
SymValue arith(char op, const SymValue& a, const SymValue& b);
// a / b: always a float division (both converted), IEEE on a zero divisor.
SymValue divide(const SymValue& a, const SymValue& b);
// -a and math.abs(a).
SymValue negate(const SymValue& a);
SymValue abs(const SymValue& a);
// math.fmod(a, b); *raises is set to the condition under which Lua raises ("bad argument #2
// to 'fmod' (zero)": two ints, the divisor 0), false for floats. Exact, but on floats it is
// IEEE's remainder, whose circuit does not fit in memory on unknown operands: a caller gives
// it to a solver only once it has folded to a numeral (is_float_numeral).
SymValue fmod(const SymValue& a, const SymValue& b, z3::expr* raises);
// math.sqrt(a): a float.
SymValue sqrt(const SymValue& a);
// The prelude's norm of (x, y, z): math.sqrt(x * x + y * y + z * z), the sum from the left,
// each operation rounded.
SymValue norm(const SymValue& x, const SymValue& y, const SymValue& z);
// What every norm of three floats is, whatever they are: NaN exactly when a component is NaN
// (no sum of squares is inf - inf), else not negative (never -0.0). For `r` standing for the
// norm without its circuit (verify/body_encoding.h, EncodedBody::lengths).
z3::expr norm_facts(const z3::expr& r, const z3::expr& x, const z3::expr& y, const z3::expr& z);
// What monotonicity gives from one point: with `p_abs` the absolute values of a point's
// components and `n` its norm (numerals), the norm `r` of components `c` that are not NaN is at
// most n when each |c_k| <= p_abs[k], at least n when each |c_k| >= p_abs[k]. (Each step is
// monotone in |c_k|: squaring, a sum of squares, the square root, and rounding to nearest.)
z3::expr norm_monotone(const z3::expr& r, const std::vector<z3::expr>& c,
                       const std::vector<z3::expr>& p_abs, const z3::expr& n);
// |a| of a float.
z3::expr float_abs(const z3::expr& a);
// Whether the numerals a and b are the same value (NaN is one value; 0.0 and -0.0 are two).
bool same_numeral(const z3::expr& a, const z3::expr& b);

// a < b, a <= b and a == b on the mathematical values (false when either is NaN).
z3::expr less(const SymValue& a, const SymValue& b);
z3::expr less_equal(const SymValue& a, const SymValue& b);
z3::expr equal(const SymValue& a, const SymValue& b);

// Whether e is a float constant (a number, +-0, +-inf or NaN).
bool is_float_numeral(const z3::expr& e);

// The value of a numeral (a model's int or float) as the machine holds it.
int64_t int_of(const z3::expr& numeral);
double float_of(const z3::expr& numeral);

}  // namespace arbc::verify::lua
