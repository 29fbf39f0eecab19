"""The claims of a random spec: asserts over events and over data, resources across ports,
properties over time of every shape (docs/language.md#properties-over-time) with rates
(`given`) and environment assumptions (`assume`)."""
from .spec import BOOL, Decl, name
from .gen_expr import ExprGen

WINDOWS = ["1ms", "100ms", "200ms", "250ms", "300ms", "0.5s", "1s", "1.5s"]


def add_claims(g):
    ports = g.spec.arbitrates()
    for a in ports:
        port_events = events_read(a)
        for rule in a.rules:
            if g.chance(0.25):
                g.spec.decls.append(event_assert(g, a, rule, port_events))
            if rule.pred is not None or g.chance(0.12):
                g.spec.decls.append(data_assert(g, a, rule))
        for _ in range(g.rng.randint(0, 3)):
            d = temporal(g, a, port_events)
            if d:
                g.spec.decls.append(d)
    resources(g, ports)


def events_read(a):
    out = []
    for r in a.rules:
        if r.when and r.when != "otherwise":
            for word in r.when.replace("(", " ").replace(")", " ").split():
                if word not in ("and", "or", "not", "true", "false") and word not in out:
                    out.append(word)
    return out


def event_assert(g, a, rule, events):
    r = g.rng
    lits = [w for w in (rule.when or "").split(" and ") if w and "(" not in w and ")" not in w and w != "otherwise"]
    if lits and r.random() < 0.6:
        c = r.choice(lits)
    elif events:
        c = r.choice(events) if r.random() < 0.5 else f"not {r.choice(events)}"
    else:
        c = "true"
    return Decl("assert", f"assert {a.port}: {rule.name} -> {c};",
                {"port": a.port, "rule": rule.name, "constraint": c})


def data_assert(g, a, rule):
    ty = g.spec.port_type(a.port)
    pred = rule.pred
    if pred is None or g.chance(0.2):
        pred = ExprGen(g.rng, g.consts, g.avoid).gen(BOOL, {"emitted": ty}, 3, pure=True)
        if "emitted" not in pred.text():
            pred = ExprGen(g.rng, g.consts, g.avoid).gen(BOOL, {"emitted": ty}, 2, pure=True)
    if "emitted" not in pred.text() or ("assert-data-string" in g.avoid and '"' in pred.text()):
        pred = type(pred)("bin", BOOL, [name(ty, "emitted"), name(ty, "emitted")], "==")
    return Decl("assert_data", f"assert {a.port}: {rule.name} -> {pred.text()};",
                {"port": a.port, "rule": rule.name, "pred": pred})


def temporal(g, a, events):
    r = g.rng
    sources = [x.source for x in a.rules]
    derived = {d.info["event"]: d.info["source"] for d in g.spec.decls_of("derived")}
    sources += [derived[e] for e in events if e in derived]
    if "shared-source-temporal" in g.avoid and len(set(sources)) < len(sources):
        return None  # a message that goes to a rule and another connection of the port
    if "temporal-every" in g.avoid and body_has(a, lambda s: s.kind == "every"):
        return None
    if "temporal-set-for" in g.avoid and body_has(a, lambda s: s.kind == "set" and s.duration):
        return None
    rules = [x.name for x in a.rules]
    rule = r.choice(rules)
    others = [x for x in rules if x != rule]
    acts = [f"act_{x.name}" for x in a.rules if x.hold]
    shape = r.choice(["spacing", "spacing", "absence", "precedence", "response", "response",
                      "stability", "assume", "given", "spacing_after"])
    w = r.choice(WINDOWS + getattr(g, "durations_extra", []))
    if shape == "spacing":
        return Decl("temporal", f"never two {rule} within {w};")
    if shape == "spacing_after" and others:
        return Decl("temporal", f"never {rule} within {w} after {r.choice(others)};")
    if shape == "absence" and (events or acts):
        return Decl("temporal", f"never {rule} while {r.choice(events + acts)};")
    if shape == "precedence" and others:
        return Decl("temporal", f"only {rule} after {r.choice(others)};")
    if shape == "stability":
        return Decl("temporal", f"stable {a.port} for {w};")
    if shape == "response":
        return response(g, a, rule, others, events, acts, w)
    if shape == "given":
        src = r.choice([x.source for x in a.rules])
        if src in g.rated:
            return None
        g.rated.add(src)
        return Decl("given", f"given {src} every {r.choice(['50ms', '100ms', '200ms', '0.5s'])};",
                    {"source": src})
    if shape == "assume":
        return assume(g, a, rules)
    return None


def body_has(a, test):
    """Whether a statement of a rule of port `a` (nested ones included) passes `test`."""
    def walk(stmts):
        return any(test(s) or any(walk(b) for _, b in s.branches) for s in stmts)
    return any(walk(r.body or []) for r in a.rules)


def response(g, a, rule, others, events, acts, w):
    r = g.rng
    if others and (r.random() < 0.6 or "response-event" in g.avoid):
        trigger = r.choice(others) + (" stops" if r.random() < 0.4 else "")
    elif "response-event" in g.avoid:
        return None
    elif events or acts:
        trigger = r.choice(events + acts)
    else:
        return None
    answer = a.port if r.random() < 0.3 else rule
    cond = ""
    if events and r.random() < 0.4:
        cond = " while " + r.choice(events) + (f" and not {r.choice(events)}" if r.random() < 0.3 else "")
    return Decl("temporal", f"after {trigger}, {answer} within {w}{cond};")


def assume(g, a, rules):
    """About an event the environment reports (a status flag or a derived event) and two rules
    of the port (docs/language.md#environment-assumptions)."""
    r = g.rng
    fed = [e for e in g.fed if e in events_read(a)]
    if not fed or len(rules) < 2:
        return None
    e = r.choice(fed)
    after, until = r.sample(rules, 2)
    if r.random() < 0.5:
        text = f"assume not {e} for {r.choice(WINDOWS[1:])} after {after};"
    else:
        text = f"assume {e} only after {after}" + (f" until {until}" if r.random() < 0.6 else "") + ";"
    return Decl("assume", text, {"event": e})


def resources(g, ports):
    by_type = {}
    for a in ports:
        by_type.setdefault(repr(g.spec.port_type(a.port)), []).append(a.port)
    k = 0
    for group in by_type.values():
        if len(group) < 2 or not g.chance(0.7):
            continue
        k += 1
        ty = g.spec.port_type(group[0])
        pred = None
        if g.chance(0.5):
            pred = ExprGen(g.rng, g.consts, g.avoid).gen(BOOL, {"emitted": ty}, 2, pure=True)
            if "emitted" not in pred.text():
                pred = None
        text = f"resource res{k} {{ {', '.join(group)} }}" + (f" when {pred.text()}" if pred else "") + ";"
        g.spec.decls.append(Decl("resource", text, {"name": f"res{k}", "ports": group, "when": pred}))
