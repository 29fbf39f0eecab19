#!/usr/bin/env python3
"""Golden tests for `arbc check` (tests/check/<case>/<case>.spec + <case>.err).

usage: run_golden.py ARBC [--update] [CASE...]

For each case, runs `arbc check <case>.spec` inside the case's folder and compares what it
prints on stderr with <case>.err, byte for byte. The message path of `use ros2` is the case's
`msg` folder when it has one, else empty (ARBC_MSG_PATH and AMENT_PREFIX_PATH of the caller are
not passed on: what a case prints does not depend on the machine). The expected exit code is 2 when <case>.err
holds an error and 0 otherwise (empty, or warnings only); a signal is always a failure. Without CASEs, every case runs.
--update rewrites the .err files (review them by eye). ctest runs each case as its own test
(check_golden.CASE). That every diagnostic id has a golden case is check_ids_covered.py's job.
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def run_case(arbc, name):
    folder = os.path.join(HERE, name)
    env = {k: v for k, v in os.environ.items() if k not in ("ARBC_MSG_PATH", "AMENT_PREFIX_PATH")}
    if os.path.isdir(os.path.join(folder, "msg")):
        env["ARBC_MSG_PATH"] = "msg"
    proc = subprocess.run([arbc, "check", name + ".spec"], cwd=folder, capture_output=True,
                          timeout=60, env=env)
    return proc.returncode, proc.stderr.decode("utf-8", "replace"), proc.stdout


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    arbc = os.path.abspath(args[0])
    update = "--update" in args or bool(os.environ.get("ARBC_UPDATE_GOLDEN"))  # scripts/golden.py --bless
    only = [a for a in args[1:] if a != "--update"]
    cases = sorted(d for d in os.listdir(HERE)
                   if os.path.exists(os.path.join(HERE, d, d + ".spec")))
    if only:
        unknown = sorted(set(only) - set(cases))
        if unknown:
            sys.exit(f"no such case: {', '.join(unknown)}")
        cases = [c for c in cases if c in only]
    failures = []
    for name in cases:
        err_path = os.path.join(HERE, name, name + ".err")
        code, err, out = run_case(arbc, name)
        if update:
            with open(err_path, "w", encoding="utf-8") as f:
                f.write(err)
        expected = open(err_path, encoding="utf-8").read() if os.path.exists(err_path) else None
        want_code = 2 if expected and ": error: " in expected else 0
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
    for f in failures:
        print("FAIL", f)
    print(f"{len(cases)} cases run, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
