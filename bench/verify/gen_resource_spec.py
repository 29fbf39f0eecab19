#!/usr/bin/env python3
"""Writes a spec with one resource over PORTS ports and RULES data-guarded rules (issue 18).

usage: gen_resource_spec.py RULES PORTS OUT.spec [--no-resource]

Every rule reads the same source and is selected in the same event state (`when e_idle`), so
only message data keeps the rules of one port apart: rule k accepts a reading whose `d` lies in
its own band [k/10, (k+1)/10) and emits a command that moves the arm. A resource is proved over
two decisions in a row (docs/checks.md#resource), and the next message may be another, so data
alone does not keep two ports apart: each port's delivery sets a delivery event (`e_busyP`, what
the arm was told, unless it is "stop") that every other port's rules exclude, as
docs/checks.md's fix says. `arbc verify` proves the spec. With --no-resource the resource is
left out (the events stay): the per-port proofs alone (the baseline).
"""
import sys


def main():
    rules, ports, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    resource = "--no-resource" not in sys.argv[4:]
    lines = [
        'app resource_bench "a resource over many data-guarded rules";',
        "type Reading = { d: float, zone: int, label: string };",
        "type Cmd = { verb: string, speed: float };",
        "module Sensor { out reading: Reading; }",
        "module Status { out flags: list<string>; }",
        "events from Status.flags { e_idle } lifetime 0.5s;",
    ]
    for p in range(ports):
        lines.append(f"module Arm{p} {{ in cmd: Cmd; }}")
    for p in range(ports):
        lines.append(f'event e_busy{p} = Arm{p}.cmd : cmd.verb != "stop" for 1s;')
    for p in range(ports):
        others = "".join(f" and not e_busy{q}" for q in range(ports) if q != p)
        lines.append(f"arbitrate Arm{p}.cmd {{")
        for k in range(p, rules, ports):
            lines.append(f"  r{k}: from Sensor.reading when e_idle{others} {{")
            lines.append(f"    accept reading.d >= {k / 10:.1f} and reading.d < {(k + 1) / 10:.1f};")
            lines.append(f'    if reading.zone > {k % 7} {{ emit {{ verb: "move", speed: reading.d * 2.0 }}; }}')
            lines.append(f'    else {{ emit {{ verb: "slow", speed: reading.d }}; }}')
            lines.append("  }")
        lines.append("}")
    if resource:
        ports_list = ", ".join(f"Arm{p}.cmd" for p in range(ports))
        lines.append(f'resource arm {{ {ports_list} }} when emitted.verb != "stop";')
    with open(out, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
