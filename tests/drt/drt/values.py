"""Message values: random ones of a type (edge values included) as JSON for `--inputs`, and an
evaluator of expressions over values with the machine's arithmetic (Lua 5.4: 64-bit wrapping
integers, IEEE doubles, `/` always a float, floored `%`), for the properties over a delivered
value (`assert ... -> P(emitted)`, a resource's `when`).

A value here is Python's: bool, int, float, str, dict (vec3 {"x","y","z"}, records), list. A
sized number is an int or a float in its type's range (a float32 is a double that a float32
holds exactly); a uint64 is its 64-bit pattern, as Lua, traces and the inputs file hold it: its
orderings compare unsigned, its + - * wrap as every int's do. A list or string with a size is
always of a size its type allows (`arbc run --inputs` refuses any other): a T[N] of exactly N,
a list<T, N> or string<N> of 0 to N, N itself and 0 often (a string of N bytes in two-byte
characters too).
"""
import math
import struct

from .spec import BOOL, INT, FLOAT, STRING, VEC3, U64, F32, INT_RANGES, is_sized, size_of, is_fixed

INT64_MAX = 2**63 - 1
INT64_MIN = -2**63
# JSON has no NaN or infinities: the inputs file and the trace write them as the strings
# "nan", "inf" and "-inf" where a float is expected (core/value_json.cc, core/json_text.cc).
NONFINITE = {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}

EDGE_INTS = [0, 1, -1, 2, 3, 5, 7, 10, 100, INT64_MAX, INT64_MIN, INT64_MAX - 1, INT64_MIN + 1,
             2**53 + 1, -(2**62)]
EDGE_FLOATS = [0.0, -0.0, 0.5, 0.1, 0.2, 0.3, 1.0, 1.5, 2.0, -1.0, 0.3333333333333333, 1e308,
               -1e308, 5e-324, 1e-300, 0.49999999999999994, 0.7999999999999999, 3.75, 1e15 + 0.5,
               math.nan, math.inf, -math.inf]  # written as NONFINITE's strings
EDGE_STRINGS = ["", "a", "take", "é✓", "日本", 'a"b', "x\ny", "\\", "z" * 300, "idle", "e1"]
FLT_MAX = 3.4028234663852886e38
FLT_TRUE_MIN = 1.401298464324817e-45  # the least subnormal
EDGE_F32 = [0.0, -0.0, 0.5, 1.0, -1.0, 1.5, FLT_MAX, -FLT_MAX, FLT_TRUE_MIN, -FLT_TRUE_MIN,
            1.1754943508222875e-38, 0.10000000149011612, 0.3333333432674408, 16777216.0, -16777216.0,
            math.nan, math.inf, -math.inf]
# Values a float32 does not hold (the runtime drops them as bad-type): they round, or overflow.
BAD_F32 = [0.1, 16777217.0, 1e39, -1e39, 0.3333333333333333, 1e-46]


class NoValue(Exception):
    """An expression without a value (an index out of range, min_by of an empty list)."""


def wrap(i):
    """An integer as Lua 5.4 holds it: 64-bit two's complement."""
    i &= (1 << 64) - 1
    return i - (1 << 64) if i >= 1 << 63 else i


def to_f32(x):
    """The float32 nearest to x, as a double (None beyond the float32 range)."""
    try:
        return struct.unpack("<f", struct.pack("<f", x))[0]
    except OverflowError:
        return None


def next_f32(x, up=True):
    """The next float32 above (below) the float32 x."""
    if math.isnan(x) or math.isinf(x):
        return x
    bits = struct.unpack("<i", struct.pack("<f", x))[0]
    if x == 0.0:
        return FLT_TRUE_MIN if up else -FLT_TRUE_MIN
    bits += 1 if (x > 0) == up else -1
    return struct.unpack("<f", struct.pack("<i", bits))[0]


def next_float(x, up=True):
    if math.isnan(x) or math.isinf(x):
        return x
    bits = struct.unpack("<q", struct.pack("<d", x))[0]
    if x == 0.0:
        return 5e-324 if up else -5e-324
    bits += 1 if (x > 0) == up else -1
    return struct.unpack("<d", struct.pack("<q", bits))[0]


class ValueGen:
    """Random values of a type; `numbers` are the spec's own constants, so thresholds are hit
    exactly and one ulp either side; `list_bound` is verify's --list-bound (longer lists too)."""

    def __init__(self, rng, numbers=(), strings=(), list_bound=4, avoid=()):
        self.rng = rng
        self.avoid = set(avoid)
        self.numbers = list(numbers)
        self.strings = list(strings)
        self.list_bound = list_bound

    def value(self, ty, flags=()):
        r = self.rng
        if ty == BOOL:
            return r.random() < 0.5
        if ty == INT:
            pool = EDGE_INTS + [int(n) for n in self.numbers if float(n).is_integer() and abs(n) < 2**62]
            if "int-edge" in self.avoid:
                pool = [v for v in pool if abs(v) < 2**31]
            v = r.choice(pool) if r.random() < 0.6 else r.randint(-3, 12)
            return v + r.choice([0, 0, 1, -1]) if abs(v) < 2**62 else v
        if ty == FLOAT:
            return self.float_value()
        if ty == STRING:
            return r.choice(EDGE_STRINGS + self.strings + list(flags))
        if ty[0] == "string":
            return self.bounded_string(size_of(ty), flags)
        if ty == VEC3:
            return {"x": self.float_value(), "y": self.float_value(), "z": self.float_value()}
        if ty[0] == "list":
            n = self.sized_length(ty) if size_of(ty) else self.length()
            return [self.value(ty[1], flags) for _ in range(n)]
        if ty[0] == "record":
            return {f: self.value(ft, flags) for f, ft in ty[1]}
        if ty == F32:
            return self.f32_value()
        if is_sized(ty):
            return self.sized_int(ty)
        raise ValueError(ty)

    def out_of_range(self):
        """Now and then a value the port's type does not hold: the runtime drops it as
        bad-type, and the proof, which assumes every value in range, must not see it."""
        return "sized-out-of-range" not in self.avoid and self.rng.random() < 0.03

    def sized_int(self, ty):
        """An int of a sized type: its edges, 0 and -1, the spec's constants that it holds, and
        one either side; a uint64 written as its bits (2^64 - 1 as -1, 2^63 as -2^63)."""
        r = self.rng
        lo, hi = INT_RANGES[ty[0]]
        if ty != U64 and self.out_of_range():
            return r.choice([lo - 1, hi + 1])
        pool = [lo, hi, lo + 1, hi - 1, 0, 1] + ([-1] if lo else [2])
        if ty == U64:
            pool += [2**63, 2**63 - 1, 2**63 + 1, 2**32, 2**53 + 1]
        pool += [int(n) + k for n in self.numbers if float(n).is_integer() and abs(n) < 2**53
                 for k in (-1, 0, 1) if lo <= int(n) + k <= hi]
        v = r.choice(pool) if r.random() < 0.7 else r.randint(max(lo, -3), min(hi, 12))
        return wrap(v)

    def f32_value(self):
        """A double that a float32 holds: its edges (FLT_MAX, the least subnormal, -0.0, 0.1
        rounded to float32, 2^24), the spec's constants rounded to float32 and one float32 ulp
        either side."""
        r = self.rng
        if self.out_of_range():
            return r.choice(BAD_F32)
        roll = r.random()
        if roll < 0.35 and self.numbers:
            v = to_f32(float(r.choice(self.numbers)))
            if v is not None:
                w = r.choice([v, v, next_f32(v), next_f32(v, False), -v])
                return w if not math.isinf(w) else v  # FLT_MAX's next is no float32
        if roll < 0.75:
            return r.choice(EDGE_F32)
        return to_f32(round(r.uniform(-2, 2), r.choice([1, 2, 7])))

    def float_value(self):
        r = self.rng
        roll = r.random()
        if roll < 0.35 and self.numbers:
            v = float(r.choice(self.numbers))
            return r.choice([v, v, next_float(v), next_float(v, False), -v])
        if roll < 0.7:
            v = r.choice(EDGE_FLOATS)
            return v if "float-edge" not in self.avoid or 1e-300 < abs(v) < 1e300 else 0.5
        return round(r.uniform(-2, 2), r.choice([1, 2, 17]))

    def length(self):
        """Empty, within the bound, or longer than --list-bound (which the proof assumes away)."""
        r = self.rng.random()
        if r < 0.15:
            return 0
        if r < 0.8 or "long-lists" in self.avoid:
            return self.rng.randint(1, self.list_bound)
        return self.rng.randint(self.list_bound + 1, self.list_bound + 3)

    def sized_length(self, ty):
        """N of a T[N]; of a list<T, N> 0, N, or one between."""
        n = size_of(ty)
        if is_fixed(ty):
            return n
        roll = self.rng.random()
        return 0 if roll < 0.2 else n if roll < 0.5 else self.rng.randint(1, n)

    def bounded_string(self, n, flags):
        """A string of at most n bytes: the edge strings and the spec's that fit, and strings of
        exactly n bytes (ASCII; two-byte characters, an ASCII one last if n is odd)."""
        r = self.rng
        pool = [s for s in EDGE_STRINGS + self.strings + list(flags) if len(s.encode()) <= n]
        if r.random() < 0.35:
            return r.choice(["z" * n, "é" * (n // 2) + "a" * (n % 2), "a" * (n % 2) + "é" * (n // 2)])
        return r.choice(pool)

    def status(self, flags):
        """A status message: some of the feed's flags, sometimes an unknown or repeated one."""
        out = [f for f in flags if self.rng.random() < 0.5]
        if self.rng.random() < 0.1:
            out.append(self.rng.choice(["unknown", ""] + list(flags)))
        return out


def lua_mod(a, b):
    """The spec's `%`: C's fmod, truncating, the sign of `a` (the monitors' arbc_fmod,
    docs/language.md#numbers), not Lua's own flooring `%`."""
    if isinstance(a, int) and isinstance(b, int):
        if b == 0:
            raise ArithmeticError("attempt to perform 'n%%0'")
        m = abs(a) % abs(b)
        return -m if a < 0 else m
    a, b = float(a), float(b)
    if b == 0 or math.isinf(a) or math.isnan(a) or math.isnan(b):
        return math.nan
    return math.fmod(a, b)  # an infinite b gives a back, as C's fmod does


def arith(op, a, b):
    if isinstance(a, dict) or isinstance(b, dict):
        return vec_arith(op, a, b)
    if op == "+" and isinstance(a, str):
        return a + b
    if op == "/":
        a, b = float(a), float(b)
        if b == 0:
            return math.nan if a == 0 or math.isnan(a) else math.copysign(math.inf, a) * \
                math.copysign(1, b)
        return a / b
    if op == "%":
        return lua_mod(a, b)
    if isinstance(a, int) and isinstance(b, int):
        return wrap({"+": a + b, "-": a - b, "*": a * b}[op])
    a, b = float(a), float(b)
    try:
        return {"+": a + b, "-": a - b, "*": a * b}[op]
    except OverflowError:
        return math.inf


def vec_arith(op, a, b):
    if op in ("+", "-"):
        return {k: arith(op, a[k], b[k]) for k in "xyz"}
    if op == "*":
        v, k = (a, b) if isinstance(a, dict) else (b, a)
        return {c: arith("*", v[c], k) for c in "xyz"}
    return {c: arith("/", a[c], b) for c in "xyz"}


def equal(a, b):
    if isinstance(a, dict):
        return set(a) == set(b) and all(equal(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return len(a) == len(b) and all(equal(x, y) for x, y in zip(a, b))
    return a == b


def compare(op, a, b):
    if isinstance(a, str):
        a, b = a.encode(), b.encode()
    return {"<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b}[op]


def lua_min_max(which, args):
    best = args[0]
    for x in args[1:]:
        if (which == "min" and x < best) or (which == "max" and best < x):
            best = x
    return best


def length(v):
    return len(v.encode()) if isinstance(v, str) else len(v)


def evaluate(e, env):
    """The value of Expr `e` with names bound in `env`; NoValue where Lua has none."""
    k = e.kind
    if k == "lit":
        return literal(e)
    if k == "name":
        return env[e.val]
    if k == "field":
        return evaluate(e.args[0], env)[e.val]
    if k == "index":
        xs, i = evaluate(e.args[0], env), evaluate(e.args[1], env)
        if not 0 <= i < len(xs):
            raise NoValue()
        return xs[i]
    if k == "neg":
        v = evaluate(e.args[0], env)
        if isinstance(v, dict):
            return {c: -v[c] for c in "xyz"}
        return wrap(-v) if isinstance(v, int) else -v
    if k == "not":
        return not evaluate(e.args[0], env)
    if k == "bin":
        return binary(e, env)
    if k == "call":
        return call(e, env)
    if k == "record":
        return {f: evaluate(a, env) for f, a in zip(e.val, e.args)}
    if k == "list":
        return [evaluate(a, env) for a in e.args]
    raise ValueError(k)


def binary(e, env):
    op = e.val
    if op == "and":
        return evaluate(e.args[0], env) and evaluate(e.args[1], env)
    if op == "or":
        return evaluate(e.args[0], env) or evaluate(e.args[1], env)
    a, b = evaluate(e.args[0], env), evaluate(e.args[1], env)
    if op in ("==", "!=", "<", "<=", ">", ">=") and mixed_numbers(a, b):
        # An int compared with a float is compared as a float (compiler/lower/lower_body.cc
        # converts it, as C does), not by mathematical value as Lua itself would.
        a, b = float(a), float(b)
    if op == "==":
        return equal(a, b)
    if op == "!=":
        return not equal(a, b)
    if op in ("<", "<=", ">", ">="):
        if U64 in (e.args[0].ty, e.args[1].ty):  # math.ult in the monitor: unsigned
            a, b = a & (2**64 - 1), b & (2**64 - 1)
        return compare(op, a, b)
    if op == "+" and isinstance(a, list):
        return a + b
    return arith(op, a, b)


def mixed_numbers(a, b):
    def kind(x):
        return None if isinstance(x, bool) else int if isinstance(x, int) else \
            float if isinstance(x, float) else None
    return {kind(a), kind(b)} == {int, float}


def call(e, env):
    f = e.val
    if f in ("min_by", "max_by"):
        xs, lam = evaluate(e.args[0], env), e.args[1]
        best = best_key = None
        for x in xs:
            key = evaluate(lam.args[0], {**env, lam.val: x})
            if best is None or (key < best_key if f == "min_by" else key > best_key):
                best, best_key = x, key
        if best is None:
            raise NoValue()
        return best
    args = [evaluate(a, env) for a in e.args]
    if f == "len":
        return length(args[0])
    if f == "abs":
        return wrap(abs(args[0])) if isinstance(args[0], int) else abs(args[0])
    if f in ("min", "max"):
        if len(args) == 1:
            if not args[0]:
                raise NoValue()
            args = args[0]
        if any(isinstance(x, float) for x in args):  # a float min/max takes its ints as floats
            args = [float(x) for x in args]
        return lua_min_max(f, args)
    if f == "vec3":
        return {"x": float(args[0]), "y": float(args[1]), "z": float(args[2])}
    if f == "norm":
        v = args[0]
        return math.sqrt(arith("+", arith("+", v["x"] * v["x"], v["y"] * v["y"]), v["z"] * v["z"]))
    if f == "dist":
        d = vec_arith("-", args[0], args[1])
        return math.sqrt(d["x"] * d["x"] + d["y"] * d["y"] + d["z"] * d["z"])
    raise ValueError(f)


def literal(e):
    t = e.val
    if e.ty == BOOL:
        return t == "true"
    if e.ty == STRING:
        return bytes(t[1:-1], "utf-8").decode("unicode_escape").encode("latin-1").decode("utf-8")
    for unit, scale in (("ms", 0.001), ("min", 60.0), ("s", 1.0)):
        if t.endswith(unit) and not t[0].isalpha():
            return float(t[: -len(unit)]) * scale
    if "." in t or "e" in t:
        return float(t)
    v = int(t)
    return wrap(v)


def to_json(v):
    """A value as the inputs file writes it: NaN and infinities as their strings (NONFINITE)."""
    if isinstance(v, float) and math.isnan(v):
        return "nan"
    if isinstance(v, float) and math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return v
