#!/usr/bin/env python3
"""A mediator's memory (`arbc run --state FILE`, runtime/mediator_memory.h): a mediator started
again goes on from what the last one delivered, and its runtime checks from what they saw.

usage: check_memory.py ARBC CASE        (run from the repository root)
  put_after_restart     a take, the mediator stopped and started again, then the put: delivered
                        with the memory (not with a fresh one), and `only put after take` holds;
  spacing_across        `never two go within 30s` is judged across the restart: a second `go`
                        right after it is a breach the restarted run names;
  broken_stays_broken   a claim broken before the restart is reported again after it;
  throttle_across       a throttle's period runs on across the restart;
  refuses               a file of another app, a file that is no memory, --state on simulated
                        time: exit 2, saying what to do.
"""
import os
import re
import subprocess
import sys
import tempfile

GRIP = """app grip "a take, then its put, across a mediator restart";
module Planner { out take: float; out put: float; }
module Arm { in cmd: string; }
event e_open = Arm.cmd : cmd == "take";
event e_busy = Arm.cmd : true for 30s;
arbitrate Arm.cmd {
  take: from Planner.take when not e_open and not e_busy { emit "take"; }
  put: from Planner.put when e_open { emit "put"; }
}
only put after take;
"""

SPACED = """app spaced "a spacing the rule does not enforce";
module Planner { out cmd: float; }
module Base { in cmd: float; }
arbitrate Base.cmd { go: from Planner.cmd; }
never two go within 30s;
"""


def expect(cond, what, out="", err=""):
    if not cond:
        sys.exit(f"FAIL: {what}\n--- stdout\n{out}\n--- stderr\n{err}")


class App:
    def __init__(self, arbc, spec_text, d, name, proved=True):
        self.arbc, self.d, self.proved = arbc, d, proved
        spec = os.path.join(d, name + ".spec")
        with open(spec, "w", encoding="utf-8") as f:
            f.write(spec_text)
        # An app whose property the proof refutes is built and run without the proof: its run
        # is what shows the breach.
        built = subprocess.run([arbc, "build", spec, "-o", os.path.join(d, "out")] +
                               ([] if proved else ["--no-verify"]),
                               capture_output=True, text=True, timeout=120)
        expect(built.returncode == 0, "arbc build failed", built.stdout, built.stderr)
        self.dir = os.path.join(d, "out", name)

    def run(self, inputs, state, *options, clock=("--realtime",)):
        path = os.path.join(self.d, "in.jsonl")
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(inputs) + "\n")
        proc = subprocess.run([self.arbc, "run", self.dir, "--inputs", path, *clock,
                               "--duration", "300ms", "--state", state, *options] +
                              ([] if self.proved else ["--no-verify"]),
                              capture_output=True, text=True, timeout=120)
        return proc.returncode, proc.stdout, proc.stderr


def row(out, connection):
    """(arrived, delivered, rejected, no-value, not-selected) of `connection` in the table."""
    for line in out.splitlines():
        words = line.split()
        if words and words[0] == connection:
            return tuple(int(w) for w in words[1:6])
    sys.exit(f"FAIL: no row for {connection}\n{out}")


def take_then_put(app, state):
    code, out, err = app.run(['{"t": 0.1, "port": "Planner.take", "value": 1.0}'], state)
    expect(code == 0 and row(out, "take")[1] == 1, f"the take: exit {code}", out, err)
    return app.run(['{"t": 0.1, "port": "Planner.put", "value": 1.0}'], state)


def case_put_after_restart(arbc):
    with tempfile.TemporaryDirectory() as d:
        app = App(arbc, GRIP, d, "grip")
        state = os.path.join(d, "memory.json")
        code, out, err = take_then_put(app, state)
        expect(code == 0, f"exit {code} after the restart", out, err)
        expect(row(out, "put")[1] == 1, "the put was not delivered after the restart", out, err)
        expect("restored the memory in " + state in err and "e_open at Arm.cmd" in err and
               "e_busy at Arm.cmd for " in err, "the restart does not say what it restored", out, err)
        expect("none broken" in out, "`only put after take` judged broken across the restart",
               out, err)
        # e_busy's 30 s ran on while no mediator was up: the take was at 100 ms and the first
        # run lasted 300 ms, so at most 29.8 s of it can be left.
        left = re.search(r"e_busy at Arm.cmd for ([\d.]+)s", err)
        expect(left and float(left.group(1)) <= 29.8,
               "e_busy's lifetime did not run on while no mediator was up", out, err)
        # Without the memory the mediator starts afresh: the put waits for a take that already
        # happened (what deadlocked table_clean's arm when its mediator was killed mid-cycle).
        code, out, err = app.run(['{"t": 0.1, "port": "Planner.put", "value": 1.0}'],
                                 os.path.join(d, "fresh.json"))
        expect(code == 0 and row(out, "put")[4] == 1, "a fresh mediator delivered the put", out,
               err)


def case_spacing_across(arbc):
    with tempfile.TemporaryDirectory() as d:
        app = App(arbc, SPACED, d, "spaced", proved=False)
        state = os.path.join(d, "memory.json")
        go = ['{"t": 0.1, "port": "Planner.cmd", "value": 1.0}']
        code, out, err = app.run(go, state)
        expect(code == 0 and "none broken" in out, f"first run: exit {code}", out, err)
        code, out, err = app.run(go, state)
        expect(code == 3, f"exit {code}, expected 3: two go within 30s across the restart", out,
               err)
        expect("never two go within 30s: 'go' delivered at -" in out,
               "the breach does not name the delivery before the restart", out, err)
        # A third run: the claim stays broken, said at the start of the run.
        code, out, err = app.run([], state)
        expect(code == 3 and "never two go within 30s: broken before this mediator started "
               "again" in out, f"the broken claim was not carried: exit {code}", out, err)


THROTTLED = """app throttled "one command per 30 s, across restarts";
module Planner { out cmd: float; }
module Base { in cmd: float; }
arbitrate Base.cmd { go: from Planner.cmd { throttle 30s; } }
"""


def case_throttle_across(arbc):
    # A throttle's period runs on from the last delivery before the restart.
    with tempfile.TemporaryDirectory() as d:
        app = App(arbc, THROTTLED, d, "throttled")
        state = os.path.join(d, "memory.json")
        go = ['{"t": 0.1, "port": "Planner.cmd", "value": 1.0}']
        code, out, err = app.run(go, state)
        expect(code == 0 and row(out, "go")[1] == 1, f"first run: exit {code}", out, err)
        code, out, err = app.run(go, state)
        expect(code == 0 and row(out, "go")[1] == 0, "a command within 30 s of the last one, "
               "across a restart, was not throttled", out, err)
        code, out, err = app.run(go, os.path.join(d, "fresh.json"))
        expect(code == 0 and row(out, "go")[1] == 1, "a fresh mediator throttled", out, err)


def case_broken_stays_broken(arbc):
    # The same as the end of spacing_across, from a breach within one run.
    with tempfile.TemporaryDirectory() as d:
        app = App(arbc, SPACED, d, "spaced", proved=False)
        state = os.path.join(d, "memory.json")
        code, out, err = app.run(['{"t": 0, "port": "Planner.cmd", "value": 1.0}',
                                  '{"t": 0.1, "port": "Planner.cmd", "value": 1.0}'], state,
                                 "--runtime-checks", "warn")
        expect(code == 0 and "1 of 1 broken" in out, f"first run: exit {code}", out, err)
        code, out, err = app.run([], state)
        expect(code == 3 and "broken before this mediator started again" in out,
               f"exit {code}: the breach before the restart was forgotten", out, err)


def case_refuses(arbc):
    with tempfile.TemporaryDirectory() as d:
        grip = App(arbc, GRIP, os.path.join(d), "grip")
        state = os.path.join(d, "memory.json")
        code, out, err = grip.run(['{"t": 0.1, "port": "Planner.take", "value": 1.0}'], state)
        expect(code == 0, f"exit {code}", out, err)
        os.makedirs(os.path.join(d, "b"))
        other = App(arbc, GRIP.replace("30s", "20s"), os.path.join(d, "b"), "grip")
        code, out, err = other.run([], state)
        expect(code == 2 and "written by a run of another build of app 'grip'" in err and
               "remove it to start this mediator with no memory" in err,
               f"another build's memory: exit {code}", out, err)
        with open(state, "w", encoding="utf-8") as f:
            f.write("[1, 2")
        code, out, err = grip.run([], state)
        expect(code == 2 and "not a memory file of `arbc run --state`" in err,
               f"a file that is no memory: exit {code}", out, err)
        code, out, err = grip.run([], state, clock=())
        expect(code == 2 and "a mediator's memory is for runs on the wall clock" in err,
               f"--state on simulated time: exit {code}", out, err)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    globals()["case_" + sys.argv[2]](os.path.abspath(sys.argv[1]))
    print("ok")


if __name__ == "__main__":
    main()
