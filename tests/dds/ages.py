#!/usr/bin/env python3
"""Message age on DDS (issue 41): stale commands rejected by their stamps, against plain Fast-DDS
programs.

stamped_ages (fastddsgen types of interop/Stamped.idl, no arbc in it) writes COUNT
TwistStampeds on rt/in/stamped, stamped with the wall clock: the odd ones now, the even ones
2 s ago; `arbc run ages --host none --mediate all --deploy interop/ages.deploy.json` passes on
those whose `age(cmd_vel.header.stamp)` is under 500 ms (interop/ages.spec, declared by
`use ros2`, no type in the deployment) to rt/out/stamped, where stamped_sub prints what it
receives. Every fresh command must reach the base, bit for bit and in order, and no stale one;
the mediator must count each stale one `rejected`.

With `sim`, the same under ROS 2 simulated time: stamped_ages also publishes /clock from 100 s
on (rosgraph_msgs/msg/Clock) and stamps with it, and the mediator runs with --use-sim-time. On
the wall clock every such stamp is decades old, so a fresh command passes only if age() reads
/clock.

usage: ages.py ARBC STAMPED_AGES STAMPED_SUB TESTS_DDS_DIR [sim]
"""
import os
import re
import signal
import subprocess
import sys

from dds_domain import Domain, environment, scratch_folder
from stamped import connection_rows, fail

COUNT = 20


def main():
    arbc, ages, sub, here = sys.argv[1:5]
    sim = sys.argv[5:] == ["sim"]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()
    domain = str(held.id)
    interop = os.path.join(here, "interop")
    out_dir = scratch_folder("arbc-dds-ages-")
    built = subprocess.run([arbc, "build", os.path.join(interop, "ages.spec"), "-o", out_dir],
                           capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    receiver = subprocess.Popen([sub, domain, "4", "60"], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, env=env)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "ages"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", os.path.join(interop, "ages.deploy.json"),
         "--domain", domain, "--duration", "100000s", "--wait-peers", "30"] +
        (["--use-sim-time"] if sim else []),
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    sender = subprocess.run([ages, domain, str(COUNT), "2000"] + (["100"] if sim else []),
                            capture_output=True, text=True, env=env, timeout=90)
    received, receiver_errors = receiver.communicate(timeout=90)
    mediator.send_signal(signal.SIGTERM)
    mediated, _ = mediator.communicate(timeout=30)
    if sender.returncode != 0:
        fail(f"stamped_ages exited {sender.returncode}", sender.stdout + sender.stderr, mediated)
    if receiver.returncode != 0:
        fail(f"stamped_sub exited {receiver.returncode}", receiver_errors, mediated)
    sent = sender.stdout.splitlines()
    fresh = [sent[i - 1] for i, line in enumerate(sent) if line.startswith("fresh ")]
    stale = [sent[i - 1] for i, line in enumerate(sent) if line.startswith("stale ")]
    got = [line for line in received.splitlines() if line.startswith("stamped ")]
    if len(fresh) + len(stale) != COUNT:
        fail(f"stamped_ages printed {len(fresh)} fresh and {len(stale)} stale samples", sender.stdout)
    if got != fresh:
        reached = sum(line in stale for line in got)
        fail(f"the base got {len(got)} commands, {reached} of them stale; {len(fresh)} were fresh",
             received, mediated)
    row = connection_rows(mediated).get("fresh")
    if not row or row["arrived"] != COUNT or row["delivered"] != len(fresh) or \
            row["rejected"] != len(stale):
        fail(f"the mediator's row for rule fresh is {row}: expected {COUNT} arrived, "
             f"{len(fresh)} delivered, {len(stale)} rejected", mediated)
    if "result: success" not in mediated:
        fail("the mediator's verdict is not success", mediated)
    # Keep-last 1, best effort (as rclcpp reads /clock): ticks that come together count once.
    clock = re.search(r"clock: \d+ samples on rt/clock, the last at ([0-9.]+)s", mediated)
    if sim and not (clock and float(clock.group(1)) >= 100 + (COUNT - 1) * 0.05):
        fail("the mediator did not read /clock up to the last sample's time", mediated)
    print(f"ok: {len(fresh)} fresh commands reached the base bit for bit, {len(stale)} stale ones "
          f"were rejected\n" + mediated)


if __name__ == "__main__":
    main()
