#!/usr/bin/env python3
"""The golden tests: run them, or rewrite them from what arbc prints now (--bless).

usage: scripts/golden.py [--bless] [--build DIR] [REGEX]

A golden test compares what arbc writes or prints with a reviewed file in the repository
(docs/contributing.md#golden-tests lists them). Every one carries the ctest label `golden`, and
every one rewrites its files instead of comparing when ARBC_UPDATE_GOLDEN is set; this script is
the one way to run them either way:

  scripts/golden.py                  every golden test (ctest -L golden), plus the verifier's
                                     report fixtures (verify_test's ReportFormatTest)
  scripts/golden.py check_golden     those whose name matches the regex
  scripts/golden.py --bless [REGEX]  rewrite their goldens, then list the files that changed:
                                     review each diff by eye (`git diff`) and say in the commit
                                     message which goldens changed and why

DIR is the build tree (default: build/ of this checkout, or $ARBC_BUILD_DIR). The build must be
current: the goldens are made by the binaries in it. Exit 0 when every test passed.
"""
import argparse
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Golden fixtures checked by a unit test rather than a ctest of their own.
UNIT_GOLDENS = "ReportFormatTest"


def run_ctest(build, args, env):
    cmd = ["ctest", "--output-on-failure", "-j", str(os.cpu_count() or 2)] + args
    print("+", " ".join(cmd), flush=True)
    return subprocess.run(cmd, cwd=build, env=env).returncode


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bless", action="store_true", help="rewrite the goldens")
    parser.add_argument("--build", default=os.environ.get("ARBC_BUILD_DIR",
                                                          os.path.join(ROOT, "build")))
    parser.add_argument("regex", nargs="?", default="")
    args = parser.parse_args()
    if not os.path.isfile(os.path.join(args.build, "CTestTestfile.cmake")):
        sys.exit(f"golden.py: {args.build} is not a configured build tree (scripts/build.sh)")
    env = dict(os.environ)
    if args.bless:
        env["ARBC_UPDATE_GOLDEN"] = "1"
    selected = ["-R", args.regex] if args.regex else []
    status = run_ctest(args.build, ["-L", "golden"] + selected, env)
    if not args.regex or args.regex in UNIT_GOLDENS:
        status |= run_ctest(args.build, ["-R", UNIT_GOLDENS], env)
    if args.bless:
        changed = subprocess.run(["git", "-C", ROOT, "status", "--short"], capture_output=True,
                                 text=True).stdout
        print("goldens rewritten; changed files (review each diff by eye before committing):")
        print(changed or "  none")
    return 1 if status else 0


if __name__ == "__main__":
    sys.exit(main())
