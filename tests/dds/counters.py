#!/usr/bin/env python3
"""The DDS mediator's counters mean what they say (issue 39), against plain Fast-DDS programs.
The teleop mediator (interop/teleop.spec, every connection mediated here) in a domain of its
own; one case per run:

  bad-type-details  interop_padded writes 300 samples at once, each longer than the spec's
                    Twist by its own number of bytes (pads of 8, 100 and 400 bytes, 1:2:3): the
                    trace's bad-type drops carry each sample's own detail, as many of each as
                    were written (they all read "the last sample's" detail).
  lost-in-transit   interop_stream writes best effort as fast as it can over UDP for 2 s: what
                    DDS reports lost in transit is `lost-in-transit`, never `queue-full`, and
                    queue-full plus lost-in-transit on `nav` add up to the topic's `lost`; the
                    losses in bulk are said when they start, before the end of the run.
  nobody            the planner runs 2 s before the base's subscriber exists: those commands
                    are written "to nobody", said when it starts and in the summary, and the
                    subscriber receives exactly the commands written minus those.

usage: counters.py ARBC INTEROP_STREAM INTEROP_SUB INTEROP_PADDED TESTS_DDS_DIR CASE
"""
import collections
import json
import os
import re
import signal
import subprocess
import sys
import time

from dds_domain import Domain, environment
from teleop_app import build_teleop


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def mediator(arbc, app, deploy, domain, env, trace=None):
    args = [arbc, "run", app, "--transport", "dds", "--host", "none", "--mediate", "all",
            "--deploy", deploy, "--domain", domain, "--duration", "100000s"]
    if trace:
        args += ["--trace", trace]
    return subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            env=env)


def stop(process):
    process.send_signal(signal.SIGTERM)
    out, _ = process.communicate(timeout=60)
    if "interrupted (SIGTERM)" not in out:
        fail(f"the mediator did not end on SIGTERM (exit {process.returncode})", out)
    return out


def table(out):
    """The end-of-run connection table: {connection: {column: count}}."""
    lines = out.splitlines()
    start = next((i for i, l in enumerate(lines) if l.startswith("connection ")), None)
    if start is None:
        fail("no connection table", out)
    columns = lines[start].split()[1:]
    rows = {}
    for line in lines[start + 1:]:
        cells = line.split()
        if len(cells) != len(columns) + 1 or not cells[1].isdigit():
            break
        rows[cells[0]] = dict(zip(columns, map(int, cells[1:])))
    return rows


def bad_type_details(arbc, stream, sub, padded, here, env, domain, app):
    deploy = os.path.join(here, "interop", "teleop.deploy.json")
    trace = os.path.join(os.path.dirname(app), "trace.jsonl")
    m = mediator(arbc, app, deploy, domain, env, trace)
    pads, count = [8, 100, 100, 400, 400, 400], 300
    writer = subprocess.run([padded, domain, str(count)] + [str(p) for p in pads],
                            capture_output=True, text=True, env=env, timeout=60)
    out = stop(m)
    if writer.returncode != 0:
        fail(f"interop_padded exited {writer.returncode}", writer.stdout + writer.stderr, out)
    details = collections.Counter()
    for line in open(trace):
        record = json.loads(line)
        if record.get("type") == "drop" and record.get("reason") == "bad-type":
            details[record.get("detail", "")] += 1
    extra = {}
    for detail, n in details.items():
        found = re.search(r"has (\d+) bytes more than", detail)
        if not found:
            fail(f"a bad-type drop without its bytes: {detail!r}", out)
        extra[int(found.group(1))] = n
    # Longer pads, more bytes: the counts in the order of the pads' sizes.
    written = [pads.count(p) * count // len(pads) for p in sorted(set(pads))]
    got = [extra[k] for k in sorted(extra)]
    if got != written:
        fail(f"bad-type drops per detail (by bytes more) {sorted(extra.items())}, written "
             f"{written} for pads {sorted(set(pads))}", out)
    if table(out)["nav"]["bad-type"] != count:
        fail(f"nav's bad-type count is not {count}", out)
    print(f"ok: {count} bad samples, each with its own detail: {sorted(extra.items())}\n" + out)


def lost_in_transit(arbc, stream, sub, padded, here, env, domain, app):
    deploy_file = os.path.join(os.path.dirname(app), "best_effort.deploy.json")
    deploy = json.load(open(os.path.join(here, "interop", "teleop.deploy.json")))
    deploy["qos"] = {"ports": {"Nav.cmd_vel": {"reliability": "best_effort"}}}
    json.dump(deploy, open(deploy_file, "w"))
    udp = environment(os.path.join(here, "loopback_udp_profile.xml"))
    m = mediator(arbc, app, deploy_file, domain, udp)
    time.sleep(1)
    planner = subprocess.Popen([stream, domain, "0", "best_effort"], env=udp)
    time.sleep(3)
    planner.kill()
    planner.wait()
    time.sleep(1)
    out = stop(m)
    nav = table(out)["nav"]
    if "lost-in-transit" not in nav:
        fail("the table has no lost-in-transit column", out)
    read = re.search(r"read  rt/nav/cmd_vel \([^)]*\): (\d+) received, (\d+) lost", out)
    if not read:
        fail("no summary line for rt/nav/cmd_vel", out)
    lost = int(read.group(2))
    if nav["lost-in-transit"] == 0:
        fail("DDS reported no sample lost in transit (the flood is meant to lose some)", out)
    # The topic's lost samples are the reader's: in transit, or its own queue full; the
    # connection's queue-full may add the runtime queue's overflow on top.
    if not nav["lost-in-transit"] <= lost <= nav["lost-in-transit"] + nav["queue-full"]:
        fail(f"nav: {nav['lost-in-transit']} lost-in-transit and {nav['queue-full']} queue-full "
             f"do not account for the topic's {lost} lost", out)
    said = "connection nav: losing messages in bulk from "
    if said not in out or out.index(said) > out.index("interrupted (SIGTERM)"):
        fail("the losses in bulk were not said when they started", out)
    print(f"ok: {nav['lost-in-transit']} lost in transit, {nav['queue-full']} queue-full\n" + out)


def nobody(arbc, stream, sub, padded, here, env, domain, app):
    deploy = os.path.join(here, "interop", "teleop.deploy.json")
    m = mediator(arbc, app, deploy, domain, env)
    planner = subprocess.Popen([stream, domain, "20"], env=env)
    time.sleep(3)
    base = subprocess.Popen([sub, domain, "3", "30"], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, env=env)
    time.sleep(3)
    planner.kill()
    planner.wait()
    heard, _ = base.communicate(timeout=60)
    out = stop(m)
    received = len([line for line in heard.splitlines()[1:] if line.strip()])
    wrote = re.search(r"wrote rt/cmd_vel \([^)]*\): (\d+) written, (\d+) to nobody", out)
    if not wrote:
        fail("the summary does not say what was written to nobody", out, heard)
    written, to_nobody = int(wrote.group(1)), int(wrote.group(2))
    if to_nobody == 0 or received == 0 or written - to_nobody != received:
        fail(f"{written} written, {to_nobody} to nobody, the subscriber received {received}",
             out, heard)
    said = ("DDS: topic rt/cmd_vel (Base.cmd_vel): written with no subscriber matched (none "
            "yet): Base does not receive it")
    if out.count(said) != 1 or out.index(said) > out.index("interrupted (SIGTERM)"):
        fail(f"the mediator does not say once, as it happens, {said!r}", out)
    print(f"ok: {written} written, {to_nobody} to nobody, {received} received\n" + out)


def main():
    arbc, stream, sub, padded, here, case = sys.argv[1:7]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = build_teleop(arbc, here, f"arbc-dds-counters-{case}-")
    app = os.path.join(out_dir, "teleop")
    cases = {"bad-type-details": bad_type_details, "lost-in-transit": lost_in_transit,
             "nobody": nobody}
    cases[case](arbc, stream, sub, padded, here, env, domain, app)


if __name__ == "__main__":
    main()
