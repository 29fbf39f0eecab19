#!/usr/bin/env python3
"""Every Z3 query goes through verify::check (verify/solver_timeout.h): the one place that arms
the run's deadline, tells the watchdog a query is in flight and classifies an unknown. A
`.check(` on a solver anywhere else in production code would run without the deadline (an
`arbc verify --timeout 10` that ran for minutes) or be interrupted outside a query. Tests may
ask Z3 directly.

usage: one_z3_query.py ROOT | --self-test
"""
import os
import re
import sys

HOME = "verify/solver_timeout.cc"
FOLDERS = ["verify", "compiler", "runtime", "cli", "harness", "import", "lsp", "dds", "report",
           "core"]


def is_test(name):
    return name.endswith(("_test.cc", "_test.h")) or name.startswith("test_models")


def queries(text):
    """Lines calling check( on a z3::solver: one named as this code base names them, or any
    name the file declares a z3::solver."""
    names = set(re.findall(r"z3::solver[&*]?\s+(\w+)", text)) | {"solver", "solver_", "s"}
    query = re.compile(r"\b(" + "|".join(sorted(names)) + r")(\.|->)check\(")
    return [n for n, line in enumerate(text.splitlines(), 1) if query.search(line.split("//")[0])]


def self_test():
    assert queries("  z3::check_result r = solver.check();\n") == [1]
    assert queries("  if (s->check(v) == z3::sat) {}\n") == [1]
    assert queries("  z3::solver tmp(ctx);\n  tmp.check();\n") == [2]
    assert queries("  r = check(solver, timeout_, &why);\n") == []
    assert queries("  // solver.check() is never called here\n") == []
    assert queries("  if (!lua.check(text, path, &error)) {}\n") == []
    print("ok")


def main():
    if sys.argv[1] == "--self-test":
        return self_test()
    root = sys.argv[1]
    bad, checked = [], 0
    for folder in FOLDERS:
        for dirpath, _, files in os.walk(os.path.join(root, folder)):
            for name in files:
                path = os.path.relpath(os.path.join(dirpath, name), root)
                if not name.endswith((".cc", ".h")) or is_test(name) or path == HOME:
                    continue
                checked += 1
                with open(os.path.join(root, path), encoding="utf-8") as f:
                    bad += [f"{path}:{n}: asks Z3 directly; use verify::check" for n in queries(f.read())]
    with open(os.path.join(root, HOME), encoding="utf-8") as f:
        home = len(queries(f.read()))
    print("\n".join(bad + [f"{checked} files, {len(bad)} queries outside {HOME} ({home} there)"]))
    return 1 if bad or home == 0 or checked < 100 else 0


if __name__ == "__main__":
    sys.exit(main())
