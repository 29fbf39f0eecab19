#!/usr/bin/env python3
"""Mistakes made when putting arbc in front of DDS programs (docs/distributed.md), each of
which used to leave a run wrong or idle without a word. arbc processes with stand-ins play
the programs, on tests/dds/interop/teleop.spec (a mux of Joy and Nav into Base).

usage: mistakes.py ARBC TESTS_DDS_DIR CASE
  two-mediators  two processes mediate Base: each says so (Base would get every command twice)
  topic-typo     the mediator's deployment misspells a topic the programs publish on: a
                 moment in (ARBC_DDS_NO_PEER_AFTER; 10 s by default), it names the topics
                 without a peer, its domain, and the topic seen in the domain that looks like
                 the misspelled one; says so again at growing intervals; and its end-of-run
                 summary names the topics that never heard a peer
  type-typo      the mediator's deployment maps Twist to another ROS 2 type than the programs
                 use: each topic's type mismatch names the deployment file's line and column
                 of that mapping and the programs' type to write there
"""
import json
import os
import re
import subprocess
import sys

from dds_domain import Domain, environment
from teleop_app import build_teleop


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


class Teleop:
    def __init__(self, arbc, here):
        self.arbc, self.here = arbc, here
        self.env = environment(os.path.join(here, "loopback_profile.xml"))
        self.domain = Domain()
        self.dir = build_teleop(arbc, here, "arbc-dds-mistakes-")
        self.deploy = os.path.join(here, "interop", "teleop.deploy.json")

    def deployment(self, edit):
        """A copy of teleop.deploy.json changed by edit(dict)."""
        with open(self.deploy) as f:
            d = json.load(f)
        edit(d)
        path = os.path.join(self.dir, "deploy.json")
        with open(path, "w") as f:
            json.dump(d, f, indent=2)
        return path

    def start(self, host, mediate, seconds, deploy=None, extra=(), env=None):
        words = [self.arbc, "run", os.path.join(self.dir, "teleop"), "--transport", "dds",
                 "--host", host, "--mediate", mediate, "--deploy", deploy or self.deploy,
                 "--domain", str(self.domain.id), "--duration", f"{seconds}s", *extra]
        return subprocess.Popen(words, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True, env=dict(self.env, **(env or {})))


def finish(*procs):
    outs = [p.communicate(timeout=60)[0] for p in procs]
    for p, out in zip(procs, outs):
        if p.returncode != 0:
            fail(f"exit {p.returncode}", out)
    return outs


def two_mediators(t):
    first = t.start("none", "all", 6)
    second = t.start("none", "Base", 6)
    outs = finish(first, second)
    line = ("DDS: another arbc process also mediates Base.cmd_vel (it publishes on topic "
            "rt/cmd_vel): Base receives what both select; give --mediate Base to one process only")
    for out in outs:
        if line not in out:
            fail("a mediator does not say that another one mediates Base", *outs)


def topic_typo(t):
    # The first report 1 s in rather than 10 s: then again at 3 s and 6 s (dds/no_peer_reports.h).
    soon = {"ARBC_DDS_NO_PEER_AFTER": "1"}
    typo = t.deployment(lambda d: d["topics"].update({"Joy.cmd_vel": "/joy/cmdvel"}))
    mediator = t.start("none", "all", 8, deploy=typo, env=soon)
    programs = t.start("Joy,Nav", "none", 8, extra=["--stub"], env=soon)
    outs = finish(mediator, programs)
    # The first report may come before discovery is over, and name more topics; the later ones
    # name exactly the two that never find a peer.
    words = [re.compile(r"DDS: no peer yet after 1 s on [^(]*rt/joy/cmdvel"),
             "DDS: still no peer after 3 s on rt/joy/cmdvel, rt/cmd_vel (nothing flows there",
             "DDS: still no peer after 6 s on rt/joy/cmdvel, rt/cmd_vel (nothing flows there",
             f"is every program in domain {t.domain.id} (--domain, ROS_DOMAIN_ID)",
             "Seen in this domain: rt/joy/cmd_vel (geometry_msgs::msg::dds_::Twist_)",
             "  never heard a peer: rt/joy/cmdvel (Joy.cmd_vel), rt/cmd_vel (Base.cmd_vel)\n"]
    for w in words:
        if not (w.search(outs[0]) if isinstance(w, re.Pattern) else w in outs[0]):
            fail(f"the mediator does not say {getattr(w, 'pattern', w)!r}", *outs)
    if outs[0].count("still no peer after") != 2:
        fail("the mediator does not say it again exactly at 3 s and 6 s", *outs)
    # The other side sees it too: rt/joy/cmd_vel has no subscriber, rt/nav/cmd_vel has one.
    if "DDS: still no peer after 6 s on rt/joy/cmd_vel (" not in outs[1]:
        fail("the programs' process does not name rt/joy/cmd_vel alone", *outs)
    if "  never heard a peer: rt/joy/cmd_vel (Joy.cmd_vel)\n" not in outs[1]:
        fail("the programs' summary does not name rt/joy/cmd_vel", *outs)


def type_typo(t):
    # A name no definition is found for (a mapping to a message arbc knows, such as
    # TwistStamped, is refused before anything runs: dds/msg_layout.h): the mismatch shows at
    # discovery, with the name the program uses.
    wrong = t.deployment(lambda d: d["types"].update({"Twist": "geometry_msgs/msg/Twst"}))
    lines = open(wrong).read().splitlines()
    line = next(i for i, text in enumerate(lines, 1) if '"Twist":' in text)
    column = lines[line - 1].index('"Twist":') + 1
    mediator = t.start("none", "all", 5, deploy=wrong)
    programs = t.start("Joy,Nav", "none", 5, extra=["--stub"])
    outs = finish(mediator, programs)
    for topic, what, port in (("rt/joy/cmd_vel", "publisher", "Joy.cmd_vel"),
                              ("rt/nav/cmd_vel", "publisher", "Nav.cmd_vel")):
        said = (f"DDS: type mismatch on topic {topic}: a remote {what} uses type "
                "geometry_msgs::msg::dds_::Twist_, this process uses "
                "geometry_msgs::msg::dds_::Twst_; they do not match, so nothing flows "
                f"between them; the name is the deployment's, {wrong}:{line}:{column} (\"Twist\": "
                f"\"geometry_msgs/msg/Twst\", the type of {port}): if the program's type "
                "is the same message, write \"geometry_msgs/msg/Twist\" there")
        if said not in outs[0]:
            fail(f"the mediator does not say {said!r}", *outs)


def main():
    arbc, here, case = sys.argv[1:4]
    {"two-mediators": two_mediators, "topic-typo": topic_typo,
     "type-typo": type_typo}[case](Teleop(arbc, here))
    print("ok")


if __name__ == "__main__":
    main()
