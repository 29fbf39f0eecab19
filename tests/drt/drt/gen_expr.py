"""Random well-typed expressions of the spec language (docs/language.md#expressions): every
operator and builtin, literals at the edges (0, -0.0, 2^63 - 1, 1e308, empty and non-ASCII
strings), lists, records and lambdas of min_by / max_by; sized numbers (docs/language.md,
"Sized numbers") read where an int or a float is wanted (they promote), put only where they fit
(a narrower type, a constant in range), and uint64 in + - * and comparisons with its partners.
Lists and strings with sizes (docs/language.md, "Lists and strings with sizes"): literals of
exactly N items for a T[N], at most N for a list<T, N>, string constants of at most N bytes for
a string<N>; a T[N] indexed at its last element, one past it and past --list-bound's 4."""
import copy

from .spec import (BOOL, INT, FLOAT, STRING, VEC3, U64, F32, INT_RANGES, Expr, lit, name, fits,
                   is_sized, is_numeric, int_like, assignable, literal_type, size_of, is_fixed)
from .values import literal

INT_LITS = ["0", "1", "2", "3", "5", "7", "10", "100", "9223372036854775807", "4611686018427387904"]
FLOAT_LITS = ["0.0", "0.5", "0.1", "0.3333333333333333", "1.5", "2.0", "1e308", "1e-300", "3.75",
              "0.2", "1e-3"]
DURATION_LITS = ["1ms", "200ms", "0.5s", "1s", "2min"]
STRING_LITS = ['""', '"a"', '"take"', '"é✓"', '"日本"', '"a\\"b"', '"x\\ny"', '"' + "z" * 40 + '"']
# Constants a float32 holds exactly: FLT_MAX, the least subnormal, 0.1 as float32 rounds it.
F32_LITS = ["0.0", "0.5", "1.5", "3.0", "16777216.0", "0.10000000149011612", "3.4028234663852886e38",
            "1.401298464324817e-45", "1.1754943508222875e-38"]
# uint64 constants: those above 2^63 - 1 are uint64 literals (their bits read negative).
U64_LITS = ["0", "1", "7", "4294967296", "9223372036854775807", "9223372036854775808",
            "18446744073709551615", "18446744073709551614"]


class ExprGen:
    """Expressions over `env` (name -> type) of a wanted type; `pure` leaves out now()."""

    def __init__(self, rng, consts=None, avoid=()):
        self.rng = rng
        self.avoid = set(avoid)
        self.consts = consts or {}  # const name -> type
        self.lambda_count = 0

    def chance(self, p):
        return self.rng.random() < p

    def names_of(self, env, ty):
        return [n for n, t in list(env.items()) + list(self.consts.items()) if fits(t, ty)]

    def gen(self, ty, env, depth=3, pure=False):
        if depth <= 0 or self.chance(0.25):
            leaf = self.leaf(ty, env)
            if leaf is not None:
                return leaf
        makers = self.makers(ty, env, depth - 1, pure)
        for _ in range(6):
            e = self.rng.choice(makers)()
            if e is not None:
                return retype(e)
        return self.leaf(ty, env, force=True)

    def leaf(self, ty, env, force=False):
        if (is_numeric(ty) or ty == BOOL) and "sized" not in self.avoid and self.chance(0.3):
            f = self.field_of(ty, env, 0)  # a message's fields, sized ones among them
            if f is not None:
                return f
        names = self.names_of(env, ty)
        local = [n for n in names if n in env]
        if local and self.chance(0.7):
            n = self.rng.choice(local)
            return name(env[n], n)
        if names and self.chance(0.3):
            n = self.rng.choice(names)
            return name(env.get(n, self.consts.get(n)), n)
        if ty == BOOL:
            return lit(BOOL, self.rng.choice(["true", "false"]))
        if ty == INT:
            pool = INT_LITS[:-2] if "int-literal-edge" in self.avoid else INT_LITS
            return lit(INT, self.rng.choice(pool))
        if ty == FLOAT:
            if self.chance(0.15):
                return lit(FLOAT, self.rng.choice(DURATION_LITS))
            pool = [f for f in FLOAT_LITS if "float-edge" not in self.avoid or f not in ("1e308", "1e-300")]
            return lit(FLOAT, self.rng.choice(pool))
        if ty == STRING:
            return lit(STRING, self.rng.choice(STRING_LITS))
        if ty[0] == "string":
            return self.bounded_string(size_of(ty))
        if ty == VEC3:
            return Expr("call", VEC3, [self.leaf(FLOAT, env, True) for _ in range(3)], "vec3")
        if is_sized(ty):
            return self.sized_const(ty)
        if ty[0] == "record":
            return record_lit(ty, [exact(self.leaf(t, env, True), t) for _, t in ty[1]])
        if ty[0] == "list":
            if names:
                n = self.rng.choice(names)
                return name(env.get(n, self.consts.get(n)), n)
            return list_lit([exact(self.leaf(ty[1], env, True), ty[1])
                             for _ in range(self.list_count(ty, 2))], size_of(ty))
        return None

    def bounded_string(self, n):
        """A constant a string<n> takes: a literal or a named constant of at most n bytes, or
        one of exactly n bytes (ASCII, or two-byte characters)."""
        consts = [k for k, b in getattr(self.consts, "string_bytes", {}).items() if b <= n]
        if consts and self.chance(0.2):
            return name(STRING, self.rng.choice(consts))
        pool = [t for t in STRING_LITS if string_bytes(t) <= n]
        pool += ['"' + "z" * n + '"', '"' + "é" * (n // 2) + "a" * (n % 2) + '"']
        return lit(STRING, self.rng.choice(pool))

    def list_count(self, ty, most):
        """How many items a list literal of type `ty` has: N of a T[N], 1 to N of a list<T, N>
        (N itself often), 1 to `most` of a list<T>."""
        n = size_of(ty)
        if is_fixed(ty):
            return n
        if n:
            return self.rng.choice([n, self.rng.randint(1, n)])
        return self.rng.randint(1, most)

    def sized_const(self, ty):
        """A constant the sized type holds: its edges, 0, -1, and a random one in its range."""
        r = self.rng
        if ty == F32:
            e = lit(FLOAT, r.choice(F32_LITS))
            return Expr("neg", FLOAT, [e]) if self.chance(0.3) else e
        if ty == U64:
            t = r.choice(U64_LITS)
            return lit(U64 if int(t) >= 2**63 else INT, t)
        lo, hi = INT_RANGES[ty[0]]
        return int_lit(r.choice([0, 1, hi, hi - 1, lo, lo + 1, -1 if lo else 2, r.randint(lo, hi)]))

    def makers(self, ty, env, d, pure):
        g = self.gen
        m = []
        # Reading a field, an element or the best of a list works for any type.
        m.append(lambda: self.field_of(ty, env, d))
        m.append(lambda: self.index_of(ty, env, d))
        m.append(lambda: self.best_of(ty, env, d))
        if ty == BOOL:
            m += [lambda: Expr("not", BOOL, [g(BOOL, env, d, pure)]),
                  lambda: Expr("bin", BOOL, [g(BOOL, env, d, pure), g(BOOL, env, d, pure)],
                               self.rng.choice(["and", "or"])),
                  lambda: self.compare(env, d, pure), lambda: self.compare(env, d, pure),
                  lambda: self.equality(env, d, pure), lambda: self.list_equality(env)]
        elif ty == INT:
            m += [lambda: self.int_arith(env, d, pure),
                  lambda: Expr("neg", INT, [g(INT, env, d, pure)]),
                  lambda: Expr("call", INT, [g(INT, env, d, pure)], "abs"),
                  lambda: Expr("call", INT, [g(INT, env, d, pure) for _ in range(self.rng.randint(2, 3))],
                               self.rng.choice(["min", "max"])),
                  lambda: self.length(env, d)]
        elif ty == FLOAT:
            m += [lambda: self.arith(env, d, pure), lambda: self.arith(env, d, pure),
                  lambda: Expr("neg", FLOAT, [g(FLOAT, env, d, pure)]),
                  lambda: Expr("call", FLOAT, [g(FLOAT, env, d, pure)], "abs"),
                  lambda: Expr("call", FLOAT, [g(FLOAT, env, d, pure), g(self.num(), env, d, pure)],
                               self.rng.choice(["min", "max"])),
                  lambda: Expr("call", FLOAT, [g(VEC3, env, d, pure)], "norm"),
                  lambda: Expr("call", FLOAT, [g(VEC3, env, d, pure), g(VEC3, env, d, pure)], "dist"),
                  lambda: Expr("field", FLOAT, [g(VEC3, env, d, pure)], self.rng.choice("xyz")),
                  lambda: g(INT, env, d, pure)]
            if not pure:
                m.append(lambda: Expr("call", FLOAT, [], "now"))
        elif ty == STRING:
            m += [lambda: Expr("bin", STRING, [g(STRING, env, d, pure), g(STRING, env, d, pure)], "+")]
        elif ty == VEC3:
            m += [lambda: Expr("call", VEC3, [g(FLOAT, env, d, pure) for _ in range(3)], "vec3"),
                  lambda: Expr("bin", VEC3, [g(VEC3, env, d, pure), g(VEC3, env, d, pure)],
                               self.rng.choice(["+", "-"])),
                  lambda: Expr("bin", VEC3, [g(VEC3, env, d, pure), g(self.num(), env, d, pure)], "*"),
                  lambda: Expr("bin", VEC3, [g(self.num(), env, d, pure), g(VEC3, env, d, pure)], "*"),
                  lambda: Expr("bin", VEC3, [g(VEC3, env, d, pure), self.nonzero()], "/"),
                  lambda: Expr("neg", VEC3, [g(VEC3, env, d, pure)])]
        elif ty == U64:
            m += [lambda: self.u64_arith(env, d, pure)]
        elif ty[0] == "record":
            m += [lambda: record_lit(ty, [exact(g(t, env, d, pure), t) for _, t in ty[1]])]
        elif ty[0] == "list":
            m += [lambda: self.list_of(ty, env, d, pure)]
        if ty == BOOL and "sized" not in self.avoid:
            m += [lambda: self.u64_compare(env, d, pure)]
        return m

    def u64_source(self, env, d):
        """A uint64 that is not a constant: a name, a field or an element of that type."""
        exactly = (lambda t: t == U64)
        names = [n for n, t in env.items() if t == U64]
        opts = [lambda: name(U64, self.rng.choice(names)) if names else None,
                lambda: self.field_of(U64, env, d, exactly), lambda: self.index_of(U64, env, d, exactly)]
        self.rng.shuffle(opts)
        for make in opts:
            e = make()
            if e is not None:
                return e
        return None

    def u64_arith(self, env, d, pure):
        """`+ - *` of a uint64 (wrapping modulo 2^64) with a partner a uint64 takes: another uint64,
        an unsigned narrower integer or a constant >= 0 (docs/language.md, "Sized numbers")."""
        a = self.u64_source(env, d)
        if a is None:
            return None
        b = self.gen(U64, env, d, pure)
        if self.chance(0.5):
            a, b = b, a
        return Expr("bin", U64, [a, b], self.rng.choice(["+", "-", "*"]))

    def u64_compare(self, env, d, pure):
        """A uint64 compared with a partner it takes: the orderings compare unsigned."""
        a = self.u64_source(env, d)
        if a is None:
            return None
        if self.chance(0.3):
            a = self.u64_arith(env, d, pure)
        b = self.gen(U64, env, d, pure)
        if self.chance(0.5):
            a, b = b, a
        return Expr("bin", BOOL, [a, b], self.rng.choice(["<", "<=", ">", ">=", "==", "!="]))

    def int_arith(self, env, d, pure):
        op = self.rng.choice(["+", "-", "*", "%"])
        rhs = self.gen(INT, env, d, pure)
        # A constant zero divisor is a check error (division-by-zero); zero from data is not.
        if op == "%" and ("int-mod" in self.avoid or (rhs.kind == "lit" and rhs.val == "0")):
            rhs = lit(INT, self.rng.choice(["2", "3", "10"]))
        return Expr("bin", INT, [self.gen(INT, env, d, pure), rhs], op)

    def num(self):
        return self.rng.choice([INT, FLOAT])

    def nonzero(self):
        t = self.rng.choice(["2", "3", "0.5", "4.0", "10"])
        return lit(FLOAT if "." in t else INT, t)

    def arith(self, env, d, pure):
        """A float from + - * / %: at least one side a float, or `/`; a divisor that is not a
        nonzero constant makes the rule opaque for data (docs/checks.md#message-data)."""
        op = self.rng.choice(["+", "-", "*", "/", "%", "/"])
        a = self.gen(FLOAT, env, d, pure)
        if op in ("/", "%") and (self.chance(0.7) or "int-mod" in self.avoid):
            b = self.nonzero()
        else:
            b = self.gen(self.num(), env, d, pure)
        if self.chance(0.5):
            a, b = (b, a) if op not in ("/", "%") else (a, b)
        return Expr("bin", FLOAT, [a, b], op)

    def compare(self, env, d, pure):
        op = self.rng.choice(["<", "<=", ">", ">="])
        if "sized" not in self.avoid and self.chance(0.3):
            edge = self.edge_compare(env, op)
            if edge is not None:
                return edge
        if self.chance(0.15):
            ty = STRING
        else:
            ty = self.num()
        return Expr("bin", BOOL, [self.gen(ty, env, d, pure), self.gen(ty, env, d, pure)], op)

    def edge_compare(self, env, op):
        """A sized number against an edge of its type or just past it (`m.level > 127` of an
        int8, `m.range < 1e-46` of a float32): true or false of every value the type holds,
        which the proof knows only if it gives the field its range, as the runtime does."""
        want = (lambda t: t not in (INT, FLOAT, U64) and is_numeric(t))
        x = self.field_of(INT, env, 0, want)
        names = [n for n, t in env.items() if want(t)]
        if names and (x is None or self.chance(0.5)):
            n = self.rng.choice(names)
            x = name(env[n], n)
        if x is None:
            return None
        if x.ty == F32:
            c = lit(FLOAT, self.rng.choice(["3.4028234663852886e38", "3.4028235677973366e38",
                                             "1.401298464324817e-45", "1e-46", "16777216.0",
                                             "16777217.0", "0.0"]))
            c = Expr("neg", FLOAT, [c]) if self.chance(0.3) else c
        else:
            lo, hi = INT_RANGES[x.ty[0]]
            c = int_lit(self.rng.choice([lo, hi, lo - 1, hi + 1, hi - 1, 0]))
        return Expr("bin", BOOL, [x, c] if self.chance(0.7) else [c, x], op)

    def edge_pair(self, env):
        """Two comparisons of one sized number with one constant: the first at an edge of its
        type, the second its negation (exclusive), the other strict side (exclusive but for the
        constant itself), or an overlapping one; None if the message has no sized number."""
        op = self.rng.choice(["<", "<=", ">", ">="])
        first = self.edge_compare(env, op)
        if first is None or self.chance(0.3):
            x = self.u64_source(env, 0)
            first = first if x is None else Expr("bin", BOOL, [x, self.sized_const(U64)], op)
        if first is None:
            return None
        x, c = first.args
        other = {"<": [">=", ">", "<="], "<=": [">", ">=", "<"], ">": ["<=", "<", ">="],
                 ">=": ["<", "<=", ">"]}[op]
        return first, Expr("bin", BOOL, [x, c], self.rng.choice(other))

    def equality(self, env, d, pure):
        ty = self.rng.choice([INT, FLOAT, STRING, BOOL, VEC3] + [t for t in env.values()])
        a, b = self.gen(ty, env, d, pure), self.gen(ty, env, d, pure)
        # Two records or lists compare only when each type takes the other's values: a literal
        # `{ f: 1 }` is a record of an int, not of the port's int8.
        # Sizes do not matter to `==` (a float[3] compares with a list<float>).
        if not (is_numeric(a.ty) and is_numeric(b.ty)) and \
                not (assignable(a.ty, b.ty, False) and assignable(b.ty, a.ty, False)):
            b = a
        return Expr("bin", BOOL, [a, b], self.rng.choice(["==", "!="]))

    def length(self, env, d):
        lists = self.lists_in(env) + [name(t, n) for n, t in env.items()
                                      if t[0] == "string" and "string-len" not in self.avoid]
        if not lists:
            return None if "string-len" in self.avoid else Expr("call", INT, [self.gen(STRING, env, d)], "len")
        if self.chance(0.2) and "string-len" not in self.avoid:
            return Expr("call", INT, [self.gen(STRING, env, d)], "len")
        return Expr("call", INT, [self.rng.choice(lists)], "len")

    def lists_in(self, env, kind="list"):
        """The lists (strings) in scope: names, and fields of records in scope (`m.cov` of a
        float[3])."""
        out = [name(t, n) for n, t in env.items() if t[0] == kind]
        return out + [Expr("field", ft, [name(t, n)], f) for n, t in env.items() if t[0] == "record"
                      for f, ft in t[1] if ft[0] == kind]

    def size_pair(self, env):
        """Two accepts over one list or string with a size that its size keeps apart or lets
        overlap: its length against N, N - 1, N + 1, 0, 4 and 5 (`len(m.s) > 7` of a
        string<8>), or an element of a T[N] of numbers at its end, one past it or at 5 against a
        constant; None if none is in scope."""
        opts = [x for x in self.lists_in(env) + self.lists_in(env, "string") if size_of(x.ty)]
        if not opts:
            return None
        x = self.rng.choice(opts)
        n = size_of(x.ty)
        ops = ["<", "<=", ">", ">=", "==", "!="]

        def one():
            if is_fixed(x.ty) and is_numeric(x.ty[1]) and self.chance(0.4):
                at = Expr("index", x.ty[1], [copy.deepcopy(x), lit(INT, str(self.rng.choice([n - 1, n, 5])))])
                return Expr("bin", BOOL, [at, lit(INT, self.rng.choice(["0", "1"]))], self.rng.choice(ops))
            k = self.rng.choice([0, n - 1, n, n, n + 1, 4, 5])
            return Expr("bin", BOOL, [Expr("call", INT, [copy.deepcopy(x)], "len"), lit(INT, str(k))],
                        self.rng.choice(ops))
        return one(), one()

    def field_of(self, ty, env, d, want=None):
        """`r.f` of a record in scope whose field f may stand for ty (`want`: which types)."""
        want = want or (lambda t: fits(t, ty))
        opts = [(n, f, ft) for n, t in env.items() if t[0] == "record" for f, ft in t[1] if want(ft)]
        if not opts:
            return None
        n, f, ft = self.rng.choice(opts)
        return Expr("field", ft, [name(env[n], n)], f)

    def index_of(self, ty, env, d, want=None):
        want = want or (lambda t: fits(t, ty))
        opts = [x for x in self.lists_in(env) if want(x.ty[1])]
        if not opts:
            return None
        xs = self.rng.choice(opts)
        return Expr("index", xs.ty[1], [xs, self.index(xs, env, d)])

    def index(self, xs, env, d):
        """An index into `xs`: computed or constant; of a T[N] also its last (constant, or
        `len(xs) - 1`), N (one past it) and 4 and 5 (past --list-bound's 4)."""
        n = size_of(xs.ty) if is_fixed(xs.ty) else 0
        roll = self.rng.random()
        if n and roll < 0.3:
            return lit(INT, str(self.rng.choice([0, n - 1, n - 1, n, 4, 5, n // 2])))
        if n and roll < 0.45:
            length = Expr("call", INT, [copy.deepcopy(xs)], "len")
            if self.chance(0.5) or "int-mod" in self.avoid:
                return Expr("bin", INT, [length, lit(INT, "1")], "-")
            return Expr("bin", INT, [self.gen(INT, env, min(d, 1)), length], "%")
        if self.chance(0.3):
            return self.gen(INT, env, d)
        return lit(INT, self.rng.choice(["0", "1", "4", "5"]))

    def best_of(self, ty, env, d):
        """min_by / max_by(list, x => key) of a list in scope whose elements may stand for ty."""
        opts = [x for x in self.lists_in(env) if fits(x.ty[1], ty)]
        if not opts:
            return None
        xs = self.rng.choice(opts)
        element = xs.ty[1]
        self.lambda_count += 1
        var = f"o{self.lambda_count}"
        key = self.gen(self.num(), {**env, var: element}, min(d, 2), pure=True)
        return Expr("call", element, [xs, Expr("lambda", key.ty, [key], var)],
                    self.rng.choice(["min_by", "max_by"]))

    def list_of(self, ty, env, d, pure):
        """A list literal of type `ty` (its count as list_count says; items past the third are
        leaves, so that a float[8] stays short)."""
        items = [self.gen(ty[1], env, d, pure) if i < 3 else self.leaf(ty[1], env, True)
                 for i in range(self.list_count(ty, 3))]
        return list_lit([exact(e, ty[1]) for e in items], size_of(ty))

    def list_equality(self, env):
        """A list in scope `==` or `!=` a literal of its size, or one more or fewer (sizes are not
        part of `==`); items the list's elements do not compare with (a literal `1` for an int8)
        are its own elements read back (`m.a == [m.a[1], m.a[0]]`)."""
        opts = self.lists_in(env)
        if not opts:
            return None
        xs = self.rng.choice(opts)
        n = size_of(xs.ty) or self.rng.randint(1, 3)
        count = max(1, self.rng.choice([n, n, n - 1, n + 1]))
        other = list_lit([exact(self.leaf(xs.ty[1], env, True), xs.ty[1]) for _ in range(count)], count)
        if not (assignable(other.ty, xs.ty, False) and assignable(xs.ty, other.ty, False)):
            other = list_lit([Expr("index", xs.ty[1], [copy.deepcopy(xs), lit(INT, str(self.rng.randrange(n)))])
                              for _ in range(count)], count)
            if not (assignable(other.ty, xs.ty, False) and assignable(xs.ty, other.ty, False)):
                return None  # [m.a[0], m.a[1]] of an int8 list is a list<int>: sized items join
        pair = [xs, other] if self.chance(0.7) else [other, xs]
        return Expr("bin", BOOL, pair, self.rng.choice(["==", "==", "!="]))


def retype(e):
    """A float-wanted arithmetic node whose operands all came out integers is an int (sema's
    rule: `int op int` is int except `/`, sized integers promoted; min, max and abs of ints are
    ints)."""
    if e.ty != FLOAT:
        return e
    if e.kind == "bin" and e.val in "+-*%" and all(int_like(a.ty) for a in e.args):
        e.ty = INT
    elif e.kind == "neg" and int_like(e.args[0].ty):
        e.ty = INT
    elif e.kind == "call" and e.val in ("min", "max", "abs") and all(int_like(a.ty) for a in e.args):
        e.ty = INT
    return e


def exact(e, ty):
    """`e` with exactly type `ty` where an int would do for a float, or a sized number for an
    int or a float, but change a record's or a list's type ({f: 1} is a record of an int)."""
    if ty == FLOAT and e.ty != FLOAT:
        return Expr("bin", FLOAT, [e, lit(FLOAT, "0.0")], "+")
    if ty == INT and e.ty != INT:
        return Expr("bin", INT, [e, lit(INT, "0")], "+")
    return e


def int_lit(v):
    """An int constant; a negative one is the negation of a literal (-128 for an int8's least)."""
    return lit(INT, str(v)) if v >= 0 else Expr("neg", INT, [lit(INT, str(-v))])


def record_lit(ty, args):
    """A record literal of the fields of `ty`, typed as arbc types it (by its fields' values)."""
    names = [f for f, _ in ty[1]]
    return Expr("record", literal_type("record", [(f, a.ty) for f, a in zip(names, args)]), args, names)


def list_lit(items, count=0):
    """A list literal, typed as arbc types it. Items of a record or list type must each fit the
    first's type; when a sized field makes them differ ({ f: 1 } and { f: m.a }), one is kept,
    or with `count` (a literal for a T[N] or a list<T, N>) the first one that many times."""
    first = items[0].ty
    if not is_numeric(first) and not all(assignable(i.ty, first) for i in items[1:]):
        items = [items[0]] * len(items) if count else items[:1]
    u64 = [i for i in items if i.ty == U64]
    if u64 and any(not i.ty[0].startswith("u") for i in items):
        # A uint64 shares a list only with unsigned items (an int constant 7 is no uint64).
        items = [i if i.ty[0].startswith("u") else u64[0] for i in items]
    return Expr("list", literal_type("list", [i.ty for i in items]), items)


def string_bytes(text):
    """The bytes of a string literal's value (`"é"` is 2)."""
    return len(literal(lit(STRING, text)).encode())
