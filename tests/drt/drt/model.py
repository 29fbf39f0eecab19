"""What `app.json` says of an app (docs/app-json.md) that the claims need: the arbitrated
ports, each connection's constraint and the events its monitor sets, and the effective guard
(docs/design.md#effective-guards), rebuilt here from those facts as core/effective_guard.h does.
"""
import json
import re


def parse_constraint(text):
    """A constraint's text (names, not, and, or, parentheses, true, false) as a tree."""
    tokens = re.findall(r"\(|\)|[A-Za-z_][A-Za-z_0-9]*", text)
    pos = [0]

    def peek():
        return tokens[pos[0]] if pos[0] < len(tokens) else None

    def take():
        pos[0] += 1
        return tokens[pos[0] - 1]

    def disj():
        args = [conj()]
        while peek() == "or":
            take()
            args.append(conj())
        return ("or", args) if len(args) > 1 else args[0]

    def conj():
        args = [unary()]
        while peek() == "and":
            take()
            args.append(unary())
        return ("and", args) if len(args) > 1 else args[0]

    def unary():
        t = take()
        if t == "not":
            return ("not", unary())
        if t == "(":
            e = disj()
            take()
            return e
        if t in ("true", "false"):
            return ("const", t == "true")
        return ("event", t)

    return disj() if tokens else ("const", True)


def holds(c, present):
    k = c[0]
    if k == "const":
        return c[1]
    if k == "event":
        return c[1] in present
    if k == "not":
        return not holds(c[1], present)
    if k == "and":
        return all(holds(a, present) for a in c[1])
    return any(holds(a, present) for a in c[1])


def events_of(c, out=None):
    out = set() if out is None else out
    if c[0] == "event":
        out.add(c[1])
    elif c[0] == "not":
        events_of(c[1], out)
    elif c[0] in ("and", "or"):
        for a in c[1]:
            events_of(a, out)
    return out


class Connection:
    def __init__(self, j):
        self.name = j["name"]
        self.source = j["source"]
        self.destination = j["destination"]
        self.kind = j["kind"]
        self.generated = j["generated"]
        self.constraint_text = j["constraint"]
        self.constraint = parse_constraint(j["constraint"])
        self.sets = set(j["sets"])
        self.unsets = set(j["unsets"])
        self.must_set = set(j["must_set"])
        self.must_unset = set(j["must_unset"])
        self.activity = j.get("activity_event") or ""
        # `then set` / `then unset` (docs/language.md#events-set-on-delivery)
        self.delivery_sets = set(j.get("delivery_sets", []))
        self.delivery_unsets = set(j.get("delivery_unsets", []))
        self.opaque = j.get("opaque", False)
        self.throttle = j.get("throttle")


class Model:
    def __init__(self, path):
        with open(path) as f:
            j = json.load(f)
        self.json = j
        self.connections = {c["name"]: Connection(c) for c in j["connections"]}
        self.ports = {p["port"]: p for p in j["arbitrated_ports"]}
        self.events = {e["name"]: e for e in j["events"]}
        self.exclusive_groups = [g["events"] if isinstance(g, dict) else g
                                 for g in j.get("exclusive_groups", [])]
        self.invariants = [parse_constraint(i["formula"] if isinstance(i, dict) else i)
                           for i in j.get("invariants", [])]

    def rules(self, port):
        return [self.connections[r] for r in self.ports[port]["rules"]]

    def into(self, port):
        return [c for c in self.connections.values() if c.destination == port]

    def effective_guard(self, rule, present):
        """E_c on a state: the constraint, the events the rule sets on every accepting path, not
        the ones it unsets on every such path that no other connection into the port can set
        (a `script` connection may set any), and its own activity event."""
        c = self.connections[rule]
        if not holds(c.constraint, present):
            return False
        if c.activity and c.activity not in present:
            return False
        if c.opaque:
            return True
        if not c.must_set <= present:
            return False
        others = [o for o in self.into(c.destination) if o.name != c.name]
        for e in c.must_unset:
            if e in present and not any(e in o.sets or o.opaque for o in others):
                return False
        return True

    def domain_holds(self, present):
        """The `exclusive` groups and `invariant`s the proof assumes, on one state."""
        for g in self.exclusive_groups:
            if sum(1 for e in g if e in present) > 1:
                return False
        return all(holds(i, present) for i in self.invariants)
