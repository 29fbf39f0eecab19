#!/usr/bin/env python3
"""`arbc run` checks what the proof proved and assumed (issue 39, runtime/claim_watch.h): a run
that breaks a property over time, an `exclusive` group, an environment assumption or a source
rate ends in failure (exit 3) naming it and the instant; a run that keeps them says so.

usage: check_runtime_checks.py ARBC CASE        (run from the repository root)
"""
import json
import os
import re
import subprocess
import sys
import tempfile

GRIPS = """app grips "two grips that the proof keeps apart through an exclusive group";
module Arm { out status: list<string>; }
module Planner { out left: float; out right: float; }
module Hand { in cmd: float; }
events from Arm.status { e_left = "left", e_right = "right" } lifetime 1s;
exclusive { e_left, e_right };
arbitrate Hand.cmd {
  left: from Planner.left when e_left;
  right: from Planner.right when e_right;
}
"""


def run(arbc, spec_text, inputs, *options, checks="fail"):
    with tempfile.TemporaryDirectory() as d:
        spec = os.path.join(d, "app.spec")
        with open(spec, "w", encoding="utf-8") as f:
            f.write(spec_text)
        path = os.path.join(d, "in.jsonl")
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(inputs) + "\n")
        proc = subprocess.run([arbc, "run", spec, "--inputs", path, *options] +
                              (["--runtime-checks", checks] if checks else []),
                              capture_output=True, text=True, timeout=120)
        return proc.returncode, proc.stdout, proc.stderr


def expect(cond, what, out="", err=""):
    if not cond:
        sys.exit(f"FAIL: {what}\n--- stdout\n{out}\n--- stderr\n{err}")


def case_exclusive_group_broken(arbc):
    # The case: a status listing both flags of an exclusive group made both grips deliver
    # and the run said success.
    code, out, err = run(arbc, GRIPS, [
        '{"t": 0, "port": "Arm.status", "value": ["left", "right"]}',
        '{"t": 0.1, "port": "Planner.left", "value": 1.0}',
        '{"t": 0.1, "port": "Planner.right", "value": 2.0}'])
    expect(code == 3, f"exit {code}, expected 3", out, err)
    # The group, and with it the port's exclusivity that rests on it.
    expect("runtime checks: 2 of 2 broken; the proof does not cover the run from 100ms:" in out,
           "no runtime-check line", out, err)
    expect("100ms  assumption exclusive { e_left, e_right }: e_left and e_right present together "
           "in Hand.cmd at 100ms" in out, "the violation is not named with its instant", out, err)
    expect("100ms  Hand.cmd: rules left, right are never selected together: 'left' delivered at "
           "100ms in a state where 'right' is selected too (events present: e_left, e_right)" in out,
           "the port's exclusivity is not said broken", out, err)
    expect("result: failure (runtime checks: assumption exclusive { e_left, e_right } at 100ms; "
           "Hand.cmd: rules left, right are never selected together at 100ms broken)" in out,
           "the verdict does not name them", out, err)


def case_fail_by_default_warn_and_off(arbc):
    # Without --runtime-checks a breach fails the run; warn says it and keeps the verdict
    # (docs/runtime.md#runtime-checks).
    code, out, err = run(arbc, GRIPS, [
        '{"t": 0, "port": "Arm.status", "value": ["left", "right"]}',
        '{"t": 0.1, "port": "Planner.left", "value": 1.0}'], checks=None)
    expect(code == 3 and "result: failure (runtime checks:" in out, f"exit {code}, expected 3",
           out, err)
    code, out, err = run(arbc, GRIPS, [
        '{"t": 0, "port": "Arm.status", "value": ["left", "right"]}',
        '{"t": 0.1, "port": "Planner.left", "value": 1.0}'], checks="warn")
    expect(code == 0, f"exit {code}, expected 0", out, err)
    expect("runtime checks: 2 of 2 broken; the proof does not cover the run from 100ms "
           "(--runtime-checks fail makes this a failure):" in out, "the breach is not said", out, err)
    code, out, err = run(arbc, GRIPS, [
        '{"t": 0, "port": "Arm.status", "value": ["left", "right"]}',
        '{"t": 0.1, "port": "Planner.left", "value": 1.0}'], checks="off")
    expect(code == 0 and "runtime checks" not in out, f"exit {code}; off still checks", out, err)


def case_exclusive_group_kept(arbc):
    code, out, err = run(arbc, GRIPS, [
        '{"t": 0, "port": "Arm.status", "value": ["left"]}',
        '{"t": 0.1, "port": "Planner.left", "value": 1.0}',
        '{"t": 0.1, "port": "Planner.right", "value": 2.0}'])
    expect(code == 0, f"exit {code}, expected 0", out, err)
    expect("runtime checks: 2 claims and assumptions of the proof watched, none broken" in out,
           "no line saying what was watched", out, err)


SPACED = """app spaced "a spacing the rule does not enforce";
module Planner { out cmd: float; }
module Base { in cmd: float; }
arbitrate Base.cmd { go: from Planner.cmd; }
never two go within 1s;
"""


def case_property_broken(arbc):
    # --no-verify runs an app whose property the proof refutes: the run says where it breaks.
    code, out, err = run(arbc, SPACED, [
        '{"t": 0, "port": "Planner.cmd", "value": 1.0}',
        '{"t": 0.25, "port": "Planner.cmd", "value": 2.0}'], "--no-verify")
    expect(code == 3, f"exit {code}, expected 3", out, err)
    expect("250ms  never two go within 1s: 'go' delivered at 0s and at 250ms" in out,
           "the property's breach is not named", out, err)
    code, out, err = run(arbc, SPACED, [
        '{"t": 0, "port": "Planner.cmd", "value": 1.0}',
        '{"t": 1.5, "port": "Planner.cmd", "value": 2.0}'], "--no-verify")
    expect(code == 0 and "none broken" in out, f"exit {code} on a run that keeps it", out, err)


def case_breach_in_trace_and_report(arbc):
    # A breach is also a trace line right after the record that showed it, and a mark in the
    # run report's timeline (docs/runtime.md#runtime-checks).
    with tempfile.TemporaryDirectory() as d:
        trace, report = os.path.join(d, "t.jsonl"), os.path.join(d, "r.html")
        code, out, err = run(arbc, SPACED, [
            '{"t": 0, "port": "Planner.cmd", "value": 1.0}',
            '{"t": 0.25, "port": "Planner.cmd", "value": 2.0}'], "--no-verify", "--trace", trace,
            "--report", report, checks="warn")
        expect(code == 0, f"exit {code}, expected 0 (warn)", out, err)
        with open(trace, encoding="utf-8") as f:
            lines = [json.loads(line) for line in f]
        kinds = [line["type"] for line in lines]
        expect(kinds.count("breach") == 1, f"{kinds.count('breach')} breach lines", out, err)
        i = kinds.index("breach")
        expect(lines[i - 1]["type"] == "deliver" and lines[i - 1]["t"] == 0.25,
               f"the breach does not follow the delivery that showed it: {lines[i - 1]}")
        expect(lines[i] == {"t": 0.25, "type": "breach", "claim": "never two go within 1s",
                            "message": "broken at 250ms: 'go' delivered at 0s and at 250ms"},
               f"breach line {lines[i]}")
        with open(report, encoding="utf-8") as f:
            html = f.read()
        expect("never two go within 1s broken (seen at" in html, "no mark in the report", out, err)
        expect("runtime check: never two go within 1s broken at 250ms" in html,
               "not listed in the report", out, err)


OVERLAP = """app overlap "two rules of one source whose bodies overlap: refuted, run anyway";
module Sensor { out v: float; }
module Motor { in cmd: float; }
arbitrate Motor.cmd {
  low: from Sensor.v { accept v < 0.6; }
  high: from Sensor.v { accept v > 0.4; }
}
"""


def case_exclusivity_broken(arbc):
    # One message accepted by both rules: delivered twice, which exclusivity forbids.
    code, out, err = run(arbc, OVERLAP, [
        '{"t": 0, "port": "Sensor.v", "value": 0.2}',
        '{"t": 0.1, "port": "Sensor.v", "value": 0.5}'], "--no-verify")
    expect(code == 3, f"exit {code}, expected 3", out, err)
    expect("100ms  Motor.cmd: rules low, high are never selected together: one message from "
           "Sensor.v delivered by both 'low' and 'high' at 100ms" in out,
           "one message delivered twice is not said", out, err)
    code, out, err = run(arbc, OVERLAP, [
        '{"t": 0, "port": "Sensor.v", "value": 0.2}',
        '{"t": 0.1, "port": "Sensor.v", "value": 0.9}'], "--no-verify")
    expect(code == 0 and "none broken" in out, f"exit {code} on messages only one rule takes",
           out, err)


ASSERTED = """app asserted "an assert the rule's guard does not keep: refuted, run anyway";
module Arm { out status: list<string>; }
module Planner { out cmd: float; }
module Hand { in cmd: float; }
events from Arm.status { e_ready = "ready", e_safe = "safe" } lifetime 1s;
arbitrate Hand.cmd { go: from Planner.cmd when e_ready; }
assert Hand.cmd: go -> e_safe;
"""


def case_assert_broken(arbc):
    code, out, err = run(arbc, ASSERTED, [
        '{"t": 0, "port": "Arm.status", "value": ["ready", "safe"]}',
        '{"t": 0.1, "port": "Planner.cmd", "value": 1.0}',
        '{"t": 0.2, "port": "Arm.status", "value": ["ready"]}',
        '{"t": 0.3, "port": "Planner.cmd", "value": 1.0}'], "--no-verify")
    expect(code == 3, f"exit {code}, expected 3", out, err)
    expect("300ms  assert Hand.cmd: go -> e_safe: 'go' delivered at 300ms with e_safe false in "
           "Hand.cmd (events present: e_ready)" in out, "the assert's breach is not named", out, err)



DOUBLED = """app doubled "an assert over data the rule does not keep: refuted, run anyway";
module Sensor { out v: float; }
module Motor { in cmd: float; }
arbitrate Motor.cmd { pass: from Sensor.v { emit v * 2.0; } }
assert Motor.cmd: pass -> emitted < 10.0;
"""


def case_data_assert_broken(arbc):
    # Asserts over `emitted` are checked on each delivery by the claims script arbc build wrote
    # from the IR the proof encodes (runtime/data_claims.h).
    code, out, err = run(arbc, DOUBLED, [
        '{"t": 0, "port": "Sensor.v", "value": 1.0}',
        '{"t": 0.1, "port": "Sensor.v", "value": 6.0}'], "--no-verify")
    expect(code == 3, f"exit {code}, expected 3", out, err)
    expect("100ms  assert Motor.cmd: pass -> emitted < 10.0 (line 5): 'pass' delivered 12.0 "
           "into Motor.cmd at 100ms, for which it is false" in out,
           "the assert over data is not said broken", out, err)
    code, out, err = run(arbc, DOUBLED, ['{"t": 0, "port": "Sensor.v", "value": 4.5}'],
                         "--no-verify")
    expect(code == 0 and "none broken" in out, f"exit {code} on a value the assert allows",
           out, err)


def case_stop_ends_the_run(arbc):
    # `--runtime-checks stop` ends the run at the first breach: what came after is not run.
    inputs = ['{"t": 0, "port": "Sensor.v", "value": 1.0}',
              '{"t": 0.1, "port": "Sensor.v", "value": 6.0}',
              '{"t": 0.5, "port": "Sensor.v", "value": 2.0}']
    code, out, err = run(arbc, DOUBLED, inputs, "--no-verify", "--duration", "2s", checks="stop")
    expect(code == 3, f"exit {code}, expected 3", out, err)
    expect("stopped: runtime check broken: assert Motor.cmd: pass -> emitted < 10.0 (line 5)"
           in out, "the run does not say it stopped at the breach", out, err)
    row = next((ln.split() for ln in out.splitlines() if ln.startswith("pass ")), None)
    expect(row is not None and row[1:3] == ["2", "2"],
           f"the run went on after the breach: {row}", out, err)
    # The same run under `fail` goes to its end.
    code, out, err = run(arbc, DOUBLED, inputs, "--no-verify", "--duration", "2s")
    row = next((ln.split() for ln in out.splitlines() if ln.startswith("pass ")), None)
    expect(code == 3 and "stopped:" not in out and row[1:3] == ["3", "3"],
           f"exit {code}, {row} under fail", out, err)


SHARED = """app shared "one arm, two ports, nothing keeps them apart: refuted, run anyway";
module Planner { out a: int; out b: int; }
module Arm { out status: list<string>; }
module Grip { in cmd: int; }
module Rake { in cmd: int; }
events from Arm.status { e_busy = "busy" } lifetime 10s;
arbitrate Grip.cmd { grip: from Planner.a when not e_busy; }
arbitrate Rake.cmd { rake: from Planner.b; }
resource arm { Grip.cmd, Rake.cmd } when emitted > 0;
"""


def case_resource_broken(arbc):
    # Two commands that use the arm, into both ports, in one event state.
    code, out, err = run(arbc, SHARED, [
        '{"t": 0.1, "port": "Planner.a", "value": 1}',
        '{"t": 0.2, "port": "Planner.b", "value": 2}'], "--no-verify")
    expect(code == 3, f"exit {code}, expected 3", out, err)
    expect("200ms  resource arm: 'grip' into Grip.cmd at 100ms and 'rake' into Rake.cmd at 200ms "
           "both delivered a command that uses it (1, 2) in one event state" in out,
           "the resource is not said broken", out, err)
    # A command its `when` says does not use it, or an event of its ports set in between (the
    # state changed: the proof's pairs are of one state), breaks nothing.
    for inputs in (['{"t": 0.1, "port": "Planner.a", "value": 1}',
                    '{"t": 0.2, "port": "Planner.b", "value": 0}'],
                   ['{"t": 0.1, "port": "Planner.a", "value": 1}',
                    '{"t": 0.15, "port": "Arm.status", "value": ["busy"]}',
                    '{"t": 0.2, "port": "Planner.b", "value": 2}']):
        code, out, err = run(arbc, SHARED, inputs, "--no-verify")
        expect(code == 0 and "none broken" in out, f"exit {code} on {inputs}", out, err)

def case_arbc_test_watches(arbc):
    # `arbc test` checks the same claims and assumptions on each test's run: a test that gives
    # both flags of the exclusive group leaves the proof, and fails unless told otherwise.
    tests = GRIPS + """
test "both grips" {
  at 0s    Arm.status <- ["left", "right"];
  at 100ms Planner.left <- 1.0;
  expect Hand.cmd receives 1.0 at 100ms;
}
"""
    with tempfile.TemporaryDirectory() as d:
        spec = os.path.join(d, "grips.spec")
        with open(spec, "w", encoding="utf-8") as f:
            f.write(tests)
        def test(*options):
            p = subprocess.run([arbc, "test", spec, *options], capture_output=True, text=True,
                               timeout=120)
            return p.returncode, p.stdout, p.stderr
        code, out, err = test()
        expect(code == 1 and "FAIL  " in out, f"exit {code}, expected 1", out, err)
        line = ("  runtime check: assumption exclusive { e_left, e_right } broken at 100ms: e_left "
                "and e_right present together in Hand.cmd at 100ms")
        expect(line in out, "the breach is not in the failure", out, err)
        code, out, err = test("--runtime-checks", "warn")
        expect(code == 0 and "PASS  " in out and line in out, f"warn: exit {code}", out, err)
        code, out, err = test("--runtime-checks", "off")
        expect(code == 0 and "runtime check" not in out, f"off: exit {code}", out, err)


RATED = """app rated "a response that relies on its source's rate";
module Scan { out range: float; }
module Base { in cmd: float; }
arbitrate Base.cmd { go: from Scan.range; }
given Scan.range every 100ms;
"""


def case_rate_broken(arbc):
    code, out, err = run(arbc, RATED, [
        '{"t": 0, "port": "Scan.range", "value": 1.0}',
        '{"t": 0.1, "port": "Scan.range", "value": 1.0}',
        '{"t": 0.5, "port": "Scan.range", "value": 1.0}'], "--duration", "500ms")
    expect(code == 3, f"exit {code}, expected 3", out, err)
    expect("200ms  assumption given Scan.range every 100ms: nothing from Scan.range between 100ms "
           "and 500ms" in out, "the rate's gap is not named", out, err)


def case_end_breach_in_trace(arbc):
    # A breach only the end of the run shows (the rate's last gap) is a trace line at the end,
    # and the report's table of runtime checks lists every check with this run's verdict.
    with tempfile.TemporaryDirectory() as d:
        trace, report = os.path.join(d, "t.jsonl"), os.path.join(d, "r.html")
        code, out, err = run(arbc, RATED, [
            '{"t": 0, "port": "Scan.range", "value": 1.0}',
            '{"t": 0.1, "port": "Scan.range", "value": 1.0}'], "--duration", "500ms",
            "--trace", trace, "--report", report)
        expect(code == 3, f"exit {code}, expected 3", out, err)
        with open(trace, encoding="utf-8") as f:
            lines = [json.loads(line) for line in f]
        breaches = [line for line in lines if line["type"] == "breach"]
        expect(breaches == [{"t": 0.5, "type": "breach",
                             "claim": "assumption given Scan.range every 100ms",
                             "message": "broken at 200ms: nothing from Scan.range between 100ms "
                                        "and 500ms"}], f"breach lines {breaches}", out, err)
        with open(report, encoding="utf-8") as f:
            html = f.read()
        expect('<table id="runtime-checks">' in html, "the report has no table of checks", out, err)
        rows = re.findall(r'<tr(?: class="broken")?><td>([^<]*)</td><td>([^<]*)</td>', html)
        expect(("Base.cmd: rules go are never selected together", "kept") not in rows and
               ("assumption given Scan.range every 100ms", "broken at 200.0 ms") in rows,
               f"the table's rows: {rows}", out, err)
    with tempfile.TemporaryDirectory() as d:
        report = os.path.join(d, "r.html")
        code, out, err = run(arbc, GRIPS, [
            '{"t": 0, "port": "Arm.status", "value": ["left"]}',
            '{"t": 0.1, "port": "Planner.left", "value": 1.0}'], "--report", report)
        expect(code == 0, f"exit {code}, expected 0", out, err)
        with open(report, encoding="utf-8") as f:
            html = f.read()
        rows = re.findall(r'<tr(?: class="broken")?><td>([^<]*)</td><td>([^<]*)</td>', html)
        expect(("assumption exclusive { e_left, e_right }", "kept") in rows and
               ("Hand.cmd: rules left, right are never selected together", "kept") in rows,
               f"the kept checks are not listed: {rows}", out, err)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    globals()["case_" + sys.argv[2]](os.path.abspath(sys.argv[1]))
    print("ok")


if __name__ == "__main__":
    main()
