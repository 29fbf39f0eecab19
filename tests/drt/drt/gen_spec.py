"""Random valid specs over the whole language (docs/language.md): modules and ports of every
type, events with lifetimes, `events from` feeds, derived events with and without `for`,
delivery events over an arbitrated port (read by its own rules or another port's),
arbitrated ports with and without `by priority`, `otherwise`, bodies (gen_body.py), `connect`,
`exclusive` / `invariant`, and the claims the proof makes (gen_claims.py). Sized numbers
(docs/language.md, "Sized numbers"; `--avoid sized` leaves them out) as ports, record fields and
list elements, each spelled as the spec chooses (`byte`, `int64`). Lists and strings with
sizes (docs/language.md, "Lists and strings with sizes"; `--avoid sized-lists` leaves them out):
`T[N]`, `list<T, N>` and `string<N>` as ports, record fields and list elements."""
from .spec import (BOOL, INT, FLOAT, STRING, VEC3, U64, F32, SIZED, SPELLINGS, list_of, Spec,
                   Module, Decl, Arbitrate, Rule, Connect, Stmt, Expr, lit, name, fits, has_sized,
                   fixed_of, bounded_of, string_of, Consts, has_size)
from .gen_body import BodyGen, DURATIONS, script_lua, guarded_emit
from .gen_claims import add_claims

SIMPLE = [INT, FLOAT, BOOL, STRING, VEC3]


class SpecGen:
    def __init__(self, rng, index, avoid=()):
        self.rng = rng
        self.avoid = set(avoid)
        self.index = index
        self.counter = {}
        self.spec = Spec(app=f"drt{index}")
        self.consts = Consts()  # name -> type (and the bytes of the string ones)
        self.sources = []     # out ports rules read: "M.p"
        self.dests = []       # in ports: "M.p"
        self.statuses = {}    # status port -> {event: flag}
        self.fed = []         # events from feeds and derived events
        self.declared = []    # events monitors own (`event e;`)
        self.lifetimes = set()
        self.rated = set()

    def chance(self, p):
        return self.rng.random() < p

    def make(self):
        r = self.rng
        self.make_types()
        self.make_consts()
        self.make_modules()
        self.make_events()
        ports = r.sample(self.dests, r.randint(1, min(3, len(self.dests))))
        rest = [d for d in self.dests if d not in ports]
        self.make_delivery_events(ports)
        for p in ports:
            self.spec.decls.append(self.arbitrate(p))
        for d in rest:
            if self.chance(0.5):
                self.spec.decls.append(self.connect(d))
        self.domain()
        add_claims(self)
        return self.spec

    def make_types(self):
        r = self.rng
        sized = self.sized_types()
        with_sizes = "sized-lists" not in self.avoid and self.chance(0.35)
        self.types = list(SIMPLE) + sized
        pool = SIMPLE + [list_of(FLOAT)] + sized * 2
        if with_sizes:
            pool += [fixed_of(FLOAT, 3), fixed_of(INT, 6), bounded_of(INT, 2),
                     string_of(r.choice([1, 4, 8]))]
        records = []
        for i in range(r.randint(0, 2)):
            fields = [(f"f{j}", r.choice(pool)) for j in range(r.randint(1, 3))]
            rec = ("record", tuple(fields))
            if self.chance(0.6):
                self.spec.aliases[f"R{i + 1}"] = rec
            self.types.append(rec)
            records.append(rec)
            if self.chance(0.5):
                self.types.append(list_of(rec))
        if self.chance(0.5):
            self.types.append(list_of(self.rng.choice([INT, FLOAT, STRING, VEC3] + sized)))
        if with_sizes:
            self.types += self.sized_lists(sized, records)

    def sized_lists(self, sized, records):
        """One to three types with sizes: T[N] (N often past --list-bound's 4, which does not
        apply to it), list<T, N> (N below and above it) and string<N>, of numbers, strings,
        vec3s and the spec's records (`{ d: float }[6]`)."""
        r = self.rng
        elements = [FLOAT, INT, STRING, VEC3, string_of(4)] + sized + records * 2
        out = []
        for _ in range(r.randint(1, 3)):
            kind = r.choice(["fixed", "fixed", "bounded", "string"])
            if kind == "fixed":
                out.append(fixed_of(r.choice(elements), r.choice([1, 2, 3, 5, 6, 6, 8])))
            elif kind == "bounded":
                out.append(bounded_of(r.choice(elements), r.choice([1, 2, 4, 6])))
            else:
                out.append(string_of(r.choice([1, 2, 4, 8, 16])))
        return out

    def sized_types(self):
        """The sized number types of this spec (uint64 and float32, the ones with their own
        rules, drawn more often; `--avoid uint64` leaves uint64 out), and how it spells int,
        float and uint8."""
        r = self.rng
        if "sized" in self.avoid or not self.chance(0.7):
            return []
        self.spec.spellings = {k: r.choice(v) for k, v in SPELLINGS.items() if r.random() < 0.5}
        pool = [t for t in SIZED + [U64, U64, F32] if t != U64 or "uint64" not in self.avoid]
        return r.sample(pool, r.randint(1, 3))

    def make_consts(self):
        for i in range(self.rng.randint(0, 3)):
            n = f"K{i + 1}"
            kind = self.rng.choice([INT, FLOAT, STRING, "duration"])
            if kind == "duration":
                e = lit(FLOAT, self.rng.choice(DURATIONS))
                self.durations_extra = getattr(self, "durations_extra", []) + [n]
                kind = FLOAT
            elif kind == INT:
                big = [] if "int-literal-edge" in self.avoid else ["9223372036854775806"]
                e = Expr("bin", INT, [lit(INT, self.rng.choice(["2"] + big)),
                                      lit(INT, "1")], "+")
            elif kind == FLOAT:
                e = lit(FLOAT, self.rng.choice(["0.5", "0.1"] + ([] if "rounding" in self.avoid else
                                                                ["1e308", "0.3333333333333333"])))
            else:
                e = lit(STRING, self.rng.choice(['"take"', '""', '"é"']))
                self.consts.string_bytes[n] = len(e.val[1:-1].encode())
            self.spec.consts.append((n, e))
            self.consts[n] = kind

    def make_modules(self):
        r = self.rng
        n_src = r.randint(1, 4)
        for i in range(n_src):
            ports = []
            for j in range(r.randint(1, 2)):
                t = r.choice(self.types)
                ports.append(("out", f"p{i + 1}{j + 1}", t))
                self.sources.append(f"S{i + 1}.p{i + 1}{j + 1}")
            self.spec.modules.append(Module(f"S{i + 1}", ports))
        for i in range(r.randint(0, 2)):
            self.spec.modules.append(Module(f"St{i + 1}", [("out", f"s{i + 1}", list_of(STRING))]))
            self.statuses[f"St{i + 1}.s{i + 1}"] = {}
        src_types = [self.spec.port_type(s) for s in self.sources]
        for i in range(r.randint(1, 4)):
            t = r.choice(src_types) if self.chance(0.7) else r.choice(self.types)
            self.spec.modules.append(Module(f"D{i + 1}", [("in", f"q{i + 1}", t)]))
            self.dests.append(f"D{i + 1}.q{i + 1}")

    def make_events(self):
        r = self.rng
        k = 0
        for port, flags in self.statuses.items():
            entries = []
            for _ in range(r.randint(1, 3)):
                k += 1
                e = f"f{k}"
                flag = e if self.chance(0.6) else f"flag{k}"
                flags[e] = flag
                entries.append(e if flag == e else f'{e} = "{flag}"')
                self.fed.append(e)
            life = r.choice(["", "200ms", "0.5s", "1s"])
            self.lifetimes.add(life)
            self.spec.decls.append(Decl("feed", f"events from {port} {{ {', '.join(entries)} }}" +
                                        (f" lifetime {life}" if life else "") + ";",
                                        {"port": port, "flags": dict(flags), "lifetime": life}))
        for i in range(r.randint(0, 2)):
            src = r.choice(self.sources)
            msg = src.split(".")[1]
            pred = BodyGen(r, self.consts, self.counter, self.avoid).exprs.gen(
                BOOL, {msg: self.spec.port_type(src)}, 3, pure=True)
            life = r.choice(["", "", "100ms", "300ms", "1s"])
            n = f"d{i + 1}"
            self.fed.append(n)
            self.spec.decls.append(Decl("derived", f"event {n} = {src} : {pred.text()}" +
                                        (f" for {life}" if life else "") + ";",
                                        {"event": n, "source": src, "pred": pred, "for": life}))
        names = [f"e{i + 1}" for i in range(r.randint(0, 3))]
        if names:
            life = r.choice(["", "", "300ms", "1s"])
            self.declared = names
            self.spec.decls.append(Decl("event", f"event {', '.join(names)}" +
                                        (f" lifetime {life}" if life else "") + ";",
                                        {"events": names, "lifetime": life}))

    def make_delivery_events(self, ports):
        """`event e = M.p : PRED [for D];` over an arbitrated port (docs/language.md#delivery-events):
        the runtime sets it at each delivery into M.p; the guards may read it in M.p itself
        (the model checker then models it exactly) or in another port."""
        if "delivery-event" in self.avoid:
            return
        for i in range(self.rng.randint(0, 2)):
            port = self.rng.choice(ports)
            msg = port.split(".")[1]
            pred = BodyGen(self.rng, self.consts, self.counter, self.avoid).exprs.gen(
                BOOL, {msg: self.spec.port_type(port)}, 3, pure=True)
            life = self.rng.choice(["", "", "100ms", "300ms", "1s"])
            n = f"o{i + 1}"
            self.fed.append(n)
            self.spec.decls.append(Decl("derived", f"event {n} = {port} : {pred.text()}" +
                                        (f" for {life}" if life else "") + ";",
                                        {"event": n, "source": port, "pred": pred, "for": life}))

    def arbitrate(self, port):
        r = self.rng
        dst = self.spec.port_type(port)
        pair = self.data_pair(port) if "sized" not in self.avoid and self.chance(0.15) else None
        if pair is None and "sized-lists" not in self.avoid and self.chance(0.2):
            pair = self.data_pair(port, sizes=True)
        if pair:
            return pair
        by_priority = self.chance(0.4)
        a = Arbitrate(port, by_priority, complete=self.chance(0.1))
        n_rules = r.randint(1, 4)
        bodies = BodyGen(r, self.consts, self.counter, self.avoid)
        owned = set()
        for i in range(n_rules):
            self.counter["r"] = self.counter.get("r", 0) + 1
            rule = Rule(f"r{self.counter['r']}", self.source_for(dst))
            src_type = self.spec.port_type(rule.source)
            msg = rule.source.split(".")[1]
            roll = r.random()
            guarded = guarded_emit(r, msg, src_type, dst) if roll < 0.15 and "rounding" not in self.avoid \
                else None
            if guarded:
                rule.body = guarded[0]
                rule.pred = guarded[1]
            elif roll < 0.2 and src_type == dst:
                rule.body = [Stmt("script", self.script(src_type))]
                owned |= set(self.declared)
            elif roll < 0.3 and src_type == dst:
                rule.body = None
            else:
                rule.body, sets = bodies.body(msg, src_type, dst, self.declared, must_emit=src_type != dst)
                owned |= sets
            if by_priority and i < n_rules - 1:
                rule.hold = r.choice(DURATIONS[1:] + getattr(self, "durations_extra", []))
            a.rules.append(rule)
        owners = self.ownership(a)
        owned |= self.delivery_effects(a) if not owners else set()
        self.guards(a, sorted(owned))
        for rule, event in owners:  # each rule is kept out while another owns the port
            others = [f"not {e}" for other, e in owners if other is not rule]
            if rule.when != "otherwise":
                rule.when = " and ".join(([f"({rule.when})"] if rule.when else []) + others)
        return a

    def ownership(self, a):
        """The pattern `then set` exists for (docs/language.md#events-set-on-delivery): each rule
        sets an event of its own as it delivers, and the others read `not` it, so the port is
        owned by whichever delivered last; verify proves such pairs exclusive by delivery."""
        if "on-delivery" in self.avoid or len(a.rules) < 2 or a.by_priority or \
                not self.chance(0.25):
            return []
        out = []
        for rule in a.rules:
            self.counter["own"] = self.counter.get("own", 0) + 1
            name = f"own{self.counter['own']}"
            life = self.rng.choice(["", "100ms", "300ms", "1s"])
            self.spec.decls.append(Decl("event", f"event {name}" +
                                        (f" lifetime {life}" if life else "") + ";",
                                        {"events": [name], "lifetime": life}))
            rule.effects.append(("set", name))
            out.append((rule, name))
        if self.chance(0.5):  # one rule also gives the port back
            giver = self.rng.choice(a.rules)
            giver.effects += [("unset", e) for other, e in out if other is not giver]
        return out

    def delivery_effects(self, a):
        """`then set d` / `then unset d` on some rules (docs/language.md#events-set-on-delivery),
        over events of this port alone, which no body sets: the port's guards may read them
        (verify proves pairs whose deliveries keep each other out: verify/delivery_order.h)."""
        r = self.rng
        if "on-delivery" in self.avoid or not self.chance(0.3):
            return set()
        own = []
        for _ in range(r.randint(1, 2)):
            self.counter["own"] = self.counter.get("own", 0) + 1
            name = f"own{self.counter['own']}"
            life = r.choice(["", "100ms", "300ms", "1s"])
            own.append(name)
            self.spec.decls.append(Decl("event", f"event {name}" +
                                        (f" lifetime {life}" if life else "") + ";",
                                        {"events": [name], "lifetime": life}))
        for rule in a.rules:
            for e in own:
                roll = r.random()
                if roll < 0.45:
                    rule.effects.append(("set", e))
                elif roll < 0.6:
                    rule.effects.append(("unset", e))
        set_somewhere = {e for rule in a.rules for op, e in rule.effects if op == "set"}
        for rule in a.rules:  # a `then unset` needs a `then set` of the event in the port
            rule.effects = [(op, e) for op, e in rule.effects if op == "set" or e in set_somewhere]
        return set_somewhere

    def data_pair(self, port, sizes=False):
        """A port of two rules of one source that only their data can keep apart: no `when`,
        and accepts comparing one sized number of the message with an edge of its type, the
        second rule the opposite or an overlapping comparison (`m.level > 126` and
        `m.level < 127` of an int8; a uint64 compared unsigned): the proof's exclusive_by_data
        pairs, which a message both rules accept breaks. With `sizes`, comparing the length of
        a list or string with a size, or an element at the end of a T[N] (ExprGen.size_pair)."""
        has = has_size if sizes else has_sized
        srcs = [s for s in self.sources if has(self.spec.port_type(s))]
        if not srcs:
            return None
        src = self.rng.choice(srcs)
        src_type, dst = self.spec.port_type(src), self.spec.port_type(port)
        msg = src.split(".")[1]
        bodies = BodyGen(self.rng, self.consts, self.counter, self.avoid)
        accepts = (bodies.exprs.size_pair if sizes else bodies.exprs.edge_pair)({msg: src_type})
        if accepts is None:
            return None
        a = Arbitrate(port)
        for cond in accepts:
            self.counter["r"] = self.counter.get("r", 0) + 1
            body = []
            if src_type != dst or self.chance(0.3):
                body, _ = bodies.body(msg, src_type, dst, [], must_emit=src_type != dst)
            a.rules.append(Rule(f"r{self.counter['r']}", src, body=[Stmt("accept", expr=cond)] + body))
        return a

    def source_for(self, dst):
        same = [s for s in self.sources if fits(self.spec.port_type(s), dst)]
        if same and self.chance(0.6):
            return self.rng.choice(same)
        return self.rng.choice(self.sources)

    def script(self, msg_type):
        n = f"script{len(self.spec.scripts) + 1}.lua"
        self.spec.scripts[n] = script_lua(self.rng, msg_type, self.declared)
        return n

    def guards(self, a, owned):
        """`when`s over the events the port can see (fed ones, and those its own rules set):
        often a partition (exclusive by construction), sometimes random, sometimes `otherwise`."""
        r = self.rng
        events = self.fed + owned
        if not events:
            return
        n = len(a.rules)
        if self.chance(0.6) or a.by_priority:
            split = r.sample(events, min(len(events), 2))
            cubes = partition(split, n)
            for rule, cube in zip(a.rules, cubes):
                extra = [lit_of(r, e) for e in events if e not in split and self.chance(0.2)]
                rule.when = " and ".join(cube + extra) or None
        else:
            for rule in a.rules:
                if self.chance(0.8):
                    rule.when = random_constraint(r, events, 2)
        if n > 1 and self.chance(0.2) and not a.by_priority:
            r.choice(a.rules).when = "otherwise"

    def connect(self, dest):
        src = self.source_for(self.spec.port_type(dest))
        body = None
        src_type, dst = self.spec.port_type(src), self.spec.port_type(dest)
        if src_type != dst or self.chance(0.5):
            body, _ = BodyGen(self.rng, self.consts, self.counter, self.avoid).body(
                src.split(".")[1], src_type, dst, [], must_emit=src_type != dst, in_rule=True)
        return Connect(src, dest, body)

    def domain(self):
        """`exclusive` groups and `invariant`s: domain knowledge the proof assumes."""
        events = self.fed + self.declared
        if len(events) >= 2 and self.chance(0.2):
            group = self.rng.sample(events, 2)
            self.spec.decls.append(Decl("exclusive", f"exclusive {{ {', '.join(group)} }};",
                                        {"events": group}))
        if events and self.chance(0.15):
            c = random_constraint(self.rng, events, 2)
            self.spec.decls.append(Decl("invariant", f"invariant {c};", {"constraint": c}))


def lit_of(rng, e):
    return e if rng.random() < 0.5 else f"not {e}"


def partition(split, n):
    """n cubes over the events of `split` that no state satisfies two of."""
    cubes = [[]]
    for e in split:
        if len(cubes) >= n:
            break
        cubes = [c + [e] for c in cubes] + [c + [f"not {e}"] for c in cubes]
    cubes = cubes[:n]
    return cubes + [["false"]] * (n - len(cubes)) if len(cubes) < n else cubes


def random_constraint(rng, events, depth):
    if depth == 0 or rng.random() < 0.4:
        return lit_of(rng, rng.choice(events))
    op = rng.choice(["and", "or", "and"])
    return f"({random_constraint(rng, events, depth - 1)} {op} {random_constraint(rng, events, depth - 1)})"
