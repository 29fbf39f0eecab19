#!/usr/bin/env python3
"""Programs without arbc in them whose QoS is not arbc's (docs/distributed.md#quality-of-service):
a planner that publishes best effort (ROS 2's sensor-data profile) in front of the mediator's
reliable reader, and a base that subscribes transient local (a latched topic) behind its
volatile writer. DDS matches neither, and the run used to look as if no program were there.

1. With teleop.deploy.json the mediator names each mismatch: the topic, the port, what each
   side has, and the setting to write in the deployment file; its no-peer report says that a
   program is there with another QoS instead of asking for the domain.
2. With those settings written ("qos": {"ports": ...}) every command the mediator writes
   reaches the base.

usage: qos_mismatch.py ARBC INTEROP_STREAM INTEROP_SUB TESTS_DDS_DIR
"""
import json
import os
import signal
import subprocess
import sys
import time

from dds_domain import Domain, environment
from teleop_app import build_teleop


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def run(arbc, stream, sub, app, deploy, domain, env):
    """The mediator, the planner (best effort) and, 1 s later, the base (transient local), 3 s
    of commands; the mediator's and the base's outputs."""
    quick = dict(env, ARBC_DDS_NO_PEER_AFTER="1")
    mediator = subprocess.Popen(
        [arbc, "run", app, "--transport", "dds", "--host", "none", "--mediate", "all",
         "--deploy", deploy, "--domain", domain, "--duration", "100000s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=quick)
    planner = subprocess.Popen([stream, domain, "20", "best_effort"], env=env)
    time.sleep(1)
    base = subprocess.Popen([sub, domain, "2", "6", "transient_local"], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, env=env)
    time.sleep(2)
    planner.kill()
    planner.wait()
    heard, _ = base.communicate(timeout=30)
    mediator.send_signal(signal.SIGTERM)
    said, _ = mediator.communicate(timeout=30)
    return said, heard


def main():
    arbc, stream, sub, here = sys.argv[1:5]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = build_teleop(arbc, here, "arbc-dds-qos-mismatch-")
    app = os.path.join(out_dir, "teleop")
    deploy = os.path.join(here, "interop", "teleop.deploy.json")

    said, heard = run(arbc, stream, sub, app, deploy, domain, env)
    lines = [
        "DDS: QoS mismatch on topic rt/nav/cmd_vel (Nav.cmd_vel): a remote publisher offers best "
        "effort reliability, this process's reader requests reliable, so nothing flows between "
        "them; if that is the program's QoS, write \"Nav.cmd_vel\": {\"reliability\": "
        f"\"best_effort\"}} in \"qos\": {{\"ports\": ...}} of {deploy} "
        "(docs/distributed.md#quality-of-service)",
        "DDS: QoS mismatch on topic rt/cmd_vel (Base.cmd_vel): a remote subscriber requests "
        "transient local durability, this process's writer offers volatile, so nothing flows "
        "between them; if that is the program's QoS, write \"Base.cmd_vel\": {\"durability\": "
        f"\"transient_local\"}} in \"qos\": {{\"ports\": ...}} of {deploy} (the subscriber then "
        "also gets the last messages written before it joined)",
        "a program on rt/nav/cmd_vel, rt/cmd_vel has a QoS that does not match (said above)",
    ]
    for line in lines:
        if line not in said:
            fail(f"the mediator does not say {line!r}", said, heard)
    if heard.strip() != "interop_sub: listening":
        fail("the base heard something through a QoS mismatch", said, heard)

    with open(deploy) as f:
        settings = json.load(f)
    settings["qos"] = {"ports": {"Nav.cmd_vel": {"reliability": "best_effort"},
                                 "Base.cmd_vel": {"durability": "transient_local"}}}
    fixed = os.path.join(out_dir, "deploy.json")
    with open(fixed, "w") as f:
        json.dump(settings, f, indent=2)
    said, heard = run(arbc, stream, sub, app, fixed, domain, env)
    if "QoS mismatch" in said:
        fail("a QoS mismatch with the settings written", said, heard)
    # Commands written before the base joined are kept by the transient-local writer (fewer
    # than its depth of 100 here) and reach the base when it does: none counts as to nobody.
    written = [l for l in said.splitlines() if l.startswith("  wrote rt/cmd_vel ")]
    got = heard.splitlines()[1:]
    if len(written) != 1 or not written[0].endswith(f": {len(got)} written") or len(got) < 50:
        fail(f"the base heard {len(got)} commands, not what the mediator wrote", said, heard)
    # The planner numbers its commands every 20 ms: about 50 were out when the base started.
    first = int(float(got[0]))
    if first > 30:
        fail(f"the base's first command is number {first}: the ones written before it joined "
             "were not kept for it", said, heard)
    print(f"ok: {len(got)} commands through best effort in and transient local out")


if __name__ == "__main__":
    main()
