#!/usr/bin/env python3
"""Generates a spec with one arbitrated port of N rules by priority, for the figure of the
largest bound properties over time reach in 10 s (bench/figures/verify_temporal.sh).

usage: gen_temporal_port.py N

Every rule but the lowest holds (100 ms + 10 ms per rank), so the port's state over time is
the activity events of N-1 holds besides three fed events with lifetimes; each rule's guard is
one of those events or its negation. The highest rule has `throttle 1s`, so its property
`never two r0 within 1s` holds at every bound: the checker explores until the time is up
instead of stopping at a violation. The spec goes to stdout.
"""
import sys


def main():
    if len(sys.argv) != 2 or not sys.argv[1].isdigit() or int(sys.argv[1]) < 2:
        sys.exit(__doc__)
    n = int(sys.argv[1])
    out = [f'app deep "{n} rules by priority with holds: the temporal bound figure";',
           "type Status = list<string>;",
           "module Arm { in cmd: float; out status: Status; }"]
    out += [f"module S{k} {{ out v: float; }}" for k in range(n)]
    out.append("events from Arm.status { e_a, e_b, e_c } lifetime 0.5s;")
    out.append("arbitrate Arm.cmd by priority {")
    for k in range(n):
        guard = ["e_a", "not e_a", "e_b", "e_c"][k % 4]
        hold = "" if k == n - 1 else f" hold {100 + 10 * k}ms"
        body = "throttle 1s; " if k == 0 else ""
        out.append(f"  r{k}: from S{k}.v when {guard}{hold} {{ {body}emit v; }}")
    out += ["}", "never two r0 within 1s;"]
    print("\n".join(out))


if __name__ == "__main__":
    main()
