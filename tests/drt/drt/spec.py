"""A structured spec (docs/language.md) that prints as spec text, so that the generator can
make one and the shrinker can take it apart.

Types are tuples: ("bool",), ("int",), ("float",), ("string",), ("vec3",), ("list", T),
("record", ((field, T), ...)), and the sized numbers by their canonical names (docs/language.md,
"Sized numbers"): ("int8",) ... ("uint64",), ("float32",); `int` is int64 and `float` float64.
Lists and strings with sizes (docs/language.md, "Lists and strings with sizes") carry them:
("list", T, N, True) is `T[N]` (exactly N), ("list", T, N, False) `list<T, N>` (at most N),
("string", N) `string<N>` (at most N bytes); whatever reads a list (`t[0] == "list"`, `t[1]`)
reads them alike.
Expressions are `Expr` trees; every compound expression prints in parentheses, so the printer
never depends on operator precedence.
"""
from dataclasses import dataclass, field
from typing import List, Optional, Tuple

BOOL, INT, FLOAT, STRING, VEC3 = ("bool",), ("int",), ("float",), ("string",), ("vec3",)

# The sized integers' ranges; a uint64 is held as its 64-bit pattern (an int64), as Lua holds it.
INT_RANGES = {"int8": (-2**7, 2**7 - 1), "int16": (-2**15, 2**15 - 1), "int32": (-2**31, 2**31 - 1),
              "uint8": (0, 2**8 - 1), "uint16": (0, 2**16 - 1), "uint32": (0, 2**32 - 1),
              "uint64": (0, 2**64 - 1), "int": (-2**63, 2**63 - 1)}
U64, F32 = ("uint64",), ("float32",)
SIZED = [(n,) for n in INT_RANGES if n != "int"] + [F32]
# Other spellings of one type (core/number_types.def): a spec may write any of them.
SPELLINGS = {"int": ["int", "int64"], "float": ["float", "float64"], "uint8": ["uint8", "byte", "char"]}


def list_of(t):
    return ("list", t)


def fixed_of(t, n):
    return ("list", t, n, True)


def bounded_of(t, n):
    return ("list", t, n, False)


def string_of(n):
    return ("string", n)


def is_string(t):
    return t[0] == "string"


def size_of(t):
    """N of T[N], list<T, N> and string<N>; 0 for an unbounded list or string (or any other)."""
    if t[0] == "list":
        return t[2] if len(t) > 2 else 0
    if t[0] == "string":
        return t[1] if len(t) > 1 else 0
    return 0


def is_fixed(t):
    return t[0] == "list" and len(t) > 3 and t[3]


def size_fits(frm, to):
    """arbc's size_fits(): every length a `frm` list or string can have is one `to` allows."""
    n = size_of(to)
    if n == 0:
        return True
    if is_fixed(to):
        return is_fixed(frm) and size_of(frm) == n
    return 0 < size_of(frm) <= n


def count_fits(count, to):
    """Whether a literal of `count` items (a list) or bytes (a string constant) goes into `to`."""
    n = size_of(to)
    return n == 0 or (count == n if is_fixed(to) else count <= n)


def unsized(t):
    """The type with every size dropped: its shape."""
    if t[0] == "list":
        return ("list", unsized(t[1]))
    if t[0] == "string":
        return STRING
    if t[0] == "record":
        return ("record", tuple((f, unsized(ft)) for f, ft in t[1]))
    return t


class Consts(dict):
    """A spec's constants, name -> type, and the bytes of each string constant's value: a
    string<N> takes a named constant of at most N bytes (docs/language.md)."""

    def __init__(self):
        super().__init__()
        self.string_bytes = {}


def is_number(t):
    return t in (INT, FLOAT)


def is_sized(t):
    return t in SIZED


def is_numeric(t):
    return t in (INT, FLOAT) or t in SIZED


def int_like(t):
    """An integer that promotes to an int in arithmetic (every integer but uint64)."""
    return t == INT or (t in SIZED and t not in (U64, F32))


def is_float(t):
    return t in (FLOAT, F32)


def bits(t):
    if t in (INT, FLOAT, U64):
        return 64
    return 32 if t == F32 else int(t[0].lstrip("uint"))


def number_assignable(frm, to):
    """Whether every value of number type `frm` is one of `to` (compiler/frontend/type_rules.cc):
    int8 into int32, uint16 into float32, float32 into float; int into float (the language's
    old rule); a uint64 only into a uint64, which takes every unsigned integer."""
    if is_float(frm):
        return is_float(to) and bits(frm) <= bits(to)
    if frm == U64:
        return to == U64
    if is_float(to):
        return to == FLOAT or bits(frm) <= 16
    if to == U64:
        return frm[0].startswith("u")
    lo, hi = INT_RANGES[frm[0]]
    return INT_RANGES[to[0]][0] <= lo and hi <= INT_RANGES[to[0]][1]


def assignable(frm, to, sizes=True):
    """arbc's assignable(): what may be stored or delivered where `to` is expected; without
    `sizes` only the shapes (what `==` of a float[9] and a list<float> asks)."""
    if is_numeric(frm) and is_numeric(to):
        return number_assignable(frm, to)
    if frm[0] != to[0]:
        return False
    if sizes and not size_fits(frm, to):
        return False
    if frm[0] == "list":
        return assignable(frm[1], to[1], sizes)
    if frm[0] == "record":
        fields = dict(to[1])
        return len(frm[1]) == len(fields) and all(f in fields and assignable(t, fields[f], sizes)
                                                   for f, t in frm[1])
    return True


def has_sized(t):
    if t[0] == "list":
        return has_sized(t[1])
    if t[0] == "record":
        return any(has_sized(ft) for _, ft in t[1])
    return is_sized(t)


def has_size(t):
    """Whether a list or string with a size is the type or one of its record's fields."""
    return bool(size_of(t)) or t[0] == "record" and any(size_of(ft) for _, ft in t[1])


def arithmetic_type(a, b):
    """The type of `a op b` for + - * % (core/type.cc): float if either is a float, uint64 if
    either is a uint64, else int: sized numbers promote."""
    if is_float(a) or is_float(b):
        return FLOAT
    return U64 if U64 in (a, b) else INT


def literal_type(kind, items):
    """The type arbc gives a record literal (its fields' types) or a list literal (its first
    item's type, joined with each next number item's as arithmetic joins them)."""
    if kind == "record":
        return ("record", tuple(items))
    element = items[0]
    for t in items[1:]:
        if is_numeric(element) and is_numeric(t):
            element = arithmetic_type(element, t)
    return ("list", element)


def type_text(t, aliases=None, spellings=None):
    """The spec text of a type; a record or list that has an alias prints as its name, a number
    type as the spec spells it (`byte` for uint8, `int64` for int)."""
    if aliases:
        for name, aliased in aliases.items():
            if aliased == t:
                return name
    if t[0] == "list":
        element = type_text(t[1], aliases, spellings)
        if is_fixed(t):
            return f"{element}[{t[2]}]"
        return f"list<{element}, {t[2]}>" if size_of(t) else f"list<{element}>"
    if t[0] == "string" and size_of(t):
        return f"string<{t[1]}>"
    if t[0] == "record":
        return "{ " + ", ".join(f"{f}: {type_text(ft, aliases, spellings)}" for f, ft in t[1]) + " }"
    return (spellings or {}).get(t[0], t[0])


def fits(value_type, expected):
    """Whether an expression of `value_type` may stand where the generator wants `expected`: the
    same type; for an int any integer that promotes to one; for a float also any float; for a
    sized number a type whose every value it holds (a uint64 stands only for itself); for a
    list, string or record one of its shape whose sizes fit (a string<4> for a string<8>)."""
    if value_type == expected:
        return True
    if expected == INT:
        return int_like(value_type)
    if expected == FLOAT:
        return int_like(value_type) or value_type == F32
    if is_sized(expected) and is_numeric(value_type):
        return number_assignable(value_type, expected)
    if expected[0] in ("list", "string", "record") and unsized(value_type) == unsized(expected):
        return assignable(value_type, expected)  # a float[3] for a list<float>, not the reverse
    return False


@dataclass
class Expr:
    kind: str           # lit, name, field, index, neg, not, bin, call, lambda, record, list
    ty: tuple
    args: list = field(default_factory=list)
    val: object = None  # lit: its text; name/field: the name; bin: the operator; call: callee

    def text(self):
        k = self.kind
        if k in ("lit", "name"):
            return self.val
        if k == "field":
            return f"{self.args[0].text()}.{self.val}"
        if k == "index":
            return f"{self.args[0].text()}[{self.args[1].text()}]"
        if k == "neg":
            return f"(-{self.args[0].text()})"
        if k == "not":
            return f"(not {self.args[0].text()})"
        if k == "bin":
            return f"({self.args[0].text()} {self.val} {self.args[1].text()})"
        if k == "call":
            return f"{self.val}({', '.join(a.text() for a in self.args)})"
        if k == "lambda":
            return f"{self.val} => {self.args[0].text()}"
        if k == "record":
            return "{ " + ", ".join(f"{f}: {a.text()}" for f, a in zip(self.val, self.args)) + " }"
        if k == "list":
            return "[" + ", ".join(a.text() for a in self.args) + "]"
        raise ValueError(k)


def lit(ty, text):
    return Expr("lit", ty, [], text)


def name(ty, n):
    return Expr("name", ty, [], n)


@dataclass
class Stmt:
    kind: str          # let var assign accept set unset if emit throttle every script
    name: str = ""     # let/var/assign/set/unset: the name; script: the file
    expr: Optional[Expr] = None
    duration: str = ""  # set ... for D; throttle D; every D
    branches: list = field(default_factory=list)  # if: [(cond or None, [Stmt])]

    def lines(self, indent):
        pad = "  " * indent
        k = self.kind
        if k in ("let", "var"):
            return [f"{pad}{k} {self.name} = {self.expr.text()};"]
        if k == "assign":
            return [f"{pad}{self.name} = {self.expr.text()};"]
        if k in ("accept", "emit"):
            return [f"{pad}{k} {self.expr.text()};"]
        if k == "set":
            return [f"{pad}set {self.name}" + (f" for {self.duration}" if self.duration else "") + ";"]
        if k == "unset":
            return [f"{pad}unset {self.name};"]
        if k == "throttle":
            return [f"{pad}throttle {self.duration};"]
        if k == "script":
            return [f'{pad}script "{self.name}";']
        if k == "every":
            return [f"{pad}every {self.duration} {{"] + block_lines(self.branches[0][1], indent + 1) + \
                [f"{pad}}}"]
        if k == "if":
            out = []
            for i, (cond, body) in enumerate(self.branches):
                head = "if" if i == 0 else ("} else if" if cond is not None else "} else")
                head = pad + head + (f" {cond.text()}" if cond is not None else "") + " {"
                out.append(head)
                out += block_lines(body, indent + 1)
            out.append(pad + "}")
            return out
        raise ValueError(k)


def block_lines(stmts, indent):
    out = []
    for s in stmts:
        out += s.lines(indent)
    return out


@dataclass
class Rule:
    name: str
    source: str                 # "M.p"
    when: Optional[str] = None  # a constraint's text, "otherwise", or None
    hold: str = ""
    body: Optional[List[Stmt]] = None  # None: `;`
    pred: Optional[Expr] = None  # a predicate over `emitted` its body makes true (gen_body.py)
    # `then set e` / `then unset e` (docs/language.md#events-set-on-delivery): (op, event)
    effects: List[Tuple[str, str]] = field(default_factory=list)

    def lines(self):
        head = f"  {self.name}: from {self.source}"
        if self.when:
            head += f" when {self.when}"
        if self.hold:
            head += f" hold {self.hold}"
        if self.effects:
            head += " then " + ", ".join(f"{op} {e}" for op, e in self.effects)
        if self.body is None:
            return [head + ";"]
        return [head + " {"] + block_lines(self.body, 2) + ["  }"]


@dataclass
class Arbitrate:
    port: str
    by_priority: bool = False
    complete: bool = False
    rules: List[Rule] = field(default_factory=list)

    def lines(self):
        head = f"arbitrate {self.port}" + (" by priority" if self.by_priority else "") + \
            (" complete" if self.complete else "") + " {"
        out = [head]
        for r in self.rules:
            out += r.lines()
        return out + ["}"]


@dataclass
class Connect:
    source: str
    dest: str
    body: Optional[List[Stmt]] = None

    def lines(self):
        head = f"connect {self.source} -> {self.dest}"
        if self.body is None:
            return [head + ";"]
        return [head + " {"] + block_lines(self.body, 1) + ["}"]


@dataclass
class Module:
    name: str
    ports: list  # [(direction, port, type)]


@dataclass
class Decl:
    """Any other declaration: its text, and what it is (for the shrinker and the oracle)."""
    kind: str
    text: str
    info: dict = field(default_factory=dict)

    def lines(self):
        return [self.text]


@dataclass
class Spec:
    app: str
    aliases: dict = field(default_factory=dict)     # type name -> type
    consts: list = field(default_factory=list)      # [(name, Expr)]
    modules: List[Module] = field(default_factory=list)
    decls: List[object] = field(default_factory=list)  # Decl, Arbitrate, Connect, in order
    scripts: dict = field(default_factory=dict)     # file name -> Lua text
    spellings: dict = field(default_factory=dict)   # number type -> how this spec writes it

    def text(self):
        out = [f'app {self.app} "a random app of the differential test (tests/drt)";']
        for n, t in self.aliases.items():
            out.append(f"type {n} = {type_text(t, None, self.spellings)};")
        for n, e in self.consts:
            out.append(f"const {n} = {e.text()};")
        for m in self.modules:
            ports = " ".join(f"{d} {p}: {type_text(t, self.aliases, self.spellings)};"
                             for d, p, t in m.ports)
            out.append(f"module {m.name} {{ {ports} }}")
        self.line_of = {}
        for d in self.decls:
            self.line_of[id(d)] = len(out) + 1
            out += d.lines()
        return "\n".join(out) + "\n"

    def port_type(self, ref):
        mod, port = ref.split(".")
        for m in self.modules:
            if m.name == mod:
                for _, p, t in m.ports:
                    if p == port:
                        return t
        return None

    def arbitrates(self):
        return [d for d in self.decls if isinstance(d, Arbitrate)]

    def decls_of(self, kind):
        return [d for d in self.decls if isinstance(d, Decl) and d.kind == kind]
