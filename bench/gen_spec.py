#!/usr/bin/env python3
"""Generates a valid arbc spec of a chosen size, for benchmarks and stress tests.

usage: gen_spec.py [--rules N] [--ports P] [--sources S] [--bodies] [--name NAME]

The spec has S source modules (out value: float), P arbitrated destination ports
(in cmd: float) and N rules spread evenly over the ports. Within a port, rule k's
constraint is the binary code of k over the port's own events, so the rules of a port are
pairwise exclusive (`arbc verify` proves them) and every constraint is satisfiable.
With --bodies each rule has a small monitor body (accept, let, if/else, emit).
The spec goes to stdout.
"""
import argparse
import math
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rules", type=int, default=10000)
    parser.add_argument("--ports", type=int, default=50)
    parser.add_argument("--sources", type=int, default=20)
    parser.add_argument("--bodies", action="store_true")
    parser.add_argument("--name", default="generated")
    args = parser.parse_args()
    if args.rules < 1 or args.ports < 1 or args.sources < 1:
        sys.exit("gen_spec.py: --rules, --ports and --sources must be at least 1")

    out = []
    w = out.append
    w(f'app {args.name} "generated: {args.rules} rules over {args.ports} ports";')
    w("")
    w("const THRESHOLD = 0.5;")
    for s in range(args.sources):
        w(f"module Source{s} {{ out value: float; }}")
    for p in range(args.ports):
        w(f"module Actuator{p} {{ in cmd: float; }}")
    w("")
    per_port = [args.rules // args.ports + (1 if p < args.rules % args.ports else 0)
                for p in range(args.ports)]
    for p in range(args.ports):
        bits = max(1, math.ceil(math.log2(max(2, per_port[p]))))
        names = ", ".join(f"e{p}_{b}" for b in range(bits))
        w(f"event {names} lifetime 1s;")
    w("")
    rule = 0
    for p in range(args.ports):
        if per_port[p] == 0:
            continue
        bits = max(1, math.ceil(math.log2(max(2, per_port[p]))))
        w(f"arbitrate Actuator{p}.cmd {{")
        for k in range(per_port[p]):
            terms = [("" if (k >> b) & 1 else "not ") + f"e{p}_{b}" for b in range(bits)]
            source = f"Source{rule % args.sources}"
            head = f"  r{rule}: from {source}.value when {' and '.join(terms)}"
            if args.bodies:
                w(head + " {")
                w("    accept value > 0.0;")
                w("    let scaled = value * 2.0;")
                w("    if scaled > THRESHOLD { emit scaled; } else { emit THRESHOLD; }")
                w("  }")
            else:
                w(head + ";")
            rule += 1
        w("}")
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
