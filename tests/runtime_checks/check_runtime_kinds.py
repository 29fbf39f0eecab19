#!/usr/bin/env python3
"""`arbc run` watches every kind of claim and assumption (issue 39, docs/runtime.md#runtime-checks):
for each property over time (docs/language.md#properties-over-time), each environment assumption
and `invariant`, a run that breaks it ends in failure (exit 3) naming it and the instant, and a
run that keeps it ends in success. The specs state what their rules do not enforce and run with
--no-verify where the proof refutes the property (a refuted claim is what a run can break).

usage: check_runtime_kinds.py ARBC CASE        (run from the repository root)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_runtime_checks import expect, run  # noqa: E402

# take and put never selected together (e_taken); nothing orders or spaces them in time.
ARM = """app arm "a claim the rules do not enforce";
module Arm {{ out status: list<string>; }}
module Planner {{ out a: float; out b: float; }}
module Base {{ in cmd: float; }}
events from Arm.status {{ e_taken = "taken", e_busy = "busy" }} lifetime 10s;
arbitrate Base.cmd {{
  take: from Planner.a when {take_when};
  put: from Planner.b when e_taken;
}}
{claim}
"""


def status(t, *flags):
    return '{"t": %s, "port": "Arm.status", "value": [%s]}' % (
        t, ", ".join('"%s"' % f for f in flags))


def take(t):
    return '{"t": %s, "port": "Planner.a", "value": 1.0}' % t


def put(t):
    return '{"t": %s, "port": "Planner.b", "value": 2.0}' % t


# A take, the arm reporting it holds the object, a put: each rule delivers once.
TAKE_THEN_PUT = [take(0.1), status(0.2, "taken"), put(0.3)]


def check(arbc, claim, broken, said, kept, verify=False, take_when="not e_taken"):
    """`claim` added to ARM: the run of `broken` exits 3 with the line `said` (instant, claim,
    what the run did) and names the claim in its verdict; the run of `kept` exits 0. A claim
    about e_busy that no property reads needs take_when to read it (so it is fed into Base.cmd)."""
    spec = ARM.format(claim=claim, take_when=take_when)
    options = ["--duration", "3s"] + ([] if verify else ["--no-verify"])
    code, out, err = run(arbc, spec, broken, *options)
    expect(code == 3, f"{claim}: exit {code} on a run that breaks it, expected 3", out, err)
    expect(said in out, f"{claim}: the breach is not said as {said!r}", out, err)
    name = claim.rstrip(";")
    expect(f"result: failure (runtime checks: " in out and name in out.split("result:")[-1],
           f"{claim}: the verdict does not name it", out, err)
    code, out, err = run(arbc, spec, kept, *options)
    expect(code == 0 and "none broken" in out,
           f"{claim}: exit {code} on a run that keeps it, expected 0", out, err)


# Properties over time: each form of docs/language.md#properties-over-time but `never two ...
# within` (check_runtime_checks.py, property_broken).

def case_absence_broken(arbc):
    check(arbc, "never take while e_busy;", [status(0, "busy"), take(0.1)],
          "100ms  never take while e_busy: 'take' delivered at 100ms with e_busy present",
          [status(0, "busy"), status(0.05), take(0.1)])


def case_precedence_broken(arbc):
    check(arbc, "only put after take;", [status(0, "taken"), put(0.3)],
          "300ms  only put after take: 'put' delivered at 300ms with no delivery of 'take' since "
          "its last", TAKE_THEN_PUT)


def case_response_broken(arbc):
    # The window ends with no put: said at its end, once the run reaches it.
    check(arbc, "after take, put within 500ms;", [take(0.1)],
          "600ms  after take, put within 500ms: triggered at 100ms, no delivery of 'put' by 600ms",
          TAKE_THEN_PUT)


def case_response_while_excuses(arbc):
    # `while C`: a decision of put's in the window with C false excuses the window.
    check(arbc, "after take, put within 500ms while e_taken;", [take(0.1), status(0.2, "taken")],
          "600ms  after take, put within 500ms while e_taken: triggered at 100ms, no delivery of "
          "'put' by 600ms", [take(0.1), put(0.3)])


def case_response_stops_broken(arbc):
    # After the *last* take: the second take at 300ms starts the window again.
    check(arbc, "after take stops, put within 500ms;", [take(0.1), take(0.3)],
          "800ms  after take stops, put within 500ms: triggered at 300ms, no delivery of 'put' by "
          "800ms", [take(0.1), take(0.3), status(0.35, "taken"), put(0.7)])


def case_response_event_broken(arbc):
    # Each time e_busy becomes present in Base.cmd, a put within 500ms.
    check(arbc, "after e_busy, put within 500ms;",
          [status(0.2, "taken"), status(0.4, "taken", "busy")],
          "900ms  after e_busy, put within 500ms: triggered at 400ms, no delivery of 'put' by 900ms",
          [status(0.2, "taken"), status(0.4, "taken", "busy"), put(0.5)])


def case_response_port_broken(arbc):
    # Any rule of the port answers: here put.
    check(arbc, "after take, Base.cmd within 500ms;", [take(0.1)],
          "600ms  after take, Base.cmd within 500ms: triggered at 100ms, no delivery of Base.cmd "
          "by 600ms", TAKE_THEN_PUT)


def case_spacing_after_broken(arbc):
    check(arbc, "never put within 1s after take;", TAKE_THEN_PUT,
          "300ms  never put within 1s after take: 'put' delivered at 300ms, 'take' at 100ms",
          [take(0.1), status(0.2, "taken"), put(1.2)])


def case_stability_broken(arbc):
    # take -> put at 300ms, put -> take at 500ms: two switches 200ms apart.
    check(arbc, "stable Base.cmd for 1s;", TAKE_THEN_PUT + [status(0.4), take(0.5)],
          "500ms  stable Base.cmd for 1s: the deliverer switched at 300ms and at 500ms",
          TAKE_THEN_PUT + [status(0.4), take(1.4)])


# Assumptions about what the environment reports (docs/language.md#environment-assumptions),
# and invariants: the proof holds with them (no --no-verify), the run breaks them.

def case_only_after_broken(arbc):
    # The arm says it holds an object no take gave it.
    check(arbc, "assume e_taken only after take;", [status(0, "taken"), take(0.1)],
          "0s  assumption assume e_taken only after take: e_taken present in Base.cmd at 0s "
          "(reported by feed_Arm_status) with no delivery of 'take'", TAKE_THEN_PUT, verify=True)


def case_only_after_until_broken(arbc):
    # After the put, the arm still says it holds it.
    check(arbc, "assume e_taken only after take until put;",
          TAKE_THEN_PUT + [status(0.4, "taken"), put(0.5)],
          "400ms  assumption assume e_taken only after take until put: e_taken present in Base.cmd "
          "at 400ms (reported by feed_Arm_status) with no delivery of 'take' since the last of "
          "'put'", TAKE_THEN_PUT + [status(0.4), take(0.5)], verify=True)


def case_absent_for_broken(arbc):
    # The arm says busy 200ms after a take it promised to answer for a second.
    check(arbc, "assume not e_busy for 1s after take;",
          [take(0.1), status(0.3, "busy"), take(0.4)],
          "300ms  assumption assume not e_busy for 1s after take: e_busy present in Base.cmd at "
          "300ms (reported by feed_Arm_status), 200ms after 'take' delivered",
          [take(0.1), status(1.3, "busy"), take(1.4)], verify=True,
          take_when="not e_taken and not e_busy")


def case_invariant_broken(arbc):
    check(arbc, "invariant not (e_taken and e_busy);", [status(0, "taken", "busy"), put(0.1)],
          "100ms  assumption invariant not (e_taken and e_busy): false in Base.cmd at 100ms "
          "(events present: e_busy, e_taken)", [status(0, "taken"), put(0.1)], verify=True,
          take_when="not e_taken and not e_busy")


# An invariant over events no rule reads: no container holds them, no proof rests on it. The run
# says it is not watched, rather than count it kept; one that mentions an event read in a port
# and one that is not is judged there as that port's proof reads it (the other may be anything).
UNREAD = """app unread "invariants over events the rules read or not";
module Arm { out status: list<string>; }
module Planner { out cmd: float; out other: float; }
module Hand { in cmd: float; }
module Leg { in cmd: float; }
events from Arm.status { e_a = "a", e_b = "b", e_c = "c", e_d = "d" } lifetime 1s;
invariant not (e_c and e_d);
invariant e_a or e_b;
arbitrate Hand.cmd { go: from Planner.cmd when e_a; }
arbitrate Leg.cmd { walk: from Planner.other; }
"""


def case_invariant_unread(arbc):
    inputs = [status(0, "b", "c", "d"), '{"t": 0.1, "port": "Planner.cmd", "value": 1.0}',
              '{"t": 0.1, "port": "Planner.other", "value": 1.0}']
    code, out, err = run(arbc, UNREAD, inputs)
    # `e_a or e_b` with only b reported holds in the world; Hand.cmd's container has no e_b and
    # Leg.cmd's none of them, which must not read as a breach.
    expect(code == 0, f"exit {code}: a true invariant read as broken", out, err)
    expect("runtime checks: 1 claim or assumption of the proof watched, none broken" in out,
           "`e_a or e_b` is not watched where e_a is read", out, err)
    expect("runtime checks: not watched: assumption invariant not (e_c and e_d): no port is fed "
           "e_c, e_d (no rule or assert reads them), so no proof rests on it and no run can see "
           "it broken" in out, "the unwatched invariant is not said", out, err)
    # Where e_a is read, `e_a or e_b` is false only if no value of e_b makes it true: never.
    # `e_a and e_b`, though, needs e_a: without it, it is broken whatever e_b is.
    spec = UNREAD.replace("invariant e_a or e_b;", "invariant e_a and (e_b or not e_b);")
    code, out, err = run(arbc, spec, inputs[1:])
    expect(code == 3 and "100ms  assumption invariant e_a and (e_b or not e_b): false in Hand.cmd "
           "at 100ms (events present: none; whatever e_b, not fed into Hand.cmd, may be)" in out,
           f"exit {code}: the invariant is not judged where e_a is read", out, err)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    globals()["case_" + sys.argv[2]](os.path.abspath(sys.argv[1]))
    print("ok")


if __name__ == "__main__":
    main()
