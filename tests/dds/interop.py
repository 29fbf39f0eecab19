#!/usr/bin/env python3
"""An arbc mediator between programs that have no arbc in them (docs/distributed.md).

interop_pub (fastddsgen types, plain Fast-DDS) publishes ROS 2 Twists on rt/joy/cmd_vel and
rt/nav/cmd_vel; `arbc run teleop.spec --host none --mediate all --deploy teleop.deploy.json`
arbitrates them by priority into rt/cmd_vel; interop_sub prints what it receives there. The
subscriber must receive exactly what the rules select, in order: nav 1..10 (the resting
joystick message is not accepted), joy 101..110 (nav 201..210 held off by joy's hold), and
nav 301..310 once the hold is over.

usage: interop.py ARBC INTEROP_PUB INTEROP_SUB TESTS_DDS_DIR
"""
import os
import signal
import subprocess
import sys

from dds_domain import Domain, environment
from teleop_app import build_teleop

EXPECTED = list(range(1, 11)) + list(range(101, 111)) + list(range(301, 311))


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def main():
    arbc, pub, sub, here = sys.argv[1:5]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = build_teleop(arbc, here, "arbc-dds-interop-")
    receiver = subprocess.Popen([sub, domain, "6", "60"], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, env=env)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "teleop"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", os.path.join(here, "interop", "teleop.deploy.json"),
         "--domain", domain, "--duration", "100000s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    sender = subprocess.run([pub, domain], capture_output=True, text=True, env=env, timeout=90)
    received, _ = receiver.communicate(timeout=90)
    mediator.send_signal(signal.SIGTERM)
    mediated, _ = mediator.communicate(timeout=15)
    if sender.returncode != 0:
        fail(f"interop_pub exited {sender.returncode}", sender.stdout + sender.stderr, mediated)
    got = [int(float(line)) for line in received.splitlines()[1:] if line.strip()]
    if got != EXPECTED:
        fail(f"the subscriber received {got}, the rules select {EXPECTED}", mediated)
    if mediator.returncode != 0 or "interrupted (SIGTERM)" not in mediated:
        fail(f"the mediator did not end cleanly on SIGTERM (exit {mediator.returncode})", mediated)
    for line in ("geometry_msgs::msg::dds_::Twist_", "rt/joy/cmd_vel", "rt/cmd_vel"):
        if line not in mediated:
            fail(f"the mediator's summary does not name {line}", mediated)
    print("ok: the subscriber received exactly what the rules select\n" + mediated)


if __name__ == "__main__":
    main()
