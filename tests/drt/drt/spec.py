"""A structured spec (docs/language.md) that prints as spec text, so that the generator can
make one and the shrinker can take it apart.

Types are tuples: ("bool",), ("int",), ("float",), ("string",), ("vec3",), ("list", T),
("record", ((field, T), ...)). Expressions are `Expr` trees; every compound expression prints
in parentheses, so the printer never depends on operator precedence.
"""
from dataclasses import dataclass, field
from typing import List, Optional

BOOL, INT, FLOAT, STRING, VEC3 = ("bool",), ("int",), ("float",), ("string",), ("vec3",)


def list_of(t):
    return ("list", t)


def is_number(t):
    return t in (INT, FLOAT)


def type_text(t, aliases=None):
    """The spec text of a type; a record or list that has an alias prints as its name."""
    if aliases:
        for name, aliased in aliases.items():
            if aliased == t:
                return name
    if t[0] == "list":
        return f"list<{type_text(t[1], aliases)}>"
    if t[0] == "record":
        return "{ " + ", ".join(f"{f}: {type_text(ft, aliases)}" for f, ft in t[1]) + " }"
    return t[0]


def fits(value_type, expected):
    """Whether a value of `value_type` is accepted where `expected` is (an int is a float)."""
    if value_type == expected:
        return True
    if value_type == INT and expected == FLOAT:
        return True
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

    def lines(self):
        head = f"  {self.name}: from {self.source}"
        if self.when:
            head += f" when {self.when}"
        if self.hold:
            head += f" hold {self.hold}"
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

    def text(self):
        out = [f'app {self.app} "a random app of the differential test (tests/drt)";']
        for n, t in self.aliases.items():
            out.append(f"type {n} = {type_text(t)};")
        for n, e in self.consts:
            out.append(f"const {n} = {e.text()};")
        for m in self.modules:
            ports = " ".join(f"{d} {p}: {type_text(t, self.aliases)};" for d, p, t in m.ports)
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
