"""A DDS domain of its own for one test run (split_run.py, interop.py).

Each run holds a lock file /tmp/arbc-dds-domain-N.lock for its domain N while it lives, so
parallel ctest runs (in this checkout or another) never share a domain; together with
loopback_profile.xml no DDS traffic of a test leaves the machine or reaches another test.

Holding the lock, a run first removes the shared-memory port segments that earlier runs in the
domain left behind (killed processes leave theirs): arbc takes a participant id whose ports have
none (dds/shm_participant_id.h), so leftovers would push ids past the four that discovery by
initial peers on 127.0.0.1 reaches.
"""
import atexit
import fcntl
import glob
import os
import random
import shutil
import tempfile

# Fast-DDS puts domain d on UDP ports from 7400 + 250 d (RTPS's default mapping: multicast
# discovery there, each participant p's unicast ports at +10 + 2p and +11 + 2p). From domain
# 102 on (port 32900) those ports fall inside Linux's ephemeral range, 32768-60999
# (/proc/sys/net/ipv4/ip_local_port_range), from which the kernel picks the local port of every
# outgoing socket: any program's connection could then hold a port a test's participant needs
# (its bind fails, or it reads another's datagrams). Domain 101 starts at 32650, below it for
# the first 53 participants; a test has a handful. Domains below 20 are left to people's own
# ROS 2 and DDS programs (ROS 2 runs in domain 0 by default).
FIRST, LAST = 20, 101


class Domain:
    def __init__(self):
        count = LAST - FIRST + 1
        start = random.randrange(count)
        for k in range(count):
            domain = FIRST + (start + k) % count
            f = open(f"/tmp/arbc-dds-domain-{domain}.lock", "w")
            try:
                fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                f.close()
                continue
            self.file, self.id = f, domain
            remove_port_segments(domain)
            return
        raise SystemExit(f"FAIL: no free DDS domain (the {count} lock files "
                         f"/tmp/arbc-dds-domain-{FIRST}..{LAST}.lock are held)")


def remove_port_segments(domain):
    """Fast-DDS's shared-memory files for the ports of `domain` (its default port plan: 250
    ports from 7400 + 250 * domain), with their lock files."""
    first = 7400 + 250 * domain
    for path in glob.glob("/dev/shm/fastrtps_port*"):
        number = os.path.basename(path)[len("fastrtps_port"):].split("_")[0]
        if number.isdigit() and first <= int(number) < first + 250:
            try:
                os.unlink(path)
            except OSError:
                pass  # another user's, or gone already


def environment(profile):
    """The environment of a DDS process of the tests: the loopback profile."""
    return dict(os.environ, FASTRTPS_DEFAULT_PROFILES_FILE=profile)


def scratch_folder(prefix):
    """A new folder under /tmp for one test's files, removed when the test's process ends
    (hundreds were left behind otherwise); what a failure needs is printed before that."""
    path = tempfile.mkdtemp(prefix=prefix)
    atexit.register(shutil.rmtree, path, True)
    return path
