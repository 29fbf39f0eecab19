#!/usr/bin/env python3
"""A spec type with the name a program without arbc in it uses and other fields
(docs/distributed.md#types-on-the-wire): DDS matches the two by name. The mediator must say so
when the first sample comes, naming the topic, the port and what to change, not only count
them at the end; and its run is a failure, not a success.

teleop.spec with Twist changed; interop_stream (plain Fast-DDS) publishes ROS 2 Twists on
rt/nav/cmd_vel.
  longer   Twist given a third field: no sample decodes
  shorter  Twist without `angular`: every sample decodes as its first field, and the mediator
           used to pass on 24-byte Twists, which the program's subscribers drop without a trace
           (they are refused as 24 bytes longer than the spec's Twist)

The mediator is given a Twist.msg that agrees with the spec (--msg-path): the definitions of
this machine and the remote program's disagree, which only the samples can show; without it
the mapping is refused before anything runs (dds/msg_layout.h, cli_dds_stamp_of_ints).

usage: foreign_layout.py ARBC INTEROP_STREAM TESTS_DDS_DIR [longer|shorter]
"""
import os
import signal
import subprocess
import sys
import time

from dds_domain import Domain, environment, scratch_folder


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def main():
    arbc, stream, here = sys.argv[1:4]
    case = sys.argv[4] if len(sys.argv) > 4 else "longer"
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = scratch_folder("arbc-dds-foreign-layout-")
    spec = os.path.join(out_dir, "teleop.spec")
    text = open(os.path.join(here, "interop", "teleop.spec")).read()
    twist = "type Twist = { linear: vec3, angular: vec3 };"
    if case == "longer":
        wrong = text.replace(twist, "type Twist = { linear: vec3, angular: vec3, speed: float };")
        why = "does not decode as geometry_msgs::msg::dds_::Twist_"
        local = "Vector3 linear\nVector3 angular\nfloat64 speed\n"
    else:
        wrong = text.replace(twist, "type Twist = { linear: vec3 };").replace(
            "or norm(cmd_vel.angular) > 0.0", "")
        why = "has 24 bytes more than geometry_msgs::msg::dds_::Twist_ as the spec declares it"
        local = "Vector3 linear\n"
    msgs = os.path.join(out_dir, "msgs")
    os.makedirs(os.path.join(msgs, "geometry_msgs", "msg"))
    with open(os.path.join(msgs, "geometry_msgs", "msg", "Twist.msg"), "w") as f:
        f.write("# this machine's Twist, not the program's\n" + local)
    if wrong == text:
        fail("teleop.spec no longer declares Twist as this test expects")
    open(spec, "w").write(wrong)
    built = subprocess.run([arbc, "build", spec, "-o", out_dir], capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "teleop"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", os.path.join(here, "interop", "teleop.deploy.json"),
         "--domain", domain, "--duration", "100000s", "--msg-path", msgs],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    publisher = subprocess.Popen([stream, domain, "20"], env=env)
    time.sleep(4)
    publisher.kill()
    publisher.wait()
    mediator.send_signal(signal.SIGTERM)
    out, _ = mediator.communicate(timeout=30)
    said = (f"DDS: topic rt/nav/cmd_vel (Nav.cmd_vel): a sample on rt/nav/cmd_vel {why}; "
            "the remote program's type has this name but "
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
