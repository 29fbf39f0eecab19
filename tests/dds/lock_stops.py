#!/usr/bin/env python3
"""A lock whose publisher stops (issue 42 item 2, docs/language.md#locks), on the DDS mediator
in front of plain Fast-DDS programs: the planner streams every 20 ms, the bumper (interop_bumper,
std_msgs/msg/Bool, best effort) reports released for 2 s, pressed for 1 s, released for 2 s, then
its program exits. With `event e_bumped = lock Bumper.pressed timeout 500ms;` and
`nav: when not e_bumped`, the base must receive the planner's commands while the bumper says
released, and none from 500 ms after the bumper's program has gone (plus 300 ms for the last
samples in flight and the mediator's clock), although the planner goes on for 2 s more.

usage: lock_stops.py ARBC INTEROP_STREAM INTEROP_SUB INTEROP_BUMPER TESTS_DDS_DIR
"""
import os
import subprocess
import sys
import tempfile
import threading
import time

from dds_domain import Domain, environment

SPEC_EVENT = "event e_bumped = Bumper.pressed : pressed for 500ms;"
LOCK = "event e_bumped = lock Bumper.pressed timeout 500ms;"


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def main():
    arbc, stream, sub, bumper, here = sys.argv[1:6]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    interop = os.path.join(here, "interop")
    with open(os.path.join(interop, "bumper.spec"), encoding="utf-8") as f:
        text = f.read()
    assert SPEC_EVENT in text
    with tempfile.TemporaryDirectory(prefix="arbc-dds-lock-stops-") as tmp:
        spec = os.path.join(tmp, "bumper.spec")
        with open(spec, "w", encoding="utf-8") as f:
            f.write(text.replace(SPEC_EVENT, LOCK))
        built = subprocess.run([arbc, "build", spec, "-o", tmp], capture_output=True, text=True)
        if built.returncode != 0:
            fail("arbc build", built.stdout + built.stderr)
        base = subprocess.Popen([sub, domain, "3", "60"], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, env=env)
        times = []  # when the base took each command

        def read():
            for line in base.stdout:
                times.append(time.monotonic())

        reader = threading.Thread(target=read)
        reader.start()
        mediator = subprocess.Popen(
            [arbc, "run", os.path.join(tmp, "bumper"), "--transport", "dds", "--host", "none",
             "--mediate", "all", "--deploy", os.path.join(interop, "bumper.deploy.json"),
             "--domain", domain, "--duration", "60s"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
        planner = subprocess.Popen([stream, domain, "20"], env=env)
        pressed = subprocess.run([bumper, domain], capture_output=True, text=True, env=env,
                                 timeout=60)
        gone = time.monotonic()
        time.sleep(2.0)  # the planner goes on; the lock must hold it off
        planner.kill()
        planner.wait()
        base.wait(timeout=60)
        reader.join()
        mediator.terminate()
        said = mediator.communicate(timeout=30)[0]
    if pressed.returncode != 0:
        fail(f"interop_bumper exited {pressed.returncode}", pressed.stdout + pressed.stderr)
    before = [t for t in times if t < gone]
    late = [round(t - gone, 3) for t in times if t > gone + 0.8]
    if len(before) < 20:
        fail(f"the base received {len(before)} commands while the bumper said released", said)
    if late:
        fail(f"the base received {len(late)} commands after the bumper's program had gone for "
             f"more than its 500 ms timeout (at +{late[0]} s)", said)
    print(f"ok: {len(before)} commands while the bumper spoke, none from 500 ms after it went")


if __name__ == "__main__":
    main()
