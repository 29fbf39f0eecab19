#!/usr/bin/env python3
"""Generates app.json files for the `arbc verify` benchmarks (bench/figures/verify.sh).

usage: gen_verify_app.py PORTS RULES EVENTS OVERLAPS OUT.json [cube|dnf]

Each port gets RULES rules. Rule i's guard is a full assignment (a cube) over the first
k = ceil(log2(RULES)) events, so distinct rules are pairwise exclusive, plus one positive literal
over the remaining events, so the port's scope has EVENTS events. The last OVERLAPS rules of each
port reuse the assignments of the first OVERLAPS rules, so exactly OVERLAPS pairs overlap.
With `dnf`, rule i's guard is instead the disjunction of two such cubes (assignments 2i and
2i+1): still pairwise exclusive, but no longer cubes, so the verifier's cube shortcut cannot
settle the port and the proof goes to Z3.
A feed sets every event, so no `unfed` or `unused` finding distracts from the proof.
"""
import json
import math
import sys


def constraint(text):
    # app.json (schema 2) carries a constraint as its text, the one representation.
    return text


def main():
    ports, rules, events, overlaps, out = sys.argv[1:6]
    ports, rules, events, overlaps = int(ports), int(rules), int(events), int(overlaps)
    shape = sys.argv[6] if len(sys.argv) > 6 else "cube"
    assert shape in ("cube", "dnf"), "shape is cube or dnf"
    per_rule = 2 if shape == "dnf" else 1
    bits = max(1, math.ceil(math.log2(max(2, per_rule * (rules - overlaps)))))
    assert events > bits, "need more events than assignment bits"
    names = [f"e{i}" for i in range(events)]
    app = {"schema_version": 2, "name": f"bench_{ports}x{rules}", "description": "",
           "spec_file": "", "modules": [], "events": [], "connections": [],
           "arbitrated_ports": []}
    for p in range(ports):
        port = f"M{p}.in"
        rule_names = []
        for i in range(rules):
            code = i if i < rules - overlaps else i - (rules - overlaps)
            cubes = []
            for c in range(per_rule * code, per_rule * code + per_rule):
                lits = [names[b] if c >> b & 1 else "not " + names[b] for b in range(bits)]
                lits.append(names[bits + i % (events - bits)])
                cubes.append(" and ".join(lits))
            text = cubes[0] if per_rule == 1 else " or ".join(f"({c})" for c in cubes)
            name = f"r{i}"
            rule_names.append(name)
            app["connections"].append({
                "name": name, "source": f"S{i}.out", "destination": port, "kind": "rule",
                "generated": False, "constraint": constraint(text),
                "sets": [], "unsets": [], "must_set": [], "must_unset": [], "opaque": False,
                "trig_interval": None, "throttle": None, "monitor": ""})
        app["connections"].append({
            "name": f"feed{p}", "source": "Sensors.status", "destination": port, "kind": "feed",
            "generated": True, "constraint": constraint("false"), "sets": names,
            "unsets": names, "must_set": [], "must_unset": [], "opaque": False,
            "trig_interval": None, "throttle": None, "monitor": ""})
        app["arbitrated_ports"].append({"port": port, "by_priority": False, "complete": False,
                                        "rules": rule_names, "asserts": []})
    with open(out, "w") as f:
        json.dump(app, f)


main()
