#!/usr/bin/env python3
"""The runtime checks on a DDS mediator in front of plain Fast-DDS programs (issue 39,
docs/runtime.md#runtime-checks): tests/dds/interop/bumper_grips.spec proves Base.cmd_vel
exclusive under `exclusive { e_bumped, e_clear }` and `given Nav.cmd_vel every 10ms`.

  broken: interop_bumper is released for 2 s, pressed for 1 s, released for 2 s (best effort,
          every 50 ms): at the press both events are present, both rules deliver the planner's
          command, and interop_stream publishes every 20 ms. The mediator must say the group,
          the port's exclusivity and the rate broken, and end in failure (exit 3).
  kept:   the bumper held pressed the whole time and the rate `every 500ms`: nothing broken, and
          the mediator ends in success.

usage: mediator_checks.py ARBC INTEROP_STREAM INTEROP_SUB INTEROP_BUMPER TESTS_DDS_DIR CASE
"""
import os
import signal
import subprocess
import sys

from dds_domain import Domain, environment, scratch_folder


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def run(arbc, stream, sub, bumper, here, spec_text, bumper_args):
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = scratch_folder("arbc-dds-checks-")
    spec = os.path.join(out_dir, "bumper_grips.spec")
    with open(spec, "w", encoding="utf-8") as f:
        f.write(spec_text)
    built = subprocess.run([arbc, "build", spec, "-o", out_dir], capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    interop = os.path.join(here, "interop")
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "bumper_grips"), "--transport", "dds", "--host",
         "none", "--mediate", "all", "--deploy", os.path.join(interop, "bumper.deploy.json"),
         "--domain", domain, "--wait-peers", "20", "--duration", "100000s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    base = subprocess.Popen([sub, domain, "2", "30"], stdout=subprocess.DEVNULL, env=env)
    planner = subprocess.Popen([stream, domain, "20"], env=env)
    pressed = subprocess.run([bumper, domain, *bumper_args], capture_output=True, text=True,
                             env=env, timeout=60)
    # The mediator ends while the planner still publishes: a planner that stopped first would
    # break the rate in its last gap, which is not this test's question.
    mediator.send_signal(signal.SIGTERM)
    said, _ = mediator.communicate(timeout=60)
    planner.kill()
    planner.wait()
    base.wait(timeout=60)
    if pressed.returncode != 0:
        fail(f"interop_bumper exits {pressed.returncode}", pressed.stdout + pressed.stderr)
    return mediator.returncode, said


def main():
    if len(sys.argv) != 7:
        sys.exit(__doc__)
    arbc, stream, sub, bumper, here, case = sys.argv[1:7]
    with open(os.path.join(here, "interop", "bumper_grips.spec"), encoding="utf-8") as f:
        spec_text = f.read()
    if case == "broken":
        code, said = run(arbc, stream, sub, bumper, here, spec_text, [])
        for line in ["assumption exclusive { e_bumped, e_clear }: e_bumped and e_clear present "
                     "together in Base.cmd_vel at ",
                     "Base.cmd_vel: rules go, halt are never selected together: ",
                     "assumption given Nav.cmd_vel every 10ms: nothing from Nav.cmd_vel between "]:
            if line not in said:
                fail(f"the mediator did not say: {line}", said)
        if code != 3 or "result: failure (runtime checks: " not in said:
            fail(f"the mediator exits {code}, expected 3 naming the checks", said)
        print("ok broken: the group, the exclusivity and the rate, each said broken")
    elif case == "kept":
        code, said = run(arbc, stream, sub, bumper, here,
                         spec_text.replace("every 10ms;", "every 500ms;"), ["held", "4"])
        if code != 0 or "runtime checks: 3 claims and assumptions of the proof watched, none " \
                        "broken" not in said:
            fail(f"the mediator exits {code}, expected 0 with nothing broken", said)
        print("ok kept: nothing broken")
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
