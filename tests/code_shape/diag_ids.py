#!/usr/bin/env python3
"""Diagnostic ids are named, never spelt (core/check_ids.h): in the production sources, no string
literal that is a diagnostic id is assigned to a diagnostic's `id` or a finding's `check`, or
passed where an id goes. Functions that take an id take a `DiagId`, so the compiler refuses a
literal there; this test covers the assignments the compiler cannot see (`d.id = "syntax";`).

usage: diag_ids.py ROOT           (exit 1 with each place; --self-test checks the matcher)
"""
import os
import re
import sys

FOLDERS = ("cli", "compiler", "core", "dds", "harness", "import", "lsp", "report", "runtime",
           "verify")
ASSIGN = re.compile(r'(?:\.|->)(?:id|check)\s*=\s*"([a-z0-9-]+)"')


def ids(root):
    text = open(os.path.join(root, "core", "check_ids.def"), encoding="utf-8").read()
    return set(re.findall(r'^ARBC_DIAG\(\w+, "([a-z0-9-]+)"', text, re.M))


def offences(text, known):
    return [m.group(1) for m in ASSIGN.finditer(text) if m.group(1) in known]


def self_test():
    known = {"syntax", "io"}
    assert offences('  d.id = "syntax";', known) == ["syntax"]
    assert offences('  problem->id = "io";', known) == ["io"]
    assert offences('  f.check = "io";', known) == ["io"]
    assert offences('  d.id = diag::Syntax.text();', known) == []
    assert offences('  l.id = "yarp";', known) == []  # not an id
    print("ok: the matcher finds spelt ids and leaves named ones")


def main():
    if sys.argv[1:] == ["--self-test"]:
        self_test()
        return
    root = sys.argv[1]
    known = ids(root)
    bad = []
    for folder in FOLDERS:
        for here, _, files in os.walk(os.path.join(root, folder)):
            for name in files:
                if not name.endswith((".cc", ".h")) or name.endswith("_test.cc"):
                    continue
                path = os.path.join(here, name)
                text = open(path, encoding="utf-8").read()
                for i, line in enumerate(text.splitlines(), 1):
                    for found in offences(line, known):
                        bad.append(f"{os.path.relpath(path, root)}:{i}: the id \"{found}\" is "
                                   f"spelt; name it (diag::..., core/check_ids.h)")
    if bad:
        print("\n".join(bad))
        sys.exit(1)
    print(f"ok: {len(known)} ids, none spelt in an assignment")


if __name__ == "__main__":
    main()
