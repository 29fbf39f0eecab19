"""What `arbc verify --format json` claims (docs/verify-json.md), read into the claims that
claims.py judges runs by: proved ports (and their pairs exclusive by data), proved asserts (no
finding at the assert's line), proved resources (their pairs, by events or by data), and
properties over time that are proved or hold up to the bound."""
import re

from . import claims as C
from .spec import is_fixed

PAIR = re.compile(r"^'([^']+)' (?:\(into [^)]*\) )?and '([^']+)'(?: \(into [^)]*\))?"
                  r"(?: \((one message|two messages)\))?")
INT_EDGE = 2**62


# How the runtime checks write each kind of property (core/app_model.h temporal_property_text).
TEMPORAL_WORDS = {
    "spacing": lambda t: t.startswith("never two ") or " within " in t and t.startswith("never "),
    "absence": lambda t: t.startswith("never ") and " while " in t,
    "precedence": lambda t: t.startswith("only "),
    "response": lambda t: t.startswith("after "),
    "stability": lambda t: t.startswith("stable"),
}


UNITS = {"ns": 1e-9, "us": 1e-6, "µs": 1e-6, "ms": 1e-3, "s": 1.0, "min": 60.0, "h": 3600.0}


def same_window(p, claim):
    """Whether the property's window (JSON, seconds) is the one the claim's text writes: two
    spacings of one rule differ only by it."""
    if "window" not in p:
        return True
    m = re.search(r"within ([\d.e+-]+)(ns|us|µs|ms|s|min|h)\b", claim)
    return bool(m) and abs(float(m.group(1)) * UNITS[m.group(2)] - p["window"]) <= 1e-12 * max(
        1.0, p["window"])


class Claims:
    def __init__(self, report, spec, model, list_bound):
        self.model = model
        self.consts = const_env(spec)
        self.list_bound = list_bound
        inp = report["inputs"][0]
        self.ports, self.data_pairs, self.delivery_pairs = [], {}, {}
        found_lines = {}
        for p in inp.get("ports", []):
            for f in p.get("findings", []):
                if f.get("location"):
                    found_lines.setdefault(f["location"]["line"], []).append(f["check"])
            if not p["unknown_reason"] and not any(
                    f["check"] in ("exclusive", "unknown", "internal") for f in p.get("findings", [])):
                self.ports.append(p["port"])
                self.data_pairs[p["port"]] = [pair(s)[:2] for s in p.get("exclusive_by_data", [])
                                              if pair(s)]
                self.delivery_pairs[p["port"]] = [
                    pair(s)[:2] for s in p.get("exclusive_by_delivery", []) if pair(s)]
        known = {p["port"]: p for p in inp.get("ports", [])}
        # A verdict that says "for lists of at most N elements" claims nothing about longer
        # lists (issue 38 item 3 allows that, said in its first line): its breaches by a longer
        # list are counted as beyond the bound, not as disagreements.
        self.bounded = {p["port"] for p in inp.get("ports", []) if p.get("list_bound")}
        self.asserts = []
        for d in spec.decls:
            kind = getattr(d, "kind", None)
            if kind not in ("assert", "assert_data"):
                continue
            line = spec.line_of.get(id(d))
            port = known.get(d.info["port"])
            if port is None or port["unknown_reason"] or line in found_lines:
                continue
            self.asserts.append((d, f"{d.text} (line {line})"))
        self.resources = []
        specs = {d.info["name"]: d.info for d in spec.decls_of("resource")}
        for r in inp.get("resources", []):
            if r["verdict"] != "proved" or r["name"] not in specs:
                continue
            pairs = [pair(s)[:2] + ("events",) for s in r.get("exclusive_by_events", []) if pair(s)]
            pairs += [pair(s) for s in r.get("exclusive_by_data", []) if pair(s)]
            self.resources.append((specs[r["name"]], pairs, bool(r.get("list_bound"))))
        # A bounded verdict whose runs are all too short for its window to close at the rates
        # given (window_bound above bound: verify's temporal-bound warning, "the search shows
        # nothing about it") claims nothing.
        self.temporal = [t for t in inp.get("temporal", [])
                         if t["outcome"] == "proved" or t["outcome"] == "holds-up-to-bound" and
                         not (t.get("window_bound") or 0) > t["bound"]]
        for t in self.temporal:
            t["_rules"] = model.ports.get(t["port"], {}).get("rules", [])
        self.triggered = {c.destination for c in model.connections.values()
                          if model.json["connections"] and trig(model, c.name)}

    def needs(self, value, ty=None):
        """The data assumption of the report a message (of type `ty`, when known) breaks, if any
        (a label, not a filter)."""
        out = []
        walk(value, ty, self.list_bound, out)
        return "; ".join(sorted(set(out)))

    def beyond_bound(self, found, bounded, res):
        """The breaches a bounded verdict does not claim: each by a message with a longer list,
        whatever else the message has (an int near 2^63 beside it does not bring it back under
        the verdict's "for lists of at most N elements")."""
        if not bounded:
            return found
        kept = [b for b in found if "--list-bound" not in b.needs]
        res.beyond_bound += len(found) - len(kept)
        return kept

    def judge(self, run, end, res):
        m = self.model
        out = C.selection(run, m)
        for port in self.ports:
            pairs = {tuple(p) for p in self.data_pairs.get(port, [])}
            by_delivery = {tuple(p) for p in self.delivery_pairs.get(port, [])}
            found, outside = C.exclusive_by_events(run, m, port, pairs, by_delivery)
            out += found
            res.outside += outside
            out += self.beyond_bound(C.exclusive_by_data(run, pairs, port, self.needs),
                                     port in self.bounded, res)
        for d, what in self.asserts:
            if d.kind == "assert":
                found, outside = C.event_assert(run, m, d.info["port"], d.info["rule"],
                                                d.info["constraint"], what)
                res.outside += outside
            else:
                found, unjudged = C.data_assert(run, m, d.info["port"], d.info["rule"], d.info["pred"],
                                                what, self.needs, self.consts)
                res.unjudged += unjudged
            out += self.beyond_bound(found, d.info["port"] in self.bounded, res)
        for info, pairs, bounded in self.resources:
            out += self.beyond_bound(C.resource(run, m, info, pairs, self.needs, self.consts),
                                     bounded, res)
        out += self.judge_temporal(run, end, res)
        out += monitor_errors(run, m)
        return out

    def proved_claim(self, claim):
        """Whether the runtime checks' name of a claim (runtime/claim_watch.h) is one the report
        proved outright: a port's exclusivity, an assert over events, a property over time."""
        m = re.match(r"(\S+): rules .* are never selected together$", claim)
        if m:
            return m.group(1) in self.ports and m.group(1) not in self.bounded
        m = re.match(r"assert (\S+): (\S+) -> ", claim)
        if m:
            return any(d.kind == "assert" and d.info["port"] == m.group(1) and
                       d.info["rule"] == m.group(2) for d, _ in self.asserts)
        words = set(re.findall(r"[A-Za-z_][\w.]*", claim))
        for p in self.temporal:
            names = [n for n in (p.get("rule"), p.get("after"), p.get("event")) if n]
            if p["outcome"] == "proved" and names and all(n in words for n in names) and \
                    p["kind"] in TEMPORAL_WORDS and TEMPORAL_WORDS[p["kind"]](claim) and \
                    same_window(p, claim):
                return True
        return False

    def runtime_checks(self, out):
        """The second oracle: `arbc run` watches the claims itself (issue 39). A claim the report
        proved that the run's checks say broken, with no assumption of the proof broken in the
        run, is a disagreement between the proof and the runtime (or between the runtime checks
        and the run). Returns the breaches."""
        lines = out.split("runtime checks: ", 1)[1].splitlines()[1:] if "runtime checks: " in out \
            else []
        broken = []
        for line in lines:
            m = re.match(r"  (\S+)  (.*?): (.*)$", line)
            if not m:
                break
            broken.append((m.group(2), m.group(3)))
        if any(c.startswith("assumption ") for c, _ in broken):
            return []  # outside the premises: neither oracle judges the claims
        return [C.Breach("runtime-check", claim, "the run's own checks say: " + what)
                for claim, what in broken if self.proved_claim(claim)]

    def judge_temporal(self, run, end, res):
        out = []
        for p in self.temporal:
            if any(C.assumption_broken(run, p["port"], a) is not None for a in p.get("assumptions", [])):
                res.outside += 1
                continue
            if p["port"] in self.triggered and p["outcome"] != "proved":
                continue
            v = C.temporal(run, p, end)
            if v is None:
                continue
            steps, what = v
            if p["outcome"] == "proved" or steps <= p["bound"]:
                line = (p.get("location") or {}).get("line")
                out.append(C.Breach("temporal", f"{p['kind']} property at line {line}: "
                                    f"{p['outcome']} (bound {p['bound']})",
                                    f"violated after {steps} decisions into {p['port']}: {what}"))
        return out


def const_env(spec):
    """The spec's constants, evaluated in order as the constant folder does."""
    from .values import evaluate
    env = {}
    for n, e in spec.consts:
        try:
            env[n] = evaluate(e, env)
        except Exception:  # noqa: BLE001 - a constant with no value is left out
            pass
    return env


def pair(s):
    m = PAIR.match(s)
    return (m.group(1), m.group(2), m.group(3) or "events") if m else None


def trig(model, name):
    for c in model.json["connections"]:
        if c["name"] == name:
            return c.get("trig_interval") is not None
    return False


def walk(v, ty, bound, out):
    """The data assumptions value `v` of type `ty` (None: unknown) breaks. No list bound applies
    to a fixed list (T[N]): the proof encodes all N elements."""
    if isinstance(v, list):
        if len(v) > bound and not (ty and is_fixed(ty)):
            out.append(f"a list of {len(v)} elements (--list-bound {bound})")
        for x in v:
            walk(x, ty[1] if ty and ty[0] == "list" else None, bound, out)
    elif isinstance(v, dict):
        fields = dict(ty[1]) if ty and ty[0] == "record" else {}
        for k, x in v.items():
            walk(x, fields.get(k), bound, out)
    elif isinstance(v, bool):
        return
    elif isinstance(v, int) and abs(v) >= INT_EDGE:
        out.append("an int near 2^63 (64-bit overflow)")
    elif isinstance(v, float) and (abs(v) >= 1e300 or (v != 0 and abs(v) < 1e-300)):
        out.append("a float at the edge of the doubles (rounding, overflow to infinity)")


def monitor_errors(run, model):
    """A generated monitor never fails (docs/language.md#expressions: an expression with no
    value drops the message as `no-value`); only a hand-written `script` may raise."""
    out = []
    for d in run.decisions:
        if d["reason"] in ("monitor-error", "quarantined"):
            c = model.connections[d["conn"]]
            if not c.opaque:
                out.append(C.Breach("monitor-error", f"the generated monitor of '{c.name}'",
                                    f"{d['reason']} at {d['t']} s: {d['detail']} "
                                    f"(message {run.message(d['msg'])!r})"))
    return out
