#!/usr/bin/env python3
"""Every domain dds_domain.Domain() can hand out keeps Fast-DDS's UDP ports below Linux's
ephemeral port range (dds_domain.py says why). Each possible random start is tried with the
lock files in a directory of this test's own and no segment removed, so that no running
test's domain is touched.

usage: dds_domain_range.py TESTS_DDS_DIR
"""
import os
import random
import sys

sys.path.insert(0, sys.argv[1])
import dds_domain  # noqa: E402
from dds_domain import scratch_folder

PARTICIPANTS = 8  # more than any test runs in one domain


def highest_port(domain):
    """The highest UDP port of the first PARTICIPANTS participants in `domain` (RTPS's default
    mapping: base 7400, 250 ports per domain, unicast at +10 + 2p and +11 + 2p)."""
    return 7400 + 250 * domain + 11 + 2 * (PARTICIPANTS - 1)


def ephemeral_low():
    try:
        with open("/proc/sys/net/ipv4/ip_local_port_range") as f:
            return min(int(f.read().split()[0]), 32768)
    except OSError:
        return 32768  # Linux's default


def main():
    locks = scratch_folder("arbc-dds-domain-range-")
    real_open = open
    dds_domain.open = lambda path, mode: real_open(
        os.path.join(locks, os.path.basename(path)), mode)
    # Without the real locks, clearing a domain's shared-memory segments could take them from
    # a test that holds the domain.
    dds_domain.remove_port_segments = lambda domain: None
    low = ephemeral_low()
    seen = set()
    for start in range(1000):
        random.randrange = lambda n, start=start: start % n
        d = dds_domain.Domain()
        d.file.close()  # free again, for the next start
        seen.add(d.id)
    bad = sorted(d for d in seen if highest_port(d) >= low)
    if bad:
        print(f"FAIL: domains {bad[0]}..{bad[-1]} put Fast-DDS's ports at or above {low}, "
              f"inside the ephemeral range (domain {bad[0]}: up to port {highest_port(bad[0])})")
        sys.exit(1)
    if min(seen) < 20:
        print(f"FAIL: domain {min(seen)} is one people's own DDS programs may use")
        sys.exit(1)
    print(f"ok: domains {min(seen)}..{max(seen)}, highest port {highest_port(max(seen))} < {low}")


if __name__ == "__main__":
    main()
