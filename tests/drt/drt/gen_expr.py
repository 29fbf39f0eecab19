"""Random well-typed expressions of the spec language (docs/language.md#expressions): every
operator and builtin, literals at the edges (0, -0.0, 2^63 - 1, 1e308, empty and non-ASCII
strings), lists, records and lambdas of min_by / max_by."""
from .spec import BOOL, INT, FLOAT, STRING, VEC3, Expr, lit, name, is_number, fits

INT_LITS = ["0", "1", "2", "3", "5", "7", "10", "100", "9223372036854775807", "4611686018427387904"]
FLOAT_LITS = ["0.0", "0.5", "0.1", "0.3333333333333333", "1.5", "2.0", "1e308", "1e-300", "3.75",
              "0.2", "1e-3"]
DURATION_LITS = ["1ms", "200ms", "0.5s", "1s", "2min"]
STRING_LITS = ['""', '"a"', '"take"', '"é✓"', '"日本"', '"a\\"b"', '"x\\ny"', '"' + "z" * 40 + '"']


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
        if ty == VEC3:
            return Expr("call", VEC3, [self.leaf(FLOAT, env, True) for _ in range(3)], "vec3")
        if ty[0] == "record":
            return Expr("record", ty, [exact(self.leaf(t, env, True), t) for _, t in ty[1]],
                        [f for f, _ in ty[1]])
        if ty[0] == "list":
            if names:
                n = self.rng.choice(names)
                return name(env.get(n, self.consts.get(n)), n)
            items = [exact(self.leaf(ty[1], env, True), ty[1]) for _ in range(self.rng.randint(1, 2))]
            return Expr("list", ty, items)
        return None

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
                  lambda: self.equality(env, d, pure)]
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
        elif ty[0] == "record":
            m += [lambda: Expr("record", ty, [exact(g(t, env, d, pure), t) for _, t in ty[1]],
                               [f for f, _ in ty[1]])]
        elif ty[0] == "list":
            m += [lambda: Expr("list", ty, [exact(g(ty[1], env, d, pure), ty[1])
                                            for _ in range(self.rng.randint(1, 3))])]

        return m

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
        if self.chance(0.15):
            ty = STRING
        else:
            ty = self.num()
        op = self.rng.choice(["<", "<=", ">", ">="])
        return Expr("bin", BOOL, [self.gen(ty, env, d, pure), self.gen(ty, env, d, pure)], op)

    def equality(self, env, d, pure):
        ty = self.rng.choice([INT, FLOAT, STRING, BOOL, VEC3] + [t for t in env.values()])
        return Expr("bin", BOOL, [self.gen(ty, env, d, pure), self.gen(ty, env, d, pure)],
                    self.rng.choice(["==", "!="]))

    def length(self, env, d):
        lists = [n for n, t in env.items() if t[0] == "list" or (t == STRING and "string-len" not in self.avoid)]
        if not lists:
            return None if "string-len" in self.avoid else Expr("call", INT, [self.gen(STRING, env, d)], "len")
        if self.chance(0.2) and "string-len" not in self.avoid:
            return Expr("call", INT, [self.gen(STRING, env, d)], "len")
        n = self.rng.choice(lists)
        return Expr("call", INT, [name(env[n], n)], "len")

    def field_of(self, ty, env, d):
        """`r.f` of a record in scope whose field f has type ty."""
        opts = [(n, f) for n, t in env.items() if t[0] == "record" for f, ft in t[1] if ft == ty]
        if not opts:
            return None
        n, f = self.rng.choice(opts)
        return Expr("field", ty, [name(env[n], n)], f)

    def index_of(self, ty, env, d):
        opts = [n for n, t in env.items() if t == ("list", ty)]
        if not opts:
            return None
        n = self.rng.choice(opts)
        i = self.gen(INT, env, d) if self.chance(0.3) else lit(INT, self.rng.choice(["0", "1", "4", "5"]))
        return Expr("index", ty, [name(env[n], n), i])

    def best_of(self, ty, env, d):
        """min_by / max_by(list, x => key) of a list in scope whose elements have type ty."""
        opts = [n for n, t in env.items() if t == ("list", ty)]
        if not opts:
            return None
        n = self.rng.choice(opts)
        self.lambda_count += 1
        var = f"o{self.lambda_count}"
        key = self.gen(self.num(), {**env, var: ty}, min(d, 2), pure=True)
        return Expr("call", ty, [name(env[n], n), Expr("lambda", key.ty, [key], var)],
                    self.rng.choice(["min_by", "max_by"]))


def retype(e):
    """A float-wanted arithmetic node whose operands all came out int is an int (sema's rule:
    `int op int` is int except `/`; min, max and abs of ints are ints)."""
    if e.ty != FLOAT:
        return e
    if e.kind == "bin" and e.val in "+-*%" and all(a.ty == INT for a in e.args):
        e.ty = INT
    elif e.kind == "neg" and e.args[0].ty == INT:
        e.ty = INT
    elif e.kind == "call" and e.val in ("min", "max", "abs") and all(a.ty == INT for a in e.args):
        e.ty = INT
    return e


def exact(e, ty):
    """`e` with exactly type `ty` where an int would do for a float but change a record's or a
    list's type ({f: 1} is a record of an int)."""
    if ty == FLOAT and e.ty == INT:
        return Expr("bin", FLOAT, [e, lit(FLOAT, "0.0")], "+")
    return e
