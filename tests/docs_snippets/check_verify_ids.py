#!/usr/bin/env python3
"""docs/checks.md's table of checks lists every id of the `verify` stage.

usage: check_verify_ids.py ARBC        (run from the repository root)

The ids are what `arbc check --list-ids` prints for the verify stage; the table's rows start
with the id in backquotes (`| [`exclusive`](#exclusive) | error | ... |`). An id missing from
the table is a finding a reader meets with no row to look it up in.
"""
import re
import subprocess
import sys


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    listed = subprocess.run([sys.argv[1], "check", "--list-ids"], capture_output=True, text=True,
                            timeout=60).stdout
    ids = {line.split()[0] for line in listed.splitlines()
           if len(line.split()) > 1 and line.split()[1] == "verify"}
    page = open("docs/checks.md", encoding="utf-8").read()
    rows = set(re.findall(r"^\| \[?`([a-z-]+)`", page, re.M))
    missing = sorted(ids - rows)
    for i in missing:
        print(f"FAIL docs/checks.md: the table of checks has no row for `{i}`")
    print(f"{len(ids)} verify ids, {len(missing)} missing from docs/checks.md")
    return 1 if missing or not ids else 0


if __name__ == "__main__":
    sys.exit(main())
