#!/usr/bin/env python3
"""A spec type with the name a program without arbc in it uses and other fields
(docs/distributed.md#types-on-the-wire): DDS matches the two by name, and every sample fails to
decode. The mediator must say so when the first one comes, naming the topic, the port and what
to change, not only count them at the end; and its run is a failure, not a success.

teleop.spec with Twist given a third field; interop_stream (plain Fast-DDS) publishes ROS 2
Twists on rt/nav/cmd_vel.

usage: foreign_layout.py ARBC INTEROP_STREAM TESTS_DDS_DIR
"""
import os
import signal
import subprocess
import sys
import tempfile
import time

from dds_domain import Domain, environment


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def main():
    arbc, stream, here = sys.argv[1:4]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = tempfile.mkdtemp(prefix="arbc-dds-foreign-layout-")
    spec = os.path.join(out_dir, "teleop.spec")
    text = open(os.path.join(here, "interop", "teleop.spec")).read()
    wrong = text.replace("type Twist = { linear: vec3, angular: vec3 };",
                         "type Twist = { linear: vec3, angular: vec3, speed: float };")
    if wrong == text:
        fail("teleop.spec no longer declares Twist as this test expects")
    open(spec, "w").write(wrong)
    built = subprocess.run([arbc, "build", spec, "-o", out_dir], capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "teleop"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", os.path.join(here, "interop", "teleop.deploy.json"),
         "--domain", domain, "--duration", "100000s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    publisher = subprocess.Popen([stream, domain, "20"], env=env)
    time.sleep(4)
    publisher.kill()
    publisher.wait()
    mediator.send_signal(signal.SIGTERM)
    out, _ = mediator.communicate(timeout=30)
    said = ("DDS: topic rt/nav/cmd_vel (Nav.cmd_vel): a sample on rt/nav/cmd_vel does not decode "
            "as geometry_msgs::msg::dds_::Twist_; the remote program's type has this name but "
            "other fields, or another order: give Nav.cmd_vel's type in the spec the program's "
            "fields, in the program's order (docs/distributed.md#types-on-the-wire); until then "
            "every sample is dropped as bad-type")
    if out.count(said) != 1:
        fail(f"the mediator does not say once {said!r}", out)
    # Before the end of the run: when the first sample came, not with the counters.
    if out.index(said) > out.index("interrupted (SIGTERM)"):
        fail("the mediator says it only at the end", out)
    # A run whose every sample went unread is not a success, environment or not.
    verdict = [line for line in out.splitlines() if line.startswith("result: ")]
    if (len(verdict) != 1 or not verdict[0].startswith(
            "result: failure (no environment; judged by quarantined connections and messages "
            "of the wrong type: ") or " bad-type into " not in verdict[0]):
        fail("the mediator's verdict does not name the messages it could not read", out)
    if mediator.returncode != 3:
        fail(f"the mediator exits {mediator.returncode}, not 3 (a run-time failure)", out)
    print("ok\n" + out)


if __name__ == "__main__":
    main()
