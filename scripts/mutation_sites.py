#!/usr/bin/env python3
"""The mutation site list (scripts/mutation_sites.txt) for scripts/mutate.sh.

usage: mutation_sites.py check ROOT [SITES]        each site's `find` occurs on exactly one
                                                   line of its file, the replacement differs
       mutation_sites.py list SITES                one line per site: id, kind
       mutation_sites.py apply ROOT ID [SITES]     applies site ID to the tree at ROOT
       mutation_sites.py show ID [SITES]           prints a site's fields
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
KEYS = ("id", "kind", "file", "find", "replace", "why")


def parse(path):
    sites, current = [], {}
    for number, line in enumerate(open(path, encoding="utf-8").read().split("\n"), 1):
        if line.startswith("#"):
            continue
        if not line.strip():
            if current:
                sites.append(current)
            current = {}
            continue
        key, sep, value = line.partition(": ")
        if not sep or key not in KEYS:
            sys.exit(f"{path}:{number}: expected 'KEY: value' with KEY one of {', '.join(KEYS)}")
        current[key] = value
        current.setdefault("line", number)
    if current:
        sites.append(current)
    return sites


def problems(root, sites):
    found, ids = [], set()
    for s in sites:
        where = f"site {s.get('id', '?')} (line {s['line']})"
        missing = [k for k in KEYS if not s.get(k)]
        if missing:
            found.append(f"{where}: missing {', '.join(missing)}")
            continue
        if s["id"] in ids:
            found.append(f"{where}: the id is used twice")
        ids.add(s["id"])
        if s["find"] == s["replace"]:
            found.append(f"{where}: the replacement is the same text")
        path = os.path.join(root, s["file"])
        if not os.path.isfile(path):
            found.append(f"{where}: no file {s['file']}")
            continue
        lines = [n for n, l in enumerate(open(path, encoding="utf-8"), 1) if s["find"] in l]
        if len(lines) != 1:
            found.append(f"{where}: `{s['find']}` is on {len(lines)} lines of {s['file']} "
                         f"({lines[:5]}), not exactly one: the code moved; fix the site")
    return found


def apply(root, site):
    path = os.path.join(root, site["file"])
    text = open(path, encoding="utf-8").read().split("\n")
    hits = [i for i, l in enumerate(text) if site["find"] in l]
    if len(hits) != 1:
        sys.exit(f"site {site['id']}: `{site['find']}` is on {len(hits)} lines of {site['file']}")
    text[hits[0]] = text[hits[0]].replace(site["find"], site["replace"], 1)
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(text))
    print(f"{site['file']}:{hits[0] + 1}: {text[hits[0]].strip()}")


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    command = args[0]
    default = os.path.join(HERE, "mutation_sites.txt")
    if command == "check" and len(args) in (2, 3):
        sites = parse(args[2] if len(args) == 3 else default)
        found = problems(args[1], sites)
        kinds = sorted({s.get("kind", "") for s in sites})
        for p in found:
            print("FAIL", p)
        print(f"{len(sites)} sites of {len(kinds)} kinds, {len(found)} problems")
        sys.exit(1 if found else 0)
    if command == "list" and len(args) <= 2:
        for s in parse(args[1] if len(args) == 2 else default):
            print(f"{s['id']}\t{s['kind']}")
        return
    if command in ("apply", "show") and len(args) >= 2:
        rest = args[1:]
        root = rest.pop(0) if command == "apply" else None
        site_id = rest.pop(0)
        sites = {s["id"]: s for s in parse(rest[0] if rest else default)}
        if site_id not in sites:
            sys.exit(f"no site {site_id}")
        if command == "apply":
            apply(root, sites[site_id])
        else:
            for k in KEYS:
                print(f"{k}: {sites[site_id][k]}")
        return
    sys.exit(__doc__)


if __name__ == "__main__":
    main()
