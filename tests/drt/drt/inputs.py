"""Random inputs for a run (`arbc run --inputs`, docs/testing.md#scripted-inputs---inputs):
messages on every source the app reads, with edge values (values.py) and edge timing: many
messages at one instant, and instants exactly at, a nanosecond before and half a nanosecond
after an earlier message plus one of the spec's durations (where a lifetime, a hold, a
throttle or a window ends). A source with a rate (`given M.p every D`) keeps it to the end.
"""
import re
from decimal import Decimal

from .values import ValueGen, to_json

NS = Decimal("1e-9")
OFFSETS = [Decimal(0), Decimal(0), -NS, NS / 2, -NS / 2, NS, Decimal("1e-6")]


def spec_durations(text):
    """Every duration the spec writes, in seconds (exact decimals)."""
    scale = {"ms": Decimal("0.001"), "s": Decimal(1), "min": Decimal(60)}
    return sorted({Decimal(n) * scale[u] for n, u in re.findall(r"\b(\d+(?:\.\d+)?)(ms|min|s)\b", text)})


def spec_numbers(text):
    return [float(n) for n in re.findall(r"(?<![\w.])(\d+\.\d+(?:e-?\d+)?|\d+e-?\d+|\d+)(?![\w.])", text)
            if len(n) < 25]


def exact_time(d):
    """The decimal a double reads back as (what the trace writes for it)."""
    return Decimal(repr(float(d)))


class InputGen:
    def __init__(self, rng, spec, sources, list_bound, avoid=()):
        """`sources`: port -> (type, flags or None); flags make a status port."""
        self.rng = rng
        self.avoid = set(avoid)
        self.spec = spec
        self.text = spec.text()
        self.sources = sources
        self.durations = spec_durations(self.text)
        strings = re.findall(r'"([a-z_0-9]*)"', self.text)
        self.values = ValueGen(rng, spec_numbers(self.text), strings, list_bound, self.avoid)
        self.rates = {d.info["source"]: spec_durations(d.text)[0] for d in spec.decls_of("given")}
        self.skipped = 0  # values with no JSON form

    def times(self, n):
        r = self.rng
        out = []
        t = Decimal(0)
        for _ in range(n):
            roll = r.random()
            if out and roll < 0.25:
                pass  # the same instant
            elif out and roll < 0.55 and self.durations:
                base = r.choice(out)
                offsets = OFFSETS[:2] if "nanosecond" in self.avoid else OFFSETS
                t = max(t, base + r.choice(self.durations) + r.choice(offsets))
            else:
                t = t + Decimal(r.choice([1, 5, 10, 25, 50, 100, 200, 250, 300, 500])) / 1000
            out.append(exact_time(t))
        return out

    def message(self, port, t):
        ty, flags = self.sources[port]
        v = self.values.status(flags) if flags is not None and self.rng.random() < 0.9 \
            else self.values.value(ty, flags or ())
        if contains_none(to_json_deep(v)):
            self.skipped += 1
            return None
        return {"t": t, "port": port, "value": v}

    def make(self):
        """(messages sorted by time (same instant: as drawn), the run's end)."""
        ports = list(self.sources)
        n = self.rng.randint(3, 30)
        msgs = []
        for t in self.times(n):
            m = self.message(self.rng.choice(ports), t)
            if m:
                msgs.append(m)
        end = (max((m["t"] for m in msgs), default=Decimal(0)) + Decimal("2"))
        for port, period in self.rates.items():
            if port in self.sources:
                msgs += self.rated(port, period, end)
        msgs.sort(key=lambda m: m["t"])
        return msgs, end

    def rated(self, port, period, end):
        """At least every `period` from 0 to `end`: the first by `period`, each next one at most
        `period` after the previous one."""
        out, last = [], Decimal(0)
        while last + period < end or not out:
            step = period * Decimal(self.rng.choice([1, 1, 2, 3, 4])) / 4
            last = exact_time(last + step)
            m = self.message(port, last)
            if m:
                out.append(m)
        return out


def to_json_deep(v):
    if isinstance(v, list):
        return [to_json_deep(x) for x in v]
    if isinstance(v, dict):
        return {k: to_json_deep(x) for k, x in v.items()}
    return to_json(v)


def contains_none(v):
    if v is None:
        return True
    if isinstance(v, list):
        return any(contains_none(x) for x in v)
    if isinstance(v, dict):
        return any(contains_none(x) for x in v.values())
    return False


def write_inputs(path, msgs):
    import json
    with open(path, "w") as f:
        for m in msgs:
            f.write('{"t": %s, "port": %s, "value": %s}\n' % (
                repr(float(m["t"])), json.dumps(m["port"]), json.dumps(to_json_deep(m["value"]), ensure_ascii=False)))
