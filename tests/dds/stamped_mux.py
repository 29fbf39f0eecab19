#!/usr/bin/env python3
"""twist_mux over TwistStamped against plain Fast-DDS programs (issue 41, "Done means"): the
joystick over navigation with a hold, commands older than 200 ms rejected by `age`.

stamped_mux (fastddsgen types of interop/Stamped.idl, no arbc in it) writes navigation's
commands every 50 ms on rt/in/nav and the joystick's on rt/in/joy, stamped with the wall clock,
some 2 s old; `arbc run stamped_mux --host none --mediate all` (interop/stamped_mux.spec:
joystick `hold 500ms` over navigation, both `accept age(...) < 200ms`) passes them on to
rt/out/stamped, where stamped_sub prints what it receives. Judged from the send times the
program prints, with 150 ms of slack each side for a loaded machine:

- no stale command reaches the base, and the mediator counts each one `rejected`;
- every fresh joystick command reaches it;
- a fresh navigation command reaches it when no fresh joystick command was sent in the 650 ms
  before it (nor in the 150 ms after), and does not when one was sent 1 to 350 ms before it;
- what reaches the base, each source's commands in the order sent, bit for bit.

The last joystick command is stale: navigation must resume after the hold, not stay held off.

usage: stamped_mux.py ARBC STAMPED_MUX STAMPED_SUB TESTS_DDS_DIR
"""
import os
import signal
import subprocess
import sys

from dds_domain import Domain, environment, scratch_folder
from stamped import connection_rows, fail

TICKS = 70
HOLD_MS, SLACK_MS = 500, 150


class Sample:
    def __init__(self, header, line):
        _, self.source, tick, self.freshness, ms = header.split()
        self.tick, self.ms, self.line = int(tick), int(ms), line


def sent_samples(output):
    lines = output.splitlines()
    return [Sample(lines[i], lines[i + 1]) for i in range(len(lines) - 1)
            if lines[i].startswith("sent ")]


def expected(samples):
    """Each sample's fate: "base" (must reach it), "never" or "either"."""
    joys = [s.ms for s in samples if s.source == "joy" and s.freshness == "fresh"]
    out = {}
    for s in samples:
        if s.freshness == "stale":
            out[s.line] = "never"
        elif s.source == "joy":
            out[s.line] = "base"
        elif any(0 < s.ms - j < HOLD_MS - SLACK_MS for j in joys):
            out[s.line] = "never"
        elif all(s.ms - j > HOLD_MS + SLACK_MS or j - s.ms > SLACK_MS for j in joys):
            out[s.line] = "base"
        else:
            out[s.line] = "either"
    return out


def run(arbc, mux, sub, here, domain, env):
    interop = os.path.join(here, "interop")
    out_dir = scratch_folder("arbc-dds-stamped-mux-")
    built = subprocess.run([arbc, "build", os.path.join(interop, "stamped_mux.spec"), "-o",
                            out_dir], capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    receiver = subprocess.Popen([sub, domain, "4", "60"], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, env=env)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "stamped_mux"), "--transport", "dds", "--host",
         "none", "--mediate", "all", "--deploy", os.path.join(interop, "stamped_mux.deploy.json"),
         "--domain", domain, "--duration", "100000s", "--wait-peers", "30"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    sender = subprocess.run([mux, domain, str(TICKS), "2000"], capture_output=True, text=True,
                            env=env, timeout=90)
    received, receiver_errors = receiver.communicate(timeout=90)
    mediator.send_signal(signal.SIGTERM)
    mediated, _ = mediator.communicate(timeout=30)
    if sender.returncode != 0:
        fail(f"stamped_mux exited {sender.returncode}", sender.stdout + sender.stderr, mediated)
    if receiver.returncode != 0:
        fail(f"stamped_sub exited {receiver.returncode}", receiver_errors, mediated)
    return sender.stdout, received, mediated


def judge(samples, got, mediated):
    fate = expected(samples)
    problems = [f"{s.source} {s.freshness} command of tick {s.tick} (sent at {s.ms} ms) "
                f"{'did not reach' if fate[s.line] == 'base' else 'reached'} the base"
                for s in samples if fate[s.line] != "either" and
                (fate[s.line] == "base") != (s.line in got)]
    unknown = [line for line in got if line not in fate]
    if unknown:
        problems.append(f"{len(unknown)} commands reached the base that were never sent "
                        f"(altered on the way?), first: {unknown[0]}")
    for source in ("nav", "joy"):
        order = [s.line for s in samples if s.source == source and s.line in got]
        if order != [line for line in got if line in order]:
            problems.append(f"{source}'s commands reached the base out of the order sent")
    rows = connection_rows(mediated)
    for rule, source in (("joystick", "joy"), ("navigation", "nav")):
        mine = [s for s in samples if s.source == source]
        stale = sum(s.freshness == "stale" for s in mine)
        reached = sum(s.line in got for s in mine)
        row = rows.get(rule) or {}
        if row.get("arrived") != len(mine) or row.get("rejected") != stale or \
                row.get("delivered") != reached:
            problems.append(f"the mediator's row for {rule} is {row}: expected {len(mine)} "
                            f"arrived, {reached} delivered, {stale} rejected")
    return problems, fate


def main():
    arbc, mux, sub, here = sys.argv[1:5]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    sent, received, mediated = run(arbc, mux, sub, here, str(held.id), env)
    samples = sent_samples(sent)
    if len(samples) != TICKS + 11:
        fail(f"stamped_mux printed {len(samples)} samples, not {TICKS + 11}", sent)
    got = [line for line in received.splitlines() if line.startswith("stamped ")]
    problems, fate = judge(samples, got, mediated)
    for p in problems:
        print("FAIL: " + p)
    if problems:
        fail(f"{len(problems)} problem(s)", received, mediated)
    if "result: success" not in mediated:
        fail("the mediator's verdict is not success", mediated)
    counts = {k: sum(v == k for v in fate.values()) for k in ("base", "never", "either")}
    print(f"ok: {len(samples)} commands; {counts['base']} reached the base as they must, "
          f"{counts['never']} did not (6 stale, the rest held off by the joystick), "
          f"{counts['either']} near a hold's edge were not judged\n" + mediated)


if __name__ == "__main__":
    main()
