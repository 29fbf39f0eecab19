#!/usr/bin/env python3
"""The checker of properties over time against the runtime (docs/checks.md#temporal).

Random small apps (one arbitrated port, one to three rules with random guards over two fed
events, holds, throttles and accepts, with and without `by priority`), each with a spacing
property `never two RULE within W;`, verified with `arbc verify --format json`; then random
input timings for each app, run on the runtime in simulated time (`arbc run --inputs`,
`--trace`). Whenever a run violates the property within a number of messages into the port
that the bound covers, the checker must not have said "proved" or "holds up to the bound".

usage: temporal_differential.py ARBC CASES [SEED] [--keep]   (CASES: runs in all; exit 0 when
none contradicts the checker, 1 otherwise; the work directory is kept when a case contradicts
or with --keep)
"""
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile

BOUND = 6          # --temporal-bound: messages into the port the checker explores
RUNS_PER_APP = 4   # random input timings per app


def rule_body(rng, name, source, holds):
    """One rule; `holds`: it outranks a later rule of a `by priority` port."""
    guard = rng.choice(["", "e1", "not e1", "e2", "e1 and not e2", "e1 or e2", "not e2"])
    head = f"  {name}: from {source}.x" + (f" when {guard}" if guard else "")
    if holds:
        head += f" hold {rng.choice([0.2, 0.5, 1])}s"
    lines = []
    if rng.random() < 0.6:
        lines.append(f"throttle {rng.choice([0.1, 0.3, 0.5, 1, 2])}s;")
    if rng.random() < 0.3:
        lines.append("accept x > 2;")
    lines.append("emit x;")
    return head + " { " + " ".join(lines) + " }"


def random_app(rng, index):
    """The spec text, the sources of its messages and the property's rule and window."""
    n_rules = rng.randint(1, 3)
    by_priority = n_rules > 1 and rng.random() < 0.5
    lifetime = rng.choice([0.2, 0.5, 1.0])
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
    rule = f"r{rng.randint(1, n_rules)}"
    window = rng.choice([0.1, 0.25, 0.5, 1.0, 2.0])
    lines.append(f"never two {rule} within {window}s;")
    return "\n".join(lines) + "\n", sources, rule, window


def random_inputs(rng, sources, rule_source):
    """Messages at distinct random times (so the order into the port is the order of time),
    half of them from the property's rule's source."""
    n = rng.randint(2, BOUND + 2)
    times = sorted(rng.sample(range(1, 1500), n))
    out = []
    for ms in times:
        if rng.random() < 0.5:
            port = f"{rule_source}.x"
        else:
            port = rng.choice(["Status.s"] + [f"{s}.x" for s in sources])
        if port == "Status.s":
            value = [e for e in ("e1", "e2") if rng.random() < 0.6]
        else:
            value = rng.randint(0, 5)
        out.append({"t": ms / 1000, "port": port, "value": value})
    return out


def verdict(arbc, spec):
    """The property's outcome and bound from `arbc verify`."""
    r = subprocess.run([arbc, "verify", spec, "--format", "json", "--temporal-bound", str(BOUND)],
                       capture_output=True, text=True, timeout=120)
    if r.returncode not in (0, 1):
        raise RuntimeError(f"arbc verify {spec} exited {r.returncode}: {r.stderr}")
    temporal = json.loads(r.stdout)["inputs"][0]["temporal"][0]
    if temporal["outcome"] == "unknown":
        print(f"{spec}: unknown: {temporal['unknown_reason']}")
    return temporal["outcome"], temporal["bound"]


def violation(arbc, app_dir, inputs, rule, window, work):
    """The number of messages into the port up to the second delivery of the first pair of
    `rule`'s deliveries less than `window` apart; None when the run has no such pair."""
    inputs_file = os.path.join(work, "inputs.jsonl")
    trace_file = os.path.join(work, "trace.jsonl")
    with open(inputs_file, "w") as f:
        f.writelines(json.dumps(m) + "\n" for m in inputs)
    duration = inputs[-1]["t"] + 1
    r = subprocess.run([arbc, "run", app_dir, "--no-verify", "--inputs", inputs_file, "--duration",
                        f"{duration}s", "--trace", trace_file],
                       capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        raise RuntimeError(f"arbc run exited {r.returncode}: {r.stderr}")
    with open(trace_file) as f:
        steps = [json.loads(line) for line in f]
    times = [s["t"] for s in steps if s.get("type") == "deliver" and s.get("connection") == rule]
    for a, b in zip(times, times[1:]):
        if b - a < window - 1e-9:
            return sum(1 for m in inputs if m["t"] <= b + 1e-9)
    return None


def main():
    args = [a for a in sys.argv[1:] if a != "--keep"]
    arbc, cases = args[0], int(args[1])
    rng = random.Random(int(args[2]) if len(args) > 2 else 19)
    work = tempfile.mkdtemp(prefix="arbc-temporal-diff.")
    counts = {"runs": 0, "violating runs": 0, "apps": 0}
    outcomes = {}
    contradictions = []
    index = 0
    while counts["runs"] < cases:
        index += 1
        spec_text, sources, rule, window = random_app(rng, index)
        spec = os.path.join(work, f"diff{index}.spec")
        with open(spec, "w") as f:
            f.write(spec_text)
        outcome, bound = verdict(arbc, spec)
        outcomes[outcome] = outcomes.get(outcome, 0) + 1
        counts["apps"] += 1
        # Built without the proof (which refuses a violated property): the same artifacts.
        app_dir = os.path.join(work, f"build{index}")
        b = subprocess.run([arbc, "build", spec, "--no-verify", "-o", app_dir], capture_output=True, text=True,
                           timeout=120)
        if b.returncode != 0:
            raise RuntimeError(f"arbc build {spec} exited {b.returncode}: {b.stderr}")
        for _ in range(RUNS_PER_APP):
            inputs = random_inputs(rng, sources, "S" + rule[1:])
            counts["runs"] += 1
            steps = violation(arbc, os.path.join(app_dir, f"diff{index}"), inputs, rule, window,
                              work)
            if steps is None:
                continue
            counts["violating runs"] += 1
            # "holds up to the bound" says nothing of longer runs; "proved" of none.
            if outcome == "proved" or (outcome == "holds-up-to-bound" and steps <= bound):
                kept = os.path.join(work, f"contradiction{len(contradictions) + 1}.jsonl")
                with open(kept, "w") as f:
                    f.writelines(json.dumps(m) + "\n" for m in inputs)
                contradictions.append(f"{spec}: {outcome} (bound {bound}), but {rule} delivered "
                                      f"twice within {window} s after {steps} messages "
                                      f"({kept})")
    print(f"{counts['apps']} apps, {counts['runs']} runs; verdicts {outcomes}; runs that "
          f"violate their property: {counts['violating runs']}")
    for c in contradictions:
        print("CONTRADICTION:", c)
    if contradictions or "--keep" in sys.argv:
        print(f"kept in {work}")
    if contradictions:
        return 1
    # The test must be able to fail: it only means something if runs do violate properties
    # and the checker says "proved" or "holds" of some apps as well as "violated" of others.
    said_holds = outcomes.get("proved", 0) + outcomes.get("holds-up-to-bound", 0)
    if counts["violating runs"] < cases // 10 or not said_holds or not outcomes.get("violated"):
        print("too few violating runs or verdicts of one kind only: the generator no longer "
              "exercises the checker")
        return 1
    if "--keep" not in sys.argv:
        shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
