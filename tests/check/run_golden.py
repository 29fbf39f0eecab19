#!/usr/bin/env python3
"""Golden tests for `arbc check` (tests/check/<case>/<case>.spec + <case>.err).

usage: run_golden.py ARBC [--update] [CASE...]
       run_golden.py ARBC --ids

For each case, runs `arbc check <case>.spec` inside the case's folder and compares what it
prints on stderr with <case>.err, byte for byte. The expected exit code is 0 when <case>.err
is empty and 2 otherwise; a signal is always a failure. Without CASEs, every case runs, and
then every diagnostic id that `arbc check --list-ids` declares must appear in some case's .err,
so each error the checker can give has a golden case; --ids runs only that last check.
--update rewrites the .err files (review them by eye). ctest runs each case as its own test
(check_golden.CASE) and the id check as check_golden_ids.
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def run_case(arbc, name):
    folder = os.path.join(HERE, name)
    proc = subprocess.run([arbc, "check", name + ".spec"], cwd=folder, capture_output=True,
                          timeout=60)
    return proc.returncode, proc.stderr.decode("utf-8", "replace"), proc.stdout


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    arbc = os.path.abspath(args[0])
    update = "--update" in args
    ids_only = "--ids" in args
    only = [a for a in args[1:] if a not in ("--update", "--ids")]
    cases = sorted(d for d in os.listdir(HERE)
                   if os.path.exists(os.path.join(HERE, d, d + ".spec")))
    if only:
        unknown = sorted(set(only) - set(cases))
        if unknown:
            sys.exit(f"no such case: {', '.join(unknown)}")
        cases = [c for c in cases if c in only]
    failures = []
    seen_ids = set()
    for name in cases:
        err_path = os.path.join(HERE, name, name + ".err")
        if ids_only:
            if os.path.exists(err_path):
                seen_ids.update(re.findall(r"\[([a-z0-9-]+)\]$", open(err_path).read(), re.M))
            continue
        code, err, out = run_case(arbc, name)
        if update:
            with open(err_path, "w", encoding="utf-8") as f:
                f.write(err)
        expected = open(err_path, encoding="utf-8").read() if os.path.exists(err_path) else None
        seen_ids.update(re.findall(r"\[([a-z0-9-]+)\]$", expected or "", re.M))
        want_code = 0 if expected == "" else 2
        if code < 0:
            failures.append(f"{name}: killed by signal {-code}")
        elif expected is None:
            failures.append(f"{name}: no {name}.err (run with --update and review it)")
        elif err != expected:
            failures.append(f"{name}: output differs\n--- expected\n{expected}--- actual\n{err}")
        elif code != want_code:
            failures.append(f"{name}: exit code {code}, expected {want_code}")
        elif out:
            failures.append(f"{name}: unexpected output on stdout: {out[:200]!r}")
    if not only:
        listed = subprocess.run([arbc, "check", "--list-ids"], capture_output=True, text=True,
                                check=True).stdout
        declared = {line.split()[0] for line in listed.splitlines() if line.strip()}
        # The yarp-* ids come from `arbc verify APP.xml`: tests/yarp_verify/ has their cases.
        declared = {i for i in declared if not i.startswith("yarp-")}
        for missing in sorted(declared - seen_ids):
            failures.append(f"diagnostic id [{missing}] has no golden case in tests/check/")
        for unknown in sorted(seen_ids - declared):
            failures.append(f"golden files use id [{unknown}], which --list-ids does not declare")
    for f in failures:
        print("FAIL", f)
    print(f"{0 if ids_only else len(cases)} cases run, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
