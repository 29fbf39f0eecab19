#!/usr/bin/env python3
"""`arbc test` watches each test's run as `arbc run` does (issue 39, docs/runtime.md#runtime-checks):
a test whose run breaks an invariant, an environment assumption, a resource or a source's rate
fails with the breach under its name (`--runtime-checks warn` passes it, saying the breach). And
both `arbc run` and `arbc test` drop a message whose list is longer than the proof of its rule
covers (`bad-value`), before the monitor.

usage: check_runtime_in_tests.py ARBC CASE        (run from the repository root)
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_runtime_checks import expect, run  # noqa: E402


def arbc_test(arbc, text, *options):
    with tempfile.TemporaryDirectory() as d:
        spec = os.path.join(d, "app.spec")
        with open(spec, "w", encoding="utf-8") as f:
            f.write(text)
        p = subprocess.run([arbc, "test", "app.spec", *options], capture_output=True, text=True,
                           timeout=120, cwd=d)
        return p.returncode, p.stdout, p.stderr


def fails_with(arbc, text, broken, said, kept, *options):
    """The test named `broken` fails with the runtime-check line `said` under its name, the test
    named `kept` passes; with --runtime-checks warn every test passes and the line is still said."""
    code, out, err = arbc_test(arbc, text, *options)
    expect(code == 1, f"exit {code}, expected 1", out, err)
    expect(f"FAIL  app.spec: {broken}\n  runtime check: {said}" in out,
           f"the test {broken!r} does not fail with {said!r}", out, err)
    expect(f"PASS  app.spec: {kept}" in out, f"the test {kept!r} does not pass", out, err)
    code, out, err = arbc_test(arbc, text, "--runtime-checks", "warn", *options)
    expect(code == 0 and f"PASS  app.spec: {broken}" in out and said in out,
           f"warn: exit {code}", out, err)


ARM = """app arm "what the arm reports, assumed";
module Arm { out status: list<string>; }
module Planner { out a: float; out b: float; }
module Base { in cmd: float; }
events from Arm.status { e_taken = "taken", e_busy = "busy" } lifetime 10s;
arbitrate Base.cmd {
  take: from Planner.a when not e_taken and not e_busy;
  put: from Planner.b when e_taken;
}
%s

test "take then put" {
  at 100ms Planner.a <- 1.0;
  at 200ms Arm.status <- ["taken"];
  at 300ms Planner.b <- 2.0;
  expect Base.cmd receives 2.0 at 300ms;
}
test "%s" {
  at 0s    Arm.status <- [%s];
  at 100ms Planner.b <- 2.0;
  expect Base.cmd receives 2.0 at 100ms;
}
"""


def case_test_invariant(arbc):
    fails_with(arbc, ARM % ("invariant not (e_taken and e_busy);", "holding and busy",
                            '"taken", "busy"'),
               "holding and busy",
               "assumption invariant not (e_taken and e_busy) broken at 100ms: false in Base.cmd "
               "at 100ms (events present: e_busy, e_taken)", "take then put")


def case_test_only_after(arbc):
    fails_with(arbc, ARM % ("assume e_taken only after take until put;", "holding what no take gave",
                            '"taken"'),
               "holding what no take gave",
               "assumption assume e_taken only after take until put broken at 0s: e_taken present "
               "in Base.cmd at 0s (reported by feed_Arm_status) with no delivery of 'take'\n",
               "take then put")


SHARED = """app shared "one arm, two ports, nothing keeps them apart: refuted, tested anyway";
module Planner { out a: int; out b: int; }
module Grip { in cmd: int; }
module Rake { in cmd: int; }
arbitrate Grip.cmd { grip: from Planner.a; }
arbitrate Rake.cmd { rake: from Planner.b; }
resource arm { Grip.cmd, Rake.cmd } when emitted > 0;

test "grip and rake at once" {
  at 100ms Planner.a <- 1;
  at 200ms Planner.b <- 2;
  expect Rake.cmd receives 2 at 200ms;
}
test "a rake that does not use the arm" {
  at 100ms Planner.a <- 1;
  at 200ms Planner.b <- 0;
  expect Rake.cmd receives 0 at 200ms;
}
"""


def case_test_resource(arbc):
    fails_with(arbc, SHARED, "grip and rake at once",
               "resource arm broken at 200ms: 'grip' into Grip.cmd at 100ms and 'rake' into "
               "Rake.cmd at 200ms both delivered a command that uses it (1, 2) in one event state",
               "a rake that does not use the arm", "--no-verify")


RATED = """app rated "a response that relies on its source's rate";
module Scan { out range: float; }
module Base { in cmd: float; }
arbitrate Base.cmd { go: from Scan.range; }
given Scan.range every 100ms;

test "a scan that pauses" {
  at 0s    Scan.range <- 1.0;
  at 100ms Scan.range <- 1.0;
  at 500ms Scan.range <- 1.0;
  expect Base.cmd receives 1.0 at 500ms;
}
test "a scan at its rate, then the test ends" {
  at 0s    Scan.range <- 1.0;
  at 100ms Scan.range <- 1.0;
  at 200ms Scan.range <- 1.0;
  expect Base.cmd receives 1.0 at 200ms;
}
"""


def case_test_rate(arbc):
    # A test is a window of the world: the rate is judged between the source's first and last
    # messages, not in the second of silence the test runs on after them.
    fails_with(arbc, RATED, "a scan that pauses",
               "assumption given Scan.range every 100ms broken at 200ms: nothing from Scan.range "
               "between 100ms and 500ms", "a scan at its rate, then the test ends")


# `pass` reads its list five times (tests/yarp_real/checks.spec): more than the proof's stand-ins
# past the list bound cover, so the proof of its assert holds for lists of at most 4 elements
# (--list-bound's default), and the runtime drops a longer one before the monitor.
BOUNDED = """app bounded "a rule proved for lists of at most 4 elements";
module Sensor { out v: list<float>; }
module Motor { in cmd: float; }
arbitrate Motor.cmd {
  pass: from Sensor.v {
    accept len(v) > 0;
    let hi = max_by(v, x => x);
    let lo = min_by(v, x => x);
    let far = max_by(v, x => x * x);
    let near = min_by(v, x => x * x);
    let mid = min_by(v, x => x - 1.0);
    accept hi < 5.0;
    emit hi * 2.0;
  }
}
assert Motor.cmd: pass -> emitted < 10.0;
"""
FOUR, FIVE = "[1.0, 2.0, 3.0, 4.0]", "[1.0, 2.0, 3.0, 4.0, 4.5]"


def case_list_bound_run(arbc):
    inputs = ['{"t": 0, "port": "Sensor.v", "value": %s}' % FOUR,
              '{"t": 0.1, "port": "Sensor.v", "value": %s}' % FIVE,
              '{"t": 0.2, "port": "Sensor.v", "value": [1.0]}']
    with tempfile.TemporaryDirectory() as d:
        trace = os.path.join(d, "t.jsonl")
        code, out, err = run(arbc, BOUNDED, inputs, "--trace", trace)
        # Inside the proof: dropped, said, and no failure.
        expect(code == 0, f"exit {code}, expected 0", out, err)
        row = next((ln.split() for ln in out.splitlines() if ln.startswith("pass ")), None)
        header = next((ln.split() for ln in out.splitlines() if ln.startswith("connection ")), [])
        expect(row and "bad-value" in header and row[header.index("bad-value")] == "1" and
               row[header.index("delivered")] == "2", f"pass's row: {row} under {header}", out, err)
        expect("runtime checks: 1 message the proof excluded dropped (bad-value: lists longer "
               "than it covers; see the trace)" in out, "the drop is not said", out, err)
        with open(trace, encoding="utf-8") as f:
            drops = [r for r in map(json.loads, f) if r["type"] == "drop"]
        expect(drops == [{"t": 0.1, "type": "drop", "connection": "pass", "reason": "bad-value",
                          "detail": "a list of 5 elements; the proof covers at most 4 (arbc "
                                    "verify --list-bound)"}], f"drops {drops}", out, err)
    # Without the proof there is no bound: the five elements are delivered.
    code, out, err = run(arbc, BOUNDED, inputs, "--no-verify")
    expect(code == 0 and "excluded" not in out, f"--no-verify: exit {code}", out, err)


def case_list_bound_test(arbc):
    tests = BOUNDED + """
test "a list longer than the proof covers" {
  at 0s    Sensor.v <- %s;
  at 100ms Sensor.v <- %s;
  expect Motor.cmd receives 8.0 at 0s;
  expect pass drops "bad-value" at 100ms;
  expect Motor.cmd receives nothing within 50ms..1s;
}
""" % (FOUR, FIVE)
    code, out, err = arbc_test(arbc, tests)
    expect(code == 0 and "PASS  " in out, f"exit {code}: the long list is not dropped", out, err)
    code, out, err = arbc_test(arbc, tests, "--no-verify")  # no proof, no bound
    expect(code == 1 and "but pass delivered at 100ms" in out, f"--no-verify: exit {code}", out,
           err)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    globals()["case_" + sys.argv[2]](os.path.abspath(sys.argv[1]))
    print("ok")


if __name__ == "__main__":
    main()
