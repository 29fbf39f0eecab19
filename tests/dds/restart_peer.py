#!/usr/bin/env python3
"""A program with no arbc in it, killed and started again behind an arbc mediator
(docs/distributed.md#killing-and-restarting-a-process).

interop_stream publishes on rt/nav/cmd_vel every 20 ms; an arbc mediator (teleop.spec) passes
each message on to rt/cmd_vel, where interop_sub listens. Each cycle kills interop_sub with
SIGKILL and starts it again at once, as a crash and a service manager would. Fast-DDS gives
the restarted subscriber the killed one's participant id, hence its shared-memory ports
(arbc's own processes avoid that, dds/shm_participant_id.h), while the mediator still has the
killed one's segments mapped; the mediator must say so at each restart. Each restarted
subscriber must hear the mediator within
HEARD_WITHIN seconds and then miss nothing. Prints per cycle: whether it took the killed one's
ports again, how long after it listened the first message came, and what it heard.

The mediator runs over shared memory and UDP (loopback_profile.xml); the subscriber under
PROFILE. HEARD_WITHIN is a number of seconds: each restarted subscriber must hear the mediator
that soon and then miss nothing (over UDP only, loopback_udp_profile.xml: 38 restarts of 40
within 0.05 s, all within 1 s).
Or it is `measure`, for shared memory, where Fast-DDS sometimes leaves the mediator writing
into the killed subscriber's segment for good (eProsima/Fast-DDS#5053): the cycles are printed,
not judged, and the test fails only if a restarted subscriber took ports of its own, which
would make docs/distributed.md's account of it wrong.

usage: restart_peer.py ARBC INTEROP_STREAM INTEROP_SUB TESTS_DDS_DIR PROFILE HEARD_WITHIN CYCLES
"""
import os
import re
import signal
import subprocess
import sys
import threading
import time

from dds_domain import Domain, environment
from teleop_app import build_teleop

HEARD_WITHIN = 10.0  # s; set from the command line
LISTEN = 2.0  # s of messages counted after the first


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def shm_ports(pid):
    try:
        with open(f"/proc/{pid}/maps") as f:
            return set(re.findall(r"/fastrtps_port(\d+)$", f.read(), re.M))
    except OSError:
        return set()


class Subscriber:
    """interop_sub, its lines read as they come: (time, value) per message."""

    def __init__(self, sub, domain, env):
        self.proc = subprocess.Popen([sub, domain, "1000", "1000"], stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, text=True, env=env)
        self.listening, self.values, self.lines = None, [], []
        threading.Thread(target=self.read, daemon=True).start()

    def read(self):
        for line in self.proc.stdout:
            self.lines.append(line)
            if line.startswith("interop_sub: listening"):
                self.listening = time.time()
            elif line.strip():
                self.values.append((time.time(), int(float(line))))

    def wait(self, until, seconds):
        deadline = time.time() + seconds
        while time.time() < deadline and not until():
            time.sleep(0.02)
        return until()

    def kill(self):
        self.proc.send_signal(signal.SIGKILL)
        self.proc.wait()


def main():
    if len(sys.argv) != 8:
        sys.exit(__doc__)
    arbc, stream, sub, here, profile, heard_within, cycles = sys.argv[1:8]
    global HEARD_WITHIN
    measure = heard_within == "measure"
    HEARD_WITHIN = 10.0 if measure else float(heard_within)
    env = environment(os.path.join(here, "loopback_profile.xml"))
    sub_env = environment(os.path.join(here, profile))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    out_dir = build_teleop(arbc, here, "arbc-dds-restart-peer-")
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "teleop"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", os.path.join(here, "interop", "teleop.deploy.json"),
         "--domain", domain, "--duration", "100000s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    publisher = subprocess.Popen([stream, domain, "20"], stdout=subprocess.DEVNULL,
                                 stderr=subprocess.DEVNULL, env=env)
    failures, same_ports = [], 0
    # Every shared-memory port an earlier subscriber mapped. Each was killed, so each of its
    # ports stays a vanished participant's for the mediator (dds/shm_port_owners.h): compare
    # with all of them, not with the last one's alone, which may not have mapped its own port
    # before it was killed (seen: one that heard nothing had 28412 unmapped, and the next one,
    # on 28412 again, was counted as on ports of its own while the mediator rightly named it).
    killed_ports = set()
    try:
        for cycle in range(int(cycles) + 1):
            s = Subscriber(sub, domain, sub_env)
            heard = s.wait(lambda: s.values, HEARD_WITHIN + 5)
            # Segments are mapped as they are first used: compare what each maps just before
            # it is killed, which by then holds them all.
            ports = shm_ports(s.proc.pid)
            again = bool(killed_ports and ports and ports <= killed_ports)
            same_ports += again
            if not heard:
                failures.append(cycle)
                print(f"cycle {cycle}: ports {sorted(ports)} (a killed one's: {again}): "
                      f"heard nothing in {HEARD_WITHIN + 5:.0f} s")
            else:
                delay = s.values[0][0] - (s.listening or s.values[0][0])
                s.wait(lambda: s.values[-1][0] - s.values[0][0] > LISTEN, LISTEN + 5)
                got = [v for _, v in s.values]
                missing = (got[-1] - got[0] + 1) - len(set(got))
                print(f"cycle {cycle}: ports {sorted(ports)} (a killed one's: {again}): first "
                      f"message {delay:.2f} s after listening, then {len(got)} messages "
                      f"({got[0]}..{got[-1]}), {missing} missing")
                if delay > HEARD_WITHIN or missing:
                    failures.append(cycle)
            killed_ports |= shm_ports(s.proc.pid) | ports
            s.kill()
    finally:
        publisher.kill()
        publisher.wait()
        mediator.send_signal(signal.SIGTERM)
        mediated, _ = mediator.communicate(timeout=30)
    if mediator.returncode != 0:
        fail(f"the mediator exited {mediator.returncode}", mediated)
    print(f"{same_ports} of {cycles} restarted subscribers took a killed one's ports again")
    print(f"{len(failures)} of {cycles} heard the mediator late, never, or missed messages: "
          f"cycles {failures}")
    # The mediator names each restart on the killed one's shared-memory ports as it sees it
    # (dds/shm_port_owners.h), and none over UDP only.
    said = len(re.findall(r"DDS: participant 'interop_sub' started on the shared-memory port "
                          r"\d+ of 'interop_sub', which vanished without leaving", mediated))
    if said != same_ports:
        fail(f"the mediator named {said} restarts on the killed one's ports, not {same_ports}",
             mediated)
    if measure:
        if same_ports != int(cycles):
            fail("a restarted subscriber took shared-memory ports of its own: Fast-DDS no longer "
                 "gives it the killed one's id (docs/distributed.md says it does)", mediated)
        print("ok: measured")
        return
    if failures:
        fail(f"cycles {failures}: the restarted subscriber heard the mediator late, never, or "
             "missed messages", mediated)
    print(f"ok: {cycles} restarts, each heard the mediator within {HEARD_WITHIN:g} s and "
          "missed nothing after its first message")


if __name__ == "__main__":
    main()
