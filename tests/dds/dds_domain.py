"""A DDS domain of its own for one test run (split_run.py, interop.py).

Each run holds a lock file /tmp/arbc-dds-domain-N.lock for its domain N while it lives, so
parallel ctest runs (in this checkout or another) never share a domain; together with
loopback_profile.xml no DDS traffic of a test leaves the machine or reaches another test.
"""
import fcntl
import os
import random


class Domain:
    def __init__(self):
        start = random.randrange(200)
        for k in range(200):
            domain = 20 + (start + k) % 200
            f = open(f"/tmp/arbc-dds-domain-{domain}.lock", "w")
            try:
                fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                f.close()
                continue
            self.file, self.id = f, domain
            return
        raise SystemExit("FAIL: no free DDS domain (200 lock files under /tmp are held)")


def environment(profile):
    """The environment of a DDS process of the tests: the loopback profile."""
    return dict(os.environ, FASTRTPS_DEFAULT_PROFILES_FILE=profile)
