"""What each claim of `arbc verify` means for one run: the one definition the differential test
judges runs by (and that runtime checks, issue 39, can take over). Each function takes the run
(trace.Run: decisions in the order the runtime made them, each with the decision state of its
port) and what the report claims, and returns the breaches as `Breach` values.

Common ground, for every claim:
- An instant is exact: the decimal the inputs wrote, durations as the spec wrote them
  (docs/design.md#events-and-lifetimes: "the proof reads every duration as the decimal the
  spec wrote"). A window of D is broken by two instants less than D apart, exactly; an entry
  set at t for D is present at t' iff t' < t + D. The runtime's 1 ns "same instant" rule is not
  part of any claim: where it makes the runtime differ, the run is judged as written.
- The decision state of a message on connection c into port P is P's container after c's
  `accept` ran (docs/design.md#the-message-path, step 2): the `set`/`unset` records before c's
  deliver or drop record, with entries lapsing at their exact expiry.
- A record an `every D` block makes (a trig, at no message's instant) is at k * D exactly.
- A message is identified by its source port and its index among that port's publications:
  the k-th decision of a connection is about the k-th message its source published.
- A run that breaks a claim's premises (an `exclusive` group or `invariant` false in the state,
  an environment assumption (`assume`) false at a decision into the port, a rate (`given`)
  not kept) is not judged for that claim: such decisions are counted as outside assumptions.
  The data assumptions the report prints (lists of at most --list-bound elements, finite
  floats, no 64-bit overflow) are NOT premises: issue 38 requires that the runtime enforce
  them or that the verdict say "up to N"; a breach that needs one is still a breach, labelled
  with the assumption it needs (`Breach.needs`). The one exception: a verdict that says "for
  lists of at most N elements" (list_bound in the JSON) claims nothing about longer lists, so
  report_claims.py counts a breach by a message with a longer list as beyond the bound.
"""
from dataclasses import dataclass

from .model import holds
from .values import NoValue, evaluate

ACCEPTED = ("not-selected", "throttled")  # drop reasons of a message the body accepted


@dataclass
class Breach:
    claim: str    # exclusive-events, exclusive-data, selection, assert, assert-data, resource,
                  # temporal, replay, crash, internal, timeout, monitor-error
    what: str     # the claim in words (its spec line when it has one)
    detail: str   # what the run did
    needs: str = ""  # a data assumption the breach relies on, if any

    def signature(self):
        """What makes two breaches the same disagreement, for the shrinker: the claim, and for
        a process-level one (internal error, crash, refused replay) its message with names,
        numbers and paths left out."""
        if self.claim in ("internal", "crash", "replay", "timeout"):
            import re
            text = re.sub(r"'[^']*'|`[^`]*`|\"[^\"]*\"|/\S+|\b[\w.]+\.(spec|lua)\b|[\d.]+", "_",
                          self.detail)
            return self.claim + ":" + text[text.find("error") if "error" in text else 0:][:70]
        if self.claim == "temporal":
            return self.claim + ":" + self.what.split(" property")[0]
        return self.claim


def with_act(d, model):
    c = model.connections[d["conn"]]
    return d["state"] | ({c.activity} if c.activity else set())


def selection(run, model):
    """Selection (docs/design.md#the-message-path, step 2): a rule delivers only when its
    constraint holds on the decision state, and a rule dropped `not-selected` only when it does
    not. Every claim below assumes it; it holds to the nanosecond, since the runtime's instants
    are whole nanoseconds compared exactly (core/instant.h)."""
    out = []
    for d in run.decisions:
        c = model.connections[d["conn"]]
        if c.kind != "rule" or d["port"] not in model.ports:
            continue
        if d["delivered"] or d["reason"] == "throttled":
            want = True
        elif d["reason"] == "not-selected":
            want = False
        else:
            continue
        if holds(c.constraint, d["state"]) != want:
            out.append(Breach("selection", f"the constraint of '{c.name}' ({c.constraint_text})",
                              f"{d['reason'] or 'delivered'} at {d['t']} s with events "
                              f"{sorted(d['state'])}"))
    return out


def exclusive_by_events(run, model, port, data_pairs=(), delivery_pairs=()):
    """A port whose report has no `exclusive`, `unknown` or `internal` finding (docs/checks.md:
    "no decision state selects two rules"; other errors, such as a refuted assert or `unfed`,
    leave that claim standing), except pairs exclusive by data (below): at every delivery
    of a rule r, the decision state with r's activity event added (set in the same step,
    docs/design.md#priorities-and-holds) satisfies no other rule's effective guard. Two
    deliveries from one event state of a `by priority` port, a higher rule's after a lower one's
    at one instant (issue 38 item 5), do not break it: the lower rule's guard reads `not act_h`.
    A pair exclusive by delivery (`then set`, verify/delivery_order.h) is judged in the state
    the delivery leaves: r's `then set` events present, its `then unset` ones absent."""
    out, outside = [], 0
    for d in run.decisions:
        if d["port"] != port or not d["delivered"]:
            continue
        state = with_act(d, model)
        if not model.domain_holds(state):
            outside += 1
            continue
        if not model.effective_guard(d["conn"], state):
            continue  # a selection breach, reported by selection()
        c = model.connections[d["conn"]]
        after = (state - c.delivery_unsets) | c.delivery_sets

        def selected(other):
            by_delivery = (d["conn"], other) in delivery_pairs or (other, d["conn"]) in delivery_pairs
            return model.effective_guard(other, after if by_delivery else state)
        both = [r.name for r in model.rules(port)
                if r.name != d["conn"] and selected(r.name)
                and (d["conn"], r.name) not in data_pairs and (r.name, d["conn"]) not in data_pairs]
        if both:
            out.append(Breach("exclusive-events", f"{port}: rules never selected together",
                              f"'{d['conn']}' delivered at {d['t']} s in state {sorted(state)}, "
                              f"which also satisfies the effective guard of {both}"))
    return out, outside


def accepted(d):
    return d["delivered"] or d["reason"] in ACCEPTED


def exclusive_by_data(run, pairs, port, needs_of):
    """A pair of rules of one source that the report calls exclusive by data ("no message passes
    both", docs/checks.md#message-data): no message of that source is accepted by both (each
    delivered it, or dropped it after its accept: `not-selected`, `throttled`)."""
    out = []
    by_msg = {}
    for d in run.decisions:
        if d["port"] == port and accepted(d):
            by_msg.setdefault(d["msg"], set()).add(d["conn"])
    for a, b in pairs:
        for msg, conns in by_msg.items():
            if a in conns and b in conns:
                v = run.message(msg)
                out.append(Breach("exclusive-data", f"{port}: '{a}' and '{b}' exclusive by data",
                                  f"both accepted message {msg[1]} of {msg[0]}: {v!r}",
                                  needs_of(v, run.message_type(msg))))
    return out


def event_assert(run, model, port, rule, constraint, what):
    """`assert M.p: RULE -> C;` (docs/language.md): at every delivery of RULE into M.p, C holds
    on the decision state with RULE's activity event added (the state the proof's h_r reads)."""
    from .model import parse_constraint, holds
    c = parse_constraint(constraint)
    out, outside = [], 0
    for d in run.decisions:
        if d["port"] != port or d["conn"] != rule or not d["delivered"]:
            continue
        state = with_act(d, model)
        if not model.domain_holds(state):
            outside += 1
        elif model.effective_guard(rule, state) and not holds(c, state):
            out.append(Breach("assert", what, f"'{rule}' delivered at {d['t']} s with events "
                              f"{sorted(state)}"))
    return out, outside


def data_assert(run, model, port, rule, pred, what, needs_of, consts):
    """`assert M.p: RULE -> P(emitted);` (docs/checks.md#assert-over-data): every value RULE
    delivers makes P true (a P that reads a value that does not exist is false). A delivered
    value the trace cannot write (NaN, an infinity: `null`) is not judged (counted)."""
    out, unjudged = [], 0
    for d in run.decisions:
        if d["port"] != port or d["conn"] != rule or not d["delivered"]:
            continue
        if has_null(d["value"]):
            unjudged += 1
            continue
        if not model.domain_holds(with_act(d, model)):
            continue  # the rule is selected only outside the domain the proof assumes
        try:
            ok = evaluate(pred, {**consts, "emitted": d["value"]}) is True
        except (NoValue, ArithmeticError, KeyError, IndexError, TypeError):
            ok = False
        if not ok:
            out.append(Breach("assert-data", what, f"'{rule}' delivered {d['value']!r} at {d['t']} s "
                              f"(message {run.message(d['msg'])!r})",
                              needs_of(run.message(d["msg"]), run.message_type(d["msg"]))))
    return out, unjudged


def has_null(v):
    if v is None:
        return True
    if isinstance(v, list):
        return any(has_null(x) for x in v)
    if isinstance(v, dict):
        return any(has_null(x) for x in v.values())
    return False


def uses(d, pred, consts):
    """Whether a delivery uses the resource (its `when` over `emitted`; none: every command).
    None when the delivered value cannot be judged (NaN or an infinity in it)."""
    if pred is None:
        return True
    if has_null(d["value"]):
        return None
    try:
        return evaluate(pred, {**consts, "emitted": d["value"]}) is True
    except (NoValue, ArithmeticError, KeyError, IndexError, TypeError):
        return False


def resource(run, model, res, pairs, needs_of, consts):
    """`resource R { P1, P2, ... } [when U];` proved (docs/checks.md#resource), per pair of rules
    (r1 into P1, r2 into P2) as the report lists it:
    - exclusive by events: no two deliveries of r1 and r2 that both use R at one instant from
      one event state: between the two decisions no entry of P1's or P2's container changed
      but by r1's or r2's own monitor (issue 38: the same event name in two ports' containers
      is two facts, so a proof that joined them is broken by such a run);
    - exclusive by data, one message (one source): no message of that source from which both
      deliver commands that use R; two messages of that source are not covered (the report's
      `per message` line);
    - exclusive by data, two messages (two sources): no message of r1's source and no message of
      r2's source that both make a command that uses R: so not both rules ever deliver one."""
    out = []
    using = {}
    for d in run.decisions:
        if d["delivered"] and d["port"] in res["ports"]:
            if not model.domain_holds(with_act(d, model)):
                continue  # outside the domain the proof assumes (an exclusive group, invariant)
            u = uses(d, res["when"], consts)
            if u:
                using.setdefault(d["conn"], []).append(d)
    for a, b, how in pairs:
        for da in using.get(a, []):
            for db in using.get(b, []):
                why = resource_pair_breach(run, da, db, how)
                if why:
                    out.append(Breach("resource", f"resource {res['name']}: '{a}' and '{b}' ({how})",
                                      why, needs_of(run.message(da["msg"]), run.message_type(da["msg"]))
                                      or needs_of(run.message(db["msg"]), run.message_type(db["msg"]))))
                    break
            else:
                continue
            break
    return out


def resource_pair_breach(run, da, db, how):
    if how == "one message":
        if da["msg"] == db["msg"]:
            return (f"'{da['conn']}' and '{db['conn']}' both delivered commands that use it from "
                    f"message {da['msg'][1]} of {da['msg'][0]} at {da['t']} s")
        return None
    if how == "two messages":
        return (f"'{da['conn']}' delivered {da['value']!r} at {da['t']} s and '{db['conn']}' "
                f"delivered {db['value']!r} at {db['t']} s: both use it")
    if da["t"] != db["t"]:
        return None
    first, second = sorted((da, db), key=lambda d: d["index"])
    ports = {da["port"], db["port"]}
    owners = {da["conn"], db["conn"]}
    for rec in run.records[first["index"] + 1: second["index"]]:
        if rec["type"] == "event" and rec["port"] in ports and rec["owner"] not in owners:
            return None
    return (f"'{first['conn']}' and '{second['conn']}' both delivered commands that use it at "
            f"{da['t']} s, with no other change to their ports' events between the two decisions "
            f"(states {sorted(first['state'])} and {sorted(second['state'])})")


# ---- Properties over time (docs/language.md#properties-over-time), judged on one port's
# records in the order the runtime made them, as verify/temporal/judge.cc judges a replay, with
# exact instants. "proved" is broken by any violating run; "holds up to N messages into P" by a
# run that violates within N decisions into P (deliveries and drops of every connection into P,
# feeds included: the model's steps). Ports with an `every` block are judged only when proved
# (its trig runs are steps the trace does not show as decisions).

def port_walk(run, port):
    """(record, decision state or None, decisions into the port so far) per record of port."""
    from .trace import Container
    box = Container()
    steps = 0
    for rec in run.port_records(port):
        if rec["type"] == "event":
            box.apply(rec, run.lifetime_of)
            yield rec, None, steps
        else:
            steps += 1
            yield rec, box.present(rec["t"]), steps


def assumption_broken(run, port, a):
    """An environment assumption (docs/language.md#environment-assumptions), at every decision
    into the port and every report of E into it: `assume E only after R [until O]`: E present
    only if R delivered before and O not since; `assume not E for D after R`: E not present less
    than D after a delivery of R. The time of the first decision or report that breaks it, or
    None."""
    armed, last_after = False, None
    for rec, state, _ in port_walk(run, port):
        if state is None:  # an event record: a report of E sets it
            present = rec.get("op") == "set" and rec.get("event") == a["event"]
        else:
            present = a["event"] in state
        if a.get("absent_for") is not None:
            if present and last_after is not None and \
                    rec["t"] - last_after < dec(a["absent_for"]):
                return rec["t"]
        elif present and not armed:
            return rec["t"]
        if rec["type"] == "deliver" and rec["connection"] == a["after"]:
            armed, last_after = True, rec["t"]
        if rec["type"] == "deliver" and a.get("until") and rec["connection"] == a["until"]:
            armed = False
    return None


def dec(x):
    from decimal import Decimal
    return Decimal(repr(x)) if isinstance(x, float) else Decimal(x)


def temporal(run, p, end):
    """The first violation of property `p` (verify JSON's `temporal` entry) as (decisions into
    the port up to it, what happened), or None. `end`: the instant the run was observed to."""
    kind, port = p["kind"], p["port"]
    w = dec(p["window"]) if p.get("window") is not None else None
    last = {}        # rule -> its last delivery
    armed = False
    last_rule = last_switch = None
    for rec, state, steps in port_walk(run, port):
        if rec["type"] != "deliver":
            continue
        t, who = rec["t"], rec["connection"]
        if kind == "spacing" and not p.get("after") and who == p["rule"] and \
                who in last and t - last[who] < w:
            return steps, f"'{who}' delivered at {last[who]} s and {t} s"
        if kind == "spacing" and p.get("after") and who == p["rule"] and \
                p["after"] in last and t - last[p["after"]] < w:
            return steps, f"'{who}' delivered at {t} s, '{p['after']}' at {last[p['after']]} s"
        if kind == "absence" and who == p["rule"] and p["event"] in state:
            return steps, f"'{who}' delivered at {t} s with {p['event']} present"
        if kind == "precedence":
            if who == p["after"]:
                armed = True
            elif who == p["rule"]:
                if not armed:
                    return steps, f"'{who}' delivered at {t} s with no '{p['after']}' since its last"
                armed = False
        if kind == "stability" and last_rule is not None and who != last_rule:
            if last_switch is not None and t - last_switch < w:
                return steps, f"switches at {last_switch} s and {t} s"
            last_switch = t
        last_rule = who
        last[who] = t
    if kind == "response":
        return response(run, p, w, end)
    return None


def response(run, p, w, end):
    """`after OTHER [stops], RULE within D [while C]`: each trigger (a delivery of OTHER; or
    EVENT becoming present: absent before a record, present after it, at its instant) at t is
    answered by a delivery of RULE (any rule of the port when RULE is the port) at a later
    record within (t, t + D]; with `stops`, a later delivery of OTHER in the window releases
    it; so does C false at a decision of RULE in the window. A window that ends after `end`
    is not judged. The rates the verdict assumes are kept by the inputs (inputs.py)."""
    from .model import parse_constraint, holds
    cond = parse_constraint(p.get("while") or "true")
    recs = list(port_walk(run, p["port"]))
    answer_any = not p.get("rule")
    event = p.get("event")
    before = set()
    from .trace import Container
    box = Container()
    for i, (rec, state, steps) in enumerate(recs):
        if rec["type"] == "event":
            was = event in box.present(rec["t"]) if event else False
            box.apply(rec, run.lifetime_of)
            trigger = event and rec["event"] == event and not was and event in box.present(rec["t"])
        else:
            trigger = not event and rec["type"] == "deliver" and rec["connection"] == p["after"]
        if not trigger:
            continue
        t = rec["t"]
        if t + w > end:
            continue
        if unanswered(recs[i + 1:], p, t + w, cond, answer_any):
            n = sum(1 for r, s, _ in recs if s is not None and r["t"] <= t + w)
            return n, f"trigger at {t} s, no answer by {t + w} s"
    del before
    return None


def unanswered(later, p, horizon, cond, answer_any):
    from .model import holds
    for rec, state, _ in later:
        if rec["t"] > horizon:
            break
        if state is None:
            continue
        who = rec["connection"]
        if p.get("stops") and rec["type"] == "deliver" and who == p["after"]:
            return False
        if not answer_any and who != p["rule"]:
            continue
        if answer_any and not who_is_rule(who, p):
            continue
        if rec["type"] == "deliver":
            return False
        if not holds(cond, state):
            return False
    return True


def who_is_rule(who, p):
    return who in p["_rules"]
