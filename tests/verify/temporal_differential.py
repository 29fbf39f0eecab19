#!/usr/bin/env python3
"""The checker of properties over time against the runtime (docs/checks.md#temporal).

Random small apps (one arbitrated port, one to three rules with random guards over two fed
events, holds, throttles and accepts, with and without `by priority`), each with one property
over time of a random shape (spacing `never two RULE within W;` or `never RULE within W after
OTHER;`, absence `never RULE while EVENT;`, precedence `only RULE after OTHER;`, response `after
OTHER [stops], RULE within W [while C];`, its trigger a rule or an event becoming present and its
answer a rule or the port, with a rate `given S.x every P;` for RULE's source, or none), verified with
`arbc verify --format json`; then random input timings for each app, run on the runtime in
simulated time (`arbc run --inputs`, `--trace`). The timings respect the stated rate (the
source publishes by P and at most P after its previous message, up to the end of the run).
Whenever a run violates the property within a number of messages into the port that the bound
covers, the checker must not have said "proved" or "holds up to the bound".
Some apps (two rules or more) carry an environment assumption `assume e1 only after RULE
[until OTHER];` or `assume not e1 for W after RULE;`; their runs are made to keep it (a status message that reports e1 where the
assumption forbids it stops reporting it, and the run is repeated), since the checker speaks
only of such environments. The test fails unless it sees violations, "holds up to the bound",
verdicts under assumptions and (in 500 runs or more) proofs by k-induction. A
counterexample whose replay disagrees with the checker (an internal error, never a verdict)
fails the test too.

Times are the runtime's whole nanoseconds (docs/design.md#events-and-lifetimes), judged exactly
(the trace's decimals read as integers, no tolerance). Half the messages come a nanosecond
before, at, or a nanosecond after an earlier message's time plus one of the app's durations
(a throttle, a hold, a lifetime, a window, a rate), where a throttle or a hold ends, an event
lapses or a window closes; some durations are themselves a nanosecond off a round value.

usage: temporal_differential.py ARBC CASES [SEED] [--keep]   (CASES: runs in all; exit 0 when
none contradicts the checker, 1 otherwise; the work directory is kept when a case contradicts
or with --keep)
"""
import decimal
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

BOUND = 6          # --temporal-bound: messages into the port the checker explores
RUNS_PER_APP = 4   # random input timings per app
NS = 10 ** 9       # nanoseconds in a second
MS = 10 ** 6       # in a millisecond


def ns_of(seconds):
    """Whole nanoseconds of a duration or a time written in seconds ("0.5", 1, a Decimal)."""
    return int(decimal.Decimal(str(seconds)) * NS)


def seconds_text(ns):
    """`ns` as the exact decimal of its seconds, as the runtime writes times."""
    text = f"{ns // NS}.{ns % NS:09d}".rstrip("0")
    return text + "0" if text.endswith(".") else text


def durations_of(spec_text):
    """Every duration the spec states, in nanoseconds: where deadlines fall after an instant."""
    return sorted({ns_of(d) for d in re.findall(r"(\d+(?:\.\d+)?)s\b", spec_text)})


def rule_body(rng, name, source, holds):
    """One rule; `holds`: it outranks a later rule of a `by priority` port."""
    guard = rng.choice(["", "e1", "not e1", "e2", "e1 and not e2", "e1 or e2", "not e2"])
    head = f"  {name}: from {source}.x" + (f" when {guard}" if guard else "")
    if holds:
        head += f" hold {rng.choice([0.2, 0.5, 1, '0.999999999', '1.000000001'])}s"
    lines = []
    if rng.random() < 0.6:
        lines.append(f"throttle {rng.choice([0.1, 0.3, 0.5, 1, 2, '0.999999999', '1.000000001'])}s;")
    if rng.random() < 0.3:
        lines.append("accept x > 2;")
    lines.append("emit x;")
    return head + " { " + " ".join(lines) + " }"


def random_app(rng, index):
    """The spec text, the sources of its messages and the property (shape, rule, argument)."""
    n_rules = rng.randint(1, 3)
    by_priority = n_rules > 1 and rng.random() < 0.5
    lifetime = rng.choice([0.2, 0.5, 1.0, "0.500000001"])
    sources = [f"S{k}" for k in range(1, n_rules + 1)]
    lines = [f'app diff{index} "a random app of the differential test";',
             "type Status = list<string>;",
             "module Status { out s: Status; }",
             "module Dst { in y: int; }"]
    lines += [f"module {s} {{ out x: int; }}" for s in sources]
    lines.append(f"events from Status.s {{ e1, e2 }} lifetime {lifetime}s;")
    lines.append("arbitrate Dst.y" + (" by priority" if by_priority else "") + " {")
    lines += [rule_body(rng, f"r{k}", s, by_priority and k < n_rules)
              for k, s in enumerate(sources, 1)]
    lines.append("}")
    k = rng.randint(1, n_rules)
    rule = f"r{k}"
    shape = rng.choice(["spacing", "spacing", "absence", "stability", "response"] +
                       (["precedence", "response", "spacing_after"] if n_rules > 1 else []))
    if shape == "stability":
        window = rng.choice(["0.1", "0.3", "0.6", "1", "0.999999999"])
        lines.append(f"stable Dst.y for {window}s;")
        return "\n".join(lines) + "\n", sources, ("stability", rule, ns_of(window)), None
    if shape == "response":
        prop = response_prop(rng, lines, n_rules, k)
        return "\n".join(lines) + "\n", sources, prop, None
    if shape == "spacing":
        window = rng.choice(["0.1", "0.25", "0.5", "1", "2", "1.000000001", "0.999999999"])
        prop = ("spacing", rule, ns_of(window))
        lines.append(f"never two {rule} within {window}s;")
    elif shape == "spacing_after":
        other = f"r{rng.choice([j for j in range(1, n_rules + 1) if j != k])}"
        window = rng.choice(["0.1", "0.25", "0.5", "1", "1.000000001"])
        prop = ("spacing_after", rule, (other, ns_of(window)))
        lines.append(f"never {rule} within {window}s after {other};")
    elif shape == "absence":
        events = ["e1", "e2"] + ([f"act_r{j}" for j in range(1, n_rules)] if by_priority else [])
        prop = ("absence", rule, rng.choice(events))
        lines.append(f"never {rule} while {prop[2]};")
    else:
        prop = ("precedence", rule, f"r{rng.choice([j for j in range(1, n_rules + 1) if j != k])}")
        lines.append(f"only {rule} after {prop[2]};")
    assumption = None
    if n_rules > 1 and rng.random() < 0.4:
        # `assume e1 only after rA [until rB];` or `assume not e1 for W after rA;`: the checker
        # explores only such environments, and the runs are made to keep it (keep_assumption).
        after, until = rng.sample([f"r{j}" for j in range(1, n_rules + 1)], 2)
        if rng.random() < 0.5:
            absent_for = rng.choice(["0.2", "0.5", "1", "1.000000001"])
            assumption = ("e1", after, None, ns_of(absent_for))
            lines.append(f"assume not e1 for {absent_for}s after {after};")
        else:
            until = until if rng.random() < 0.7 else None
            assumption = ("e1", after, until, None)
            lines.append(f"assume e1 only after {after}" + (f" until {until}" if until else "") + ";")
    return "\n".join(lines) + "\n", sources, prop, assumption


def response_prop(rng, lines, n_rules, k):
    """Appends `[given S_k.x every P;] after T [stops], A within W [while C];` to `lines`, T a
    rule rO or an event (its becoming present), A the rule rk or the port Dst.y (any rule); the
    property as (shape, rule or "Dst.y", (trigger, stops, window, condition, period or None))."""
    if n_rules > 1 and rng.random() < 0.6:
        trigger = f"r{rng.choice([j for j in range(1, n_rules + 1) if j != k])}"
        stops = rng.random() < 0.6
    else:
        trigger, stops = rng.choice(["e1", "e2"]), False
    answer = f"r{k}" if rng.random() < 0.6 else "Dst.y"
    window = rng.choice(["0.3", "0.6", "1", "1.5", "0.999999999"])
    condition = rng.choice(["", "", "e1", "not e2", "e1 and e2"])
    period = rng.choice([None, "0.2", "0.4", "0.7"])
    if period is not None:
        lines.append(f"given S{k}.x every {period}s;")
    lines.append(f"after {trigger}{' stops' if stops else ''}, {answer} within {window}s"
                 + (f" while {condition}" if condition else "") + ";")
    period = None if period is None else ns_of(period)
    return ("response", answer, (trigger, stops, ns_of(window), condition, period, f"S{k}"))


def rated_times(rng, period, end, taken):
    """Times (ns, on whole milliseconds) of a source publishing at least every `period` ns from
    0 to `end`, avoiding the times in `taken` (so that the order into the port is the order of
    time)."""
    out, last = [], 0
    p = period // MS
    while (last + p) * MS <= end or not out:
        t = rng.randint(last + 1, last + p)
        while t * MS in taken and t > last + 1:
            t -= 1
        if t * MS in taken:
            break
        out.append(t * MS)
        taken.add(t * MS)
        last = t
    return out


def random_inputs(rng, sources, rule_source, durations, period=None):
    """As random_other_inputs; with a `period` (ns), the rule's source also publishes at that
    rate up to the end of the run (the last message plus the longest window)."""
    if period is None:
        return random_other_inputs(rng, sources, rule_source, durations)
    others = random_other_inputs(rng, [s for s in sources if s != rule_source], None, durations)
    taken = {m["t"] for m in others}
    end = max(taken) + 1500 * MS if taken else 1500 * MS
    rated = [{"t": t, "port": f"{rule_source}.x", "value": rng.randint(0, 5)}
             for t in rated_times(rng, period, end, taken)]
    return sorted(others + rated, key=lambda m: m["t"])


def near_deadlines(rng, times, durations):
    """`times` (ns, distinct, sorted) with about half of them moved to a nanosecond before, at,
    or a nanosecond after an earlier time plus one of `durations`: where a throttle or a hold
    that began at that earlier message ends, an event it set lapses, or a window closes."""
    times = list(times)
    for i in range(1, len(times)):
        if not durations or rng.random() < 0.5:
            continue
        moved = times[rng.randrange(i)] + rng.choice(durations) + rng.choice([-1, 0, 1])
        if moved not in times:
            times[i] = moved
    return sorted(times)


def random_other_inputs(rng, sources, rule_source, durations):
    """Messages at distinct times (so the order into the port is the order of time), many of
    them on a deadline's last nanosecond or just past it (near_deadlines), half of them from the
    property's rule's source."""
    n = rng.randint(2, BOUND + 2)
    times = near_deadlines(rng, [ms * MS for ms in sorted(rng.sample(range(1, 1500), n))],
                           durations)
    out = []
    for t in times:
        if rule_source and rng.random() < 0.5:
            port = f"{rule_source}.x"
        else:
            port = rng.choice(["Status.s"] + [f"{s}.x" for s in sources])
        if port == "Status.s":
            value = [e for e in ("e1", "e2") if rng.random() < 0.6]
        else:
            value = rng.randint(0, 5)
        out.append({"t": t, "port": port, "value": value})
    return out


def decisions(steps):
    """Per decision into Dst.y (a rule's delivery or drop, a feed's message), in order: its
    time, its connection and the entries of e1 in the port as they are at the decision."""
    entries = {}
    for s in steps:
        if s.get("type") == "event" and s.get("port") == "Dst.y" and s.get("event") == "e1":
            if s["op"] == "set":
                entries[s["owner"]] = s.get("expiry", -1)
            else:
                entries.pop(s["owner"], None)
        elif s.get("type") in ("deliver", "drop") and (
                s["connection"].startswith("r") or s["connection"].startswith("feed_")):
            present = any(e < 0 or s["t"] < e for e in entries.values())
            yield s["t"], s["connection"], s["type"] == "deliver", present


def broken_at(steps, assumption):
    """The time of the first decision at which the run breaks the assumption; None if none."""
    _, after, until, absent_for = assumption
    armed = False
    last_after = None
    for t, who, delivered, present in decisions(steps):
        if absent_for is None and present and not armed:
            return t
        if (absent_for is not None and present and last_after is not None
                and t - last_after < absent_for):
            return t
        if delivered and who == after:
            armed = True
            last_after = t
        if delivered and who == until:
            armed = False
    return None


def keep_assumption(arbc, app_dir, inputs, assumption, work):
    """The inputs changed until the run keeps the assumption: the status message that last
    reported e1 before the decision that broke it no longer does (at most len(inputs) times);
    the trace of the run that keeps it."""
    for _ in range(len(inputs) + 1):
        steps = run_trace(arbc, app_dir, inputs, work)
        at = broken_at(steps, assumption)
        if at is None:
            return steps
        reported = [m for m in inputs if m["port"] == "Status.s" and "e1" in m["value"]
                    and m["t"] <= at]
        if not reported:
            raise RuntimeError(f"{app_dir}: e1 present at {at} with no status reporting it")
        reported[-1]["value"].remove("e1")
    raise RuntimeError(f"{app_dir}: could not make the run keep {assumption}")


def verdict(arbc, spec):
    """The property's outcome, bound and k-induction's k from `arbc verify`."""
    r = subprocess.run([arbc, "verify", spec, "--format", "json", "--temporal-bound", str(BOUND)],
                       capture_output=True, text=True, timeout=120)
    if r.returncode not in (0, 1):
        raise RuntimeError(f"arbc verify {spec} exited {r.returncode}: {r.stderr}")
    temporal = json.loads(r.stdout)["inputs"][0]["temporal"][0]
    if temporal["outcome"] == "unknown":
        print(f"{spec}: unknown: {temporal['unknown_reason']}")
        if "internal error" in (temporal["unknown_reason"] or ""):
            return "unknown (replay disagrees)", temporal["bound"], None
    return temporal["outcome"], temporal["bound"], temporal.get("induction_k")


def first_violation(steps, prop):
    """The time of the delivery at which the trace first violates `prop`; None if it does not."""
    kind, rule, arg = prop
    last = None           # spacing: rule's last delivery (after OTHER: OTHER's)
    entries = {}          # absence: the event's entries in the port, owner -> expiry (-1: none)
    armed = False         # precedence: OTHER delivered since rule's last delivery
    last_who = last_switch = None  # stability: the last rule to deliver, the last switch
    for s in steps:
        if s.get("type") == "event" and s.get("port") == "Dst.y" and s.get("event") == arg:
            if s["op"] == "set":
                entries[s["owner"]] = s.get("expiry", -1)
            else:
                entries.pop(s["owner"], None)
        if s.get("type") != "deliver":
            continue
        t, who = s["t"], s["connection"]
        if kind == "stability":  # two switches of the delivering rule less than arg apart
            if last_who is not None and who != last_who:
                if last_switch is not None and t - last_switch < arg:
                    return t
                last_switch = t
            last_who = who
            continue
        if kind == "spacing_after":  # rule less than the window after OTHER's last delivery
            other, window = arg
            if who == other:
                last = t
            elif who == rule and last is not None and t - last < window:
                return t
            continue
        if kind == "precedence" and who == arg:
            armed = True
        if who != rule:
            continue
        if kind == "spacing":
            if last is not None and t - last < arg:
                return t
            last = t
        elif kind == "absence":
            if any(e < 0 or t < e for e in entries.values()):
                return t
        else:
            if not armed:
                return t
            armed = False
    return None


def holds(condition, present):
    """A `while` condition ("", "e1", "not e2", "e1 and e2") over the present events."""
    if not condition:
        return True
    return all((e[4:] not in present) if e.startswith("not ") else (e in present)
               for e in condition.split(" and "))


def response_violation(steps, prop, inputs):
    """The end of the first window of `prop` (a response) that the run leaves unanswered while
    the rate still holds; None if there is none."""
    _, rule, (other, stops, window, condition, period, rated) = prop
    port = rule == "Dst.y"  # any rule answers
    # The answering rules decide on their sources' messages.
    decision_times = [m["t"] for m in inputs
                      if m["port"] != "Status.s" and (port or m["port"] == "S" + rule[1:] + ".x")]
    rated_times = [m["t"] for m in inputs if m["port"] == rated + ".x"]
    # The observed run: while the rate holds (to its last message plus the period), or, with no
    # rate, to the end of the run.
    end = (rated_times[-1] + period) if period is not None and rated_times else inputs[-1]["t"] + NS
    history = []  # (t, event, owner, expiry or None for an unset)
    delivers = []
    for s in steps:
        if s.get("type") == "event" and s.get("port") == "Dst.y":
            history.append((s["t"], s["event"], s["owner"],
                            s.get("expiry", -1) if s["op"] == "set" else None))
        elif s.get("type") == "deliver":
            delivers.append((s["t"], s["connection"]))

    def present_at(d):
        entries = {}
        for t, event, owner, expiry in history:
            if t > d:
                break
            if expiry is None:
                entries.pop((event, owner), None)
            else:
                entries[event, owner] = expiry
        return {ev for (ev, _), x in entries.items() if x < 0 or d < x}

    def onsets(event):
        """The times `event` becomes present in the port: absent before a record, present after."""
        out, entries = [], {}
        for t, ev, owner, expiry in history:
            if ev != event:
                continue
            before = any(x < 0 or t < x for x in entries.values())
            if expiry is None:
                entries.pop(owner, None)
            else:
                entries[owner] = expiry
            if not before and any(x < 0 or t < x for x in entries.values()):
                out.append(t)
        return out

    triggers = onsets(other) if other.startswith("e") else [t for t, w in delivers if w == other]
    for t in triggers:
        if t + window > end:
            continue
        answered = any(t < u <= t + window and (w == rule or port or (stops and w == other))
                       for u, w in delivers)
        lapsed = any(t < d <= t + window and not holds(condition, present_at(d))
                     for d in decision_times)
        if not answered and not lapsed:
            return t + window
    return None


def input_line(m):
    """One line of an inputs file, its time the exact decimal of its nanoseconds."""
    return (f'{{"t": {seconds_text(m["t"])}, "port": {json.dumps(m["port"])}, '
            f'"value": {json.dumps(m["value"])}}}\n')


def trace_record(line):
    """A trace line with its times (exact decimals of nanoseconds) as whole nanoseconds."""
    r = json.loads(line, parse_float=decimal.Decimal)
    for key in ("t", "expiry"):
        if key in r:
            r[key] = ns_of(r[key])
    return r


def run_trace(arbc, app_dir, inputs, work):
    """The trace of the run of `inputs` on the runtime in simulated time."""
    inputs_file = os.path.join(work, "inputs.jsonl")
    trace_file = os.path.join(work, "trace.jsonl")
    with open(inputs_file, "w") as f:
        f.writelines(input_line(m) for m in inputs)
    duration = seconds_text(inputs[-1]["t"] + NS)
    # The runtime checks off: this script is the oracle, and a violated property is a run to
    # compare, not a failed one.
    r = subprocess.run([arbc, "run", app_dir, "--no-verify", "--inputs", inputs_file, "--duration",
                        f"{duration}s", "--trace", trace_file, "--runtime-checks", "off"],
                       capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        raise RuntimeError(f"arbc run exited {r.returncode}: {r.stderr}")
    with open(trace_file) as f:
        return [trace_record(line) for line in f]


def violation(steps, inputs, prop):
    """The number of messages into the port up to the delivery at which the run violates
    `prop`; None when it does not."""
    at = response_violation(steps, prop, inputs) if prop[0] == "response" else \
        first_violation(steps, prop)
    return None if at is None else sum(1 for m in inputs if m["t"] <= at)


def main():
    args = [a for a in sys.argv[1:] if a != "--keep"]
    arbc, cases = args[0], int(args[1])
    rng = random.Random(int(args[2]) if len(args) > 2 else 19)
    work = tempfile.mkdtemp(prefix="arbc-temporal-diff.")
    counts = {"runs": 0, "violating runs": 0, "apps": 0, "runs under an assumption": 0}
    outcomes = {}
    shapes = {}  # (shape, outcome) -> apps
    contradictions = []
    index = 0
    while counts["runs"] < cases:
        index += 1
        spec_text, sources, prop, assumption = random_app(rng, index)
        rule = prop[1]
        spec = os.path.join(work, f"diff{index}.spec")
        with open(spec, "w") as f:
            f.write(spec_text)
        outcome, bound, induction_k = verdict(arbc, spec)
        if outcome == "unknown (replay disagrees)":
            # The checker's own replay found that the model and the runtime disagree on this
            # app (reported as an internal error, never as a verdict): a bug all the same.
            contradictions.append(f"{spec}: the replay of the checker's counterexample "
                                  "disagrees with it (internal error)")
        said = outcome + (f" (k-induction)" if induction_k else "")
        label = prop[0]
        if prop[0] == "response":  # which trigger and which answer
            label += (" to event" if prop[2][0].startswith("e") else "") + \
                (" by port" if prop[1] == "Dst.y" else "")
        key = (label + (" assuming" if assumption else ""), said)
        outcomes[said] = outcomes.get(said, 0) + 1
        shapes[key] = shapes.get(key, 0) + 1
        counts["apps"] += 1
        # Built without the proof (which refuses a violated property): the same artifacts.
        app_dir = os.path.join(work, f"build{index}")
        b = subprocess.run([arbc, "build", spec, "--no-verify", "-o", app_dir], capture_output=True, text=True,
                           timeout=120)
        if b.returncode != 0:
            raise RuntimeError(f"arbc build {spec} exited {b.returncode}: {b.stderr}")
        for _ in range(RUNS_PER_APP):
            period = prop[2][4] if prop[0] == "response" else None
            rated = prop[2][5] if prop[0] == "response" else "S" + rule[1:]
            inputs = random_inputs(rng, sources, rated, durations_of(spec_text), period)
            counts["runs"] += 1
            built = os.path.join(app_dir, f"diff{index}")
            if assumption:
                trace = keep_assumption(arbc, built, inputs, assumption, work)
                counts["runs under an assumption"] += 1
            else:
                trace = run_trace(arbc, built, inputs, work)
            steps = violation(trace, inputs, prop)
            if steps is None:
                continue
            counts["violating runs"] += 1
            # "holds up to the bound" says nothing of longer runs; "proved" of none.
            if outcome == "proved" or (outcome == "holds-up-to-bound" and steps <= bound):
                kept = os.path.join(work, f"contradiction{len(contradictions) + 1}.jsonl")
                with open(kept, "w") as f:
                    f.writelines(input_line(m) for m in inputs)
                contradictions.append(f"{spec}: {outcome} (bound {bound}), but the run violates "
                                      f"{prop[0]} after {steps} messages ({kept})")
    print(f"{counts['apps']} apps, {counts['runs']} runs ({counts['runs under an assumption']} "
          f"under an assumption); runs that violate their property: "
          f"{counts['violating runs']}; verdicts:")
    for (shape, outcome), n in sorted(shapes.items()):
        print(f"  {shape:<20} {outcome:<30} {n}")
    for c in contradictions:
        print("CONTRADICTION:", c)
    if contradictions or "--keep" in sys.argv:
        print(f"kept in {work}")
    if contradictions:
        return 1
    # The test must be able to fail: it only means something if runs do violate properties
    # and the checker says "proved" or "holds" of some apps as well as "violated" of others.
    # And it must see "holds up to the bound", verdicts under assumptions and, in a run of 500
    # or more, proofs by k-induction (the spacing after another rule gives some: a hold keeps a
    # lower rule out; 4 apps at the default seed); the sanitized build's 100 runs may see none.
    said_holds = sum(n for o, n in outcomes.items() if o not in ("violated", "unknown"))
    induction_seen = cases < 500 or any(o.endswith("(k-induction)") for o in outcomes)
    kinds_seen = (outcomes.get("holds-up-to-bound") and induction_seen
                  and any(shape.endswith("assuming") for shape, _ in shapes))
    if (counts["violating runs"] < cases // 10 or not outcomes.get("violated") or not kinds_seen
            or not said_holds):
        print("too few violating runs or verdicts of one kind only: the generator no longer "
              "exercises the checker")
        return 1
    if "--keep" not in sys.argv:
        shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
