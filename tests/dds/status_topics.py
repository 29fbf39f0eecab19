#!/usr/bin/env python3
"""The DDS mediator's live status (issue 42, docs/distributed.md#live-status), read by a program
with no arbc in it (diag_sub, fastddsgen types of diagnostic_msgs).

interop_pub runs the teleop script through a mediator of interop/teleop.spec (interop.py says
what): nav, then the joystick with its 2 s hold over nav, then nav again. diag_sub listens to
the mediator's latched status topic of Base.cmd_vel and to /diagnostics from the start; a second
diag_sub joins after the script, and reads the last status although it was written before it
joined (transient local). The status must name nav selected with joy waiting, then joy selected
with nav held by joy's hold, then nav again; /diagnostics must come about once a second with
counters that end at what the base received.

usage: status_topics.py ARBC INTEROP_PUB INTEROP_SUB DIAG_SUB TESTS_DDS_DIR
"""
import os
import re
import signal
import subprocess
import sys
import time

from dds_domain import Domain, environment
from teleop_app import build_teleop

STATUS_TOPIC = "rt/arbc/teleop/status/Base/cmd_vel"


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def statuses(lines):
    """(time, level, message, {key: value}) of each status line of diag_sub."""
    out = []
    for line in lines:
        m = re.match(r"([0-9.]+) status (\d+)\|([^|]*)\|([^|]*)\|(.*)$", line)
        if m:
            values = dict(kv.split("=", 1) for kv in m.group(5).split(";") if kv)
            out.append((float(m.group(1)), int(m.group(2)), m.group(4), values))
    return out


def diagnostics(lines):
    """(time, {key: value} of Base.cmd_vel's status) of each diagnostics line."""
    out = []
    for line in lines:
        m = re.match(r"([0-9.]+) diagnostics [0-9.]+\|teleop: Base.cmd_vel \d [^{]*\{(.*)\}$", line)
        if m:
            out.append((float(m.group(1)),
                        dict(kv.split("=", 1) for kv in m.group(2).split(";") if kv)))
    return out


def check_sequence(seen, mediated):
    """The states the script goes through, in order."""
    want = [("nav", "rule joy", "may deliver"),
            ("joy", "rule nav", "held by joy's hold"),
            ("nav", "rule joy", "may deliver")]
    at = 0
    for _, _, _, values in seen:
        selected, key, state = want[at]
        if values.get("selected") == selected and values.get(key, "").startswith(state):
            at += 1
            if at == len(want):
                return
    fail(f"the status did not go through {want} (reached {at}): " + repr(seen), mediated)


def main():
    arbc, pub, sub, diag, here = sys.argv[1:6]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = build_teleop(arbc, here, "arbc-dds-status-")
    watcher = subprocess.Popen([diag, domain, STATUS_TOPIC, "4", "60", "diagnostics"],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    receiver = subprocess.Popen([sub, domain, "6", "60"], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, env=env)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "teleop"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", os.path.join(here, "interop", "teleop.deploy.json"),
         "--domain", domain, "--duration", "100000s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    sender = subprocess.run([pub, domain], capture_output=True, text=True, env=env, timeout=90)
    received, _ = receiver.communicate(timeout=90)
    time.sleep(1)  # a status or two after the last command
    late = subprocess.run([diag, domain, STATUS_TOPIC, "1", "10"], capture_output=True,
                          text=True, env=env, timeout=30)
    shown = subprocess.run([arbc, "status", "--domain", domain], capture_output=True, text=True,
                           env=env, timeout=30)
    mediator.send_signal(signal.SIGTERM)
    mediated, _ = mediator.communicate(timeout=15)
    gone = subprocess.run([arbc, "status", "--domain", domain, "--wait", "1.5s"],
                          capture_output=True, text=True, env=env, timeout=30)
    watched, _ = watcher.communicate(timeout=30)
    if sender.returncode != 0:
        fail(f"interop_pub exited {sender.returncode}", sender.stdout + sender.stderr, mediated)
    delivered = len([line for line in received.splitlines()[1:] if line.strip()])
    if delivered != 30:
        fail(f"the base received {delivered} commands, the script makes 30", received, mediated)

    seen = statuses(watched.splitlines())
    check_sequence(seen, watched + mediated)
    if any(seen[i][3] == seen[i + 1][3] and seen[i][2] == seen[i + 1][2]
           for i in range(len(seen) - 1)):
        fail("a status was written again unchanged (it is written only when it changes)", watched)

    # A subscriber that joins late reads the last status at once: nav selected.
    last = statuses(late.stdout.splitlines())
    if len(last) != 1 or last[0][3].get("selected") != "nav" or last[0][2] != "nav selected":
        fail("the late subscriber did not read the latched status 'nav selected'",
             late.stdout + late.stderr, mediated)

    # `arbc status` shows the running mediator's port; with none running it says so (exit 3).
    want = "teleop: Base.cmd_vel  OK  nav selected | joy: may deliver  [30 of "
    if shown.returncode != 0 or not shown.stdout.startswith(want):
        fail(f"`arbc status` (exit {shown.returncode}) did not show '{want}...'",
             shown.stdout + shown.stderr)
    if gone.returncode != 3 or "no arbc mediator's status on /diagnostics" not in gone.stderr:
        fail(f"`arbc status` with no mediator running: exit {gone.returncode}",
             gone.stdout + gone.stderr)

    diag = diagnostics(watched.splitlines())
    if len(diag) < 4:
        fail(f"{len(diag)} /diagnostics messages in a run of several seconds", watched)
    gaps = [b[0] - a[0] for a, b in zip(diag, diag[1:])]
    if not all(0.6 <= g <= 1.6 for g in gaps):
        fail(f"/diagnostics came at gaps {gaps}, not about once a second", watched)
    counts = [int(values["delivered"]) for _, values in diag]
    if counts != sorted(counts) or counts[-1] != 30:
        fail(f"the delivered counter went {counts}; the base received 30", watched)
    if "dropped not-selected" not in diag[-1][1] or "arrived" not in diag[-1][1]:
        fail("the last /diagnostics lacks the arrived and not-selected counters", watched)
    print(f"ok: {len(seen)} status changes, {len(diag)} diagnostics at gaps "
          f"{min(gaps):.2f}..{max(gaps):.2f} s, the late subscriber read 'nav selected'")


if __name__ == "__main__":
    main()
