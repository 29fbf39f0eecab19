"""A run as its trace tells it (docs/runtime.md#trace-format), read for the claims: which
connection decided which message, and each port's event container at each decision.

Instants are exact: a trace time is the shortest decimal of a double, which for the inputs this
test writes is the decimal the inputs file wrote (what a user, a test and a counterexample
mean by "at 0.3 s"); a set's expiry is its time plus the lifetime the spec wrote, as a decimal,
not the double sum the runtime records (0.2 + 0.1 is 0.30000000000000004 there).
"""
import json
from decimal import Decimal

from .spec import VEC3, is_float
from .values import NONFINITE


def from_trace(v, t):
    """A value of type `t` as the trace writes it: numbers as Decimals, a float's NaN and
    infinities as "nan", "inf", "-inf" (a string field's "inf" stays a string)."""
    if t is None or v is None:
        return to_float(v)
    if is_float(t) or t == VEC3 and not isinstance(v, dict):
        return NONFINITE[v] if isinstance(v, str) and v in NONFINITE else to_float(v)
    if t == VEC3:
        return {k: from_trace(x, ("float",)) for k, x in v.items()}
    if t[0] == "list" and isinstance(v, list):
        return [from_trace(x, t[1]) for x in v]
    if t[0] == "record" and isinstance(v, dict):
        fields = dict(t[1])
        return {k: from_trace(x, fields.get(k)) for k, x in v.items()}
    return to_float(v)


def to_float(v):
    if isinstance(v, Decimal):
        return float(v)
    if isinstance(v, list):
        return [to_float(x) for x in v]
    if isinstance(v, dict):
        return {k: to_float(x) for k, x in v.items()}
    return v


class Container:
    """One port's entries: (event, owner) -> expiry (None: until unset)."""

    def __init__(self):
        self.entries = {}

    def apply(self, rec, lifetime_of):
        key = (rec["event"], rec["owner"])
        if rec["op"] == "set":
            self.entries[key] = None if "expiry" not in rec else rec["t"] + lifetime_of(rec)
        elif rec["op"] == "unset":
            self.entries.pop(key, None)
        # `expire` records come late (when the container is next read): presence is judged by
        # the expiry instants themselves.

    def present(self, t):
        return {e for (e, _), x in self.entries.items() if x is None or t < x}

    def present_owned(self, t, event):
        return [o for (e, o), x in self.entries.items() if e == event and (x is None or t < x)]


class Run:
    """Records in the order the runtime made them, each with an exact "t" (Decimal), and per
    decision (a `deliver` or `drop` record) the message it decided and the state it read."""

    def __init__(self, lines, model, durations, port_type=lambda port: None):
        self.port_type = port_type  # "M.p" -> its type (spec.py's tuples), for from_trace
        self.records = []
        for line in lines:
            if line.strip():
                rec = json.loads(line, parse_float=Decimal)
                rec["t"] = Decimal(rec["t"])
                self.records.append(rec)
        self.model = model
        self.durations = sorted(set(durations))
        self.snap_trig_instants()
        self.decisions = []  # dicts: index, conn, port, t, delivered, reason, msg, state, value
        self.publishes = {}  # port -> [values]
        self._walk()

    def snap_trig_instants(self):
        """A record an `every D` block made at no message's instant is at k * D exactly (the
        spec's instants; the runtime computes it as one double product)."""
        inputs = {r["t"] for r in self.records if r["type"] == "publish"}
        trig = {c["name"]: Decimal(repr(c["trig_interval"])) for c in self.model.json["connections"]
                if c.get("trig_interval")}
        for r in self.records:
            if r["type"] == "event" and r.get("owner") in trig and r["t"] not in inputs:
                d = trig[r["owner"]]
                r["t"] = (r["t"] / d).to_integral_value() * d

    def lifetime_of(self, rec):
        """The decimal lifetime behind a set's double expiry: the spec's duration closest to it."""
        lt = float(rec["expiry"]) - float(rec["t"])
        best = min(self.durations, key=lambda d: abs(float(d) - lt), default=None)
        if best is not None and abs(float(best) - lt) < 1e-6:
            return best
        # A lifetime the spec does not write (a script's setEvent): durations are at least a
        # microsecond and written with few digits, so the difference rounded to 1 ns is it.
        return Decimal(str(round(lt, 9)))

    def _walk(self):
        containers = {p: Container() for p in self.model.ports}
        seen = {}  # connection -> decisions so far (its k-th is the k-th publish on its source)
        for i, rec in enumerate(self.records):
            kind = rec["type"]
            if kind == "publish":
                self.publishes.setdefault(rec["port"], []).append(
                    from_trace(rec["value"], self.port_type(rec["port"])))
            elif kind == "publish-error":
                # A value its port's type does not hold (300 on an int8): no publish record,
                # a bad-type drop on each connection; a placeholder keeps the k-th decision of
                # a connection on the k-th message of its source.
                self.publishes.setdefault(rec["port"], []).append(None)
            elif kind == "event" and rec["port"] in containers:
                containers[rec["port"]].apply(rec, self.lifetime_of)
            elif kind in ("deliver", "drop"):
                conn = self.model.connections.get(rec["connection"])
                if conn is None:
                    continue
                k = seen.get(conn.name, 0)
                seen[conn.name] = k + 1
                port = conn.destination
                state = containers[port].present(rec["t"]) if port in containers else set()
                self.decisions.append({
                    "index": i, "conn": conn.name, "port": port, "t": rec["t"],
                    "delivered": kind == "deliver", "reason": rec.get("reason"),
                    "detail": rec.get("detail"), "msg": (conn.source, k), "state": state,
                    "value": from_trace(rec.get("value"), self.port_type(port)),
                    "raw_value": rec.get("value")})

    def message(self, msg):
        port, k = msg
        values = self.publishes.get(port, [])
        return values[k] if k < len(values) else None

    def message_type(self, msg):
        """The type of a message's source port (spec.py's tuples), None if unknown."""
        return self.port_type(msg[0])

    def port_records(self, port):
        """The deliveries, drops and event records of one port, in order."""
        conns = {c.name for c in self.model.connections.values() if c.destination == port}
        out = []
        for rec in self.records:
            if rec["type"] == "event" and rec.get("port") == port:
                out.append(rec)
            elif rec["type"] in ("deliver", "drop") and rec.get("connection") in conns and \
                    rec.get("reason") != "bad-type":  # a message the proof's model never has
                out.append(rec)
        return out
