#!/usr/bin/env python3
"""Runs the kept cases of the random differential test
(docs/reliability.md#random-differential-testing): each case folder (tests/drt/cases/NAME/: app.spec, spec.json, inputs.jsonl, end,
README) is verified and run again on its inputs, and must now agree: no claim of the report
broken by the run, no internal error, crash or hang. tests/drt/open/ holds the cases that still
disagree on today's code; `--expect-disagreement` runs those and fails on one that agrees
(it is fixed: move it to cases/).

usage: run_cases.py ARBC FOLDER... [--expect-disagreement]   (a FOLDER of case folders, or a case)
"""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from drt.cases import run_case  # noqa: E402
from drt.oracle import Arbc, Oracle  # noqa: E402


def case_folders(paths):
    for p in paths:
        if os.path.exists(os.path.join(p, "spec.json")):
            yield p
        elif os.path.isdir(p):
            for name in sorted(os.listdir(p)):
                if os.path.exists(os.path.join(p, name, "spec.json")):
                    yield os.path.join(p, name)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    expect = "--expect-disagreement" in sys.argv
    oracle = Oracle(Arbc(os.path.abspath(args[0])))
    work = tempfile.mkdtemp(prefix="arbc-drt-cases.")
    bad = n = 0
    for folder in case_folders(args[1:]):
        n += 1
        res = run_case(oracle, folder, os.path.join(work, os.path.basename(folder)))
        disagrees = bool(res.breaches) or bool(res.rejected)
        with open(os.path.join(folder, "README")) as f:
            readme = f.readline().strip()
        if disagrees != expect:
            bad += 1
            print(f"FAIL  {folder}: {readme}")
            for b, _ in res.breaches:
                print(f"  [{b.claim}] {b.what}: {b.detail}")
            if res.rejected:
                print(f"  arbc check refuses it: {', '.join(res.rejected)}")
            if expect:
                print("  it agrees now: move it to tests/drt/cases/")
        else:
            print(f"PASS  {folder}" + (" (still disagrees)" if expect else ""))
    print(f"{n} cases, {bad} failed" + (f" (work folder {work})" if bad else ""))
    if not bad:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if bad or n == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
