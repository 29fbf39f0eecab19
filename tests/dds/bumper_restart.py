#!/usr/bin/env python3
"""A mediator killed and restarted while the bumper is held (issue 39, restarts): three plain
Fast-DDS programs (tests/dds/interop/bumper.spec) with the bumper pressed the whole time, best
effort at 20 Hz, and the planner publishing every 20 ms. The mediator is started, left to run,
killed (SIGKILL) and started again, CYCLES times. The base must receive nothing: after each start
e_bumped is unknown until the bumper's feed speaks (docs/design.md#unknown-events-after-a-start),
and when it speaks it says pressed. The time since the start is no evidence: a mediator that
took "unknown" for "absent" once the event's lifetime (500 ms) had passed let nav through
whenever the bumper's publisher was discovered late.

usage: bumper_restart.py ARBC INTEROP_STREAM INTEROP_SUB INTEROP_BUMPER TESTS_DDS_DIR CYCLES
"""
import os
import re
import subprocess
import sys
import time

from dds_domain import Domain, environment, scratch_folder

RUN_SECONDS = 1.2  # each mediator's life: past the event's 500 ms lifetime since its start
LAST_RUN_SECONDS = 6.0  # the last one's, whose counters are judged


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def main():
    arbc, stream, sub, bumper, here, cycles = sys.argv[1:7]
    cycles = int(cycles)
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = scratch_folder("arbc-dds-bumper-restart-")
    interop = os.path.join(here, "interop")
    built = subprocess.run([arbc, "build", os.path.join(interop, "bumper.spec"), "-o", out_dir],
                           capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    seconds = cycles * (RUN_SECONDS + 0.5) + LAST_RUN_SECONDS + 10
    base = subprocess.Popen([sub, domain, str(seconds), str(seconds)], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, env=env)
    planner = subprocess.Popen([stream, domain, "20"], env=env)
    pressed = subprocess.Popen([bumper, domain, "held", str(seconds)], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True, env=env)
    time.sleep(1.0)  # the programs up before the first mediator, as on a running robot
    said = []
    for _ in range(cycles):
        mediator = subprocess.Popen(
            [arbc, "run", os.path.join(out_dir, "bumper"), "--transport", "dds", "--host",
             "none", "--mediate", "all", "--deploy", os.path.join(interop, "bumper.deploy.json"),
             "--domain", domain, "--duration", "100000s"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
        time.sleep(RUN_SECONDS)
        mediator.kill()
        said.append(mediator.communicate(timeout=30)[0])
    # One last mediator ends by SIGTERM, so that its counters say what it read and dropped.
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "bumper"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", os.path.join(interop, "bumper.deploy.json"), "--domain",
         domain, "--duration", "100000s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    # Long enough for discovery to match the planner too: this mediator sits at participant id
    # 3 + CYCLES, past the initial peers' reach, so the peers learn of it only from its own
    # announcements; under the sanitizers 2.4 s was once too short (nothing read from nav).
    time.sleep(LAST_RUN_SECONDS)
    mediator.terminate()
    last = mediator.communicate(timeout=30)[0]
    for p in (planner, pressed, base):
        p.kill()
    heard = base.communicate(timeout=30)[0]
    pressed.communicate(timeout=30)
    numbers = [line for line in heard.splitlines()[1:] if line.strip()]
    if numbers:
        fail(f"the base received {len(numbers)} commands while the bumper was held, over "
             f"{cycles + 1} starts of the mediator", last, heard)
    bumps = re.search(r"read  rt/bumper \(std_msgs::msg::dds_::Bool_\): (\d+) received", last)
    if not bumps or int(bumps.group(1)) < 5:
        fail("the last mediator did not read the bumper's samples", last)
    navs = re.search(r"read  rt/nav/cmd_vel \([^)]*\): (\d+) received", last)
    if not navs or int(navs.group(1)) < 5:  # how many: when discovery matched, under load
        fail("the last mediator did not read the planner's commands (nothing was kept out)", last)
    print(f"ok: {cycles + 1} starts of the mediator with the bumper held, the base received "
          f"nothing; the last one read {bumps.group(1)} bumper samples and {navs.group(1)} "
          "commands")


if __name__ == "__main__":
    main()
