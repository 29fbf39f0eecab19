#!/usr/bin/env python3
"""A mutant of an app (tests/verify/table_clean_*_mutant.spec mutate specs/table_clean.spec to
show that `arbc verify` refutes what the mutation breaks) must stay the app plus its mutation:
the app's declarations in ORIGINAL and in MUTANT (everything before the first property over
time, assumption, rate or test), comments and blank lines aside, may differ in at most CHANGED
lines (default 1). A mutant keeps only the properties its mutation is about. Without this check
a mutant could be refuted for a difference that has nothing to do with its mutation, or drift
from the app it claims to mutate.

usage: same_app.py ORIGINAL MUTANT [CHANGED]   (exit 0 when they match, 1 with the differences)
"""
import difflib
import re
import sys

ENDS = re.compile(r"^(test|never|only|assume|after|stable|given)\s")


def app_part(path):
    lines = []
    for raw in open(path, encoding="utf-8"):
        line = re.sub(r"\s*//.*$", "", raw).rstrip()
        if not line.strip():
            continue
        if ENDS.match(line):
            break
        lines.append(line)
    return lines


def main():
    original, mutant = sys.argv[1], sys.argv[2]
    allowed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    a, b = app_part(original), app_part(mutant)
    changed = []
    for tag, i1, i2, j1, j2 in difflib.SequenceMatcher(a=a, b=b, autojunk=False).get_opcodes():
        if tag != "equal":
            changed += [f"  {original}: {x}" for x in a[i1:i2]]
            changed += [f"  {mutant}: {y}" for y in b[j1:j2]]
            allowed -= max(i2 - i1, j2 - j1)
    if allowed < 0:
        print(f"{mutant} is no longer {original} with its mutation; the differences:")
        print("\n".join(changed))
        return 1
    print(f"{mutant}: {original} ({len(a)} lines) with {len(changed)} changed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
