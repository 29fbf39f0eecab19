#!/usr/bin/env python3
"""A bumper stops a planner (tests/dds/interop/bumper.spec), all three plain Fast-DDS programs:
interop_stream publishes Twists on rt/nav/cmd_vel every 20 ms, interop_bumper a
std_msgs/msg/Bool on rt/bumper every 50 ms, best effort (ROS 2's sensor-data profile), pressed
for 1 s in the middle of 5 s, and interop_sub reads rt/cmd_vel. A spec `bool` travels as
std_msgs/msg/Bool (docs/distributed.md#types-on-the-wire); the deployment gives the bumper's
port best effort ("qos": {"ports": ...}).

What the base receives must be what the spec says: every command the mediator wrote, commands
before and after the press, and none for at least the 1 s press (the event lasts 500 ms more);
the mediator reads the bumper's samples without a mismatch or an undecodable one.

usage: bumper.py ARBC INTEROP_STREAM INTEROP_SUB INTEROP_BUMPER TESTS_DDS_DIR
"""
import os
import re
import signal
import subprocess
import sys

from dds_domain import Domain, environment, scratch_folder


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def main():
    arbc, stream, sub, bumper, here = sys.argv[1:6]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = scratch_folder("arbc-dds-bumper-")
    interop = os.path.join(here, "interop")
    built = subprocess.run([arbc, "build", os.path.join(interop, "bumper.spec"), "-o", out_dir],
                           capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "bumper"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", os.path.join(interop, "bumper.deploy.json"),
         "--domain", domain, "--wait-peers", "20", "--duration", "100000s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    base = subprocess.Popen([sub, domain, "2", "30"], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, env=env)
    planner = subprocess.Popen([stream, domain, "20"], env=env)
    pressed = subprocess.run([bumper, domain], capture_output=True, text=True, env=env,
                             timeout=60)
    planner.kill()
    planner.wait()
    heard, _ = base.communicate(timeout=60)
    mediator.send_signal(signal.SIGTERM)
    said, _ = mediator.communicate(timeout=60)
    if pressed.returncode != 0:
        fail(f"interop_bumper exits {pressed.returncode}", pressed.stdout + pressed.stderr)
    for wrong in ("mismatch", "does not decode", "bytes more than"):
        if wrong in said:
            fail(f"the mediator says {wrong!r}", said)
    bumps = re.search(r"read  rt/bumper \(std_msgs::msg::dds_::Bool_\): (\d+) received, "
                      r"\d+ lost, 0 undecodable", said)
    if not bumps or int(bumps.group(1)) < 50:
        fail("the mediator did not read the bumper's samples", said)
    written = re.search(r"wrote rt/cmd_vel \(geometry_msgs::msg::dds_::Twist_\): (\d+) written",
                        said)
    numbers = [float(x) for x in heard.splitlines()[1:]]
    if not written or int(written.group(1)) != len(numbers):
        fail(f"the base heard {len(numbers)} commands, not what the mediator wrote", said, heard)
    # The commands are numbered every 20 ms: the press (1 s, and 500 ms of the event's life)
    # is the widest gap, with commands on both sides.
    gaps = [(b - a, a, b) for a, b in zip(numbers, numbers[1:])]
    widest = max(gaps, default=(0, 0, 0))
    if widest[0] < 50 or widest[1] == numbers[0] or widest[2] == numbers[-1]:
        fail(f"no stop of 1 s or more between commands (widest gap {widest})", said, heard)
    print(f"ok: {len(numbers)} commands, none from {widest[1]:g} to {widest[2]:g} "
          f"({widest[0] * 0.02:.2f} s); bumper samples read: {bumps.group(1)}")


if __name__ == "__main__":
    main()
