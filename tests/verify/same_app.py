#!/usr/bin/env python3
"""A spec that copies another's app to add properties (tests/verify/table_clean_temporal.spec
copies specs/table_clean.spec) must keep up with it: the declarations of ORIGINAL before its
first `test` must be those of COPY before its first property over time, assumption or rate,
comments and blank lines aside. Without this check the copy could prove properties of an app
that no longer exists.

usage: same_app.py ORIGINAL COPY   (exit 0 when they match, 1 with the first difference)
"""
import re
import sys

ENDS_ORIGINAL = re.compile(r"^test\s")
ENDS_COPY = re.compile(r"^(never|only|assume|after|stable|given)\s")


def app_part(path, ends):
    lines = []
    for raw in open(path, encoding="utf-8"):
        line = re.sub(r"\s*//.*$", "", raw).rstrip()
        if not line.strip():
            continue
        if ends.match(line):
            break
        lines.append(line)
    return lines


def main():
    original, copy = sys.argv[1], sys.argv[2]
    a, b = app_part(original, ENDS_ORIGINAL), app_part(copy, ENDS_COPY)
    for k, (x, y) in enumerate(zip(a, b)):
        if x != y:
            print(f"{copy} no longer copies {original}: declaration {k + 1} differs:\n"
                  f"  {original}: {x}\n  {copy}: {y}")
            return 1
    if len(a) != len(b):
        print(f"{copy} no longer copies {original}: {len(a)} declaration lines against {len(b)}")
        return 1
    print(f"{copy}: the app of {original} ({len(a)} lines)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
