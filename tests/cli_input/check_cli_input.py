#!/usr/bin/env python3
"""Command-line input a new user gets wrong: each case runs arbc and checks the exit code and
the words of the message (issue 13, "Smaller things a new user hit", and `arbc verify` on input
with errors).

usage: check_cli_input.py ARBC TEST_PLUGIN CASE        (run from the repository root)
"""
import json
import os
import subprocess
import sys
import tempfile

PINGPONG = "runtime/testdata/pingpong"


def run(arbc, *args, cwd=None):
    proc = subprocess.run([arbc, *args], capture_output=True, text=True, timeout=120, cwd=cwd)
    return proc.returncode, proc.stdout, proc.stderr


def expect(cond, what, out="", err=""):
    if not cond:
        sys.exit(f"FAIL: {what}\n--- stdout\n{out}\n--- stderr\n{err}")


def expect_bad_input(result, *words):
    code, out, err = result
    expect(code == 2, f"exit {code}, expected 2", out, err)
    for w in words:
        expect(w in err, f"stderr lacks {w!r}", out, err)
    expect(len(err) < 400, "the message is not short", out, err)


def case_seed_negative(arbc, plugin):
    expect_bad_input(run(arbc, "run", PINGPONG, "--plugin", plugin, "--seed", "-1"),
                     "--seed '-1' is not a whole number from 0 to 18446744073709551615")


def case_seed_too_large(arbc, plugin):
    expect_bad_input(run(arbc, "run", PINGPONG, "--plugin", plugin,
                         "--seed", "18446744073709551616"), "--seed '18446744073709551616'")


def case_duration_without_unit(arbc, plugin):
    expect_bad_input(run(arbc, "run", PINGPONG, "--plugin", plugin, "--duration", "5"),
                     "--duration '5' is not a positive duration with its unit",
                     "(write 5s for seconds)")


def case_timeout_zero(arbc, plugin):
    expect_bad_input(run(arbc, "verify", "--timeout", "0", "tests/verify/table_clean.app.json"),
                     "--timeout: '0' is not a positive number of seconds")


def case_run_takes_app_json(arbc, plugin):
    code, out, err = run(arbc, "run", PINGPONG + "/app.json", "--plugin", plugin)
    expect(code == 0 and "result: success" in out, f"exit {code}", out, err)


def case_malformed_app_json(arbc, plugin):
    with tempfile.TemporaryDirectory() as d:
        os.mkdir(os.path.join(d, "monitors"))
        with open(os.path.join(d, "app.json"), "w") as f:
            f.write('{\n  "schema_version": 1,\n  "name": "x",,\n}\n')
        code, out, err = run(arbc, "run", d, "--plugin", plugin)
        expect_bad_input((code, out, err), "app.json: not valid JSON at line 3, column 15:")
        expect(err.count("rebuild") == 1, "the rebuild hint is not given exactly once", out, err)
        with open(os.path.join(d, "app.json"), "w") as f:
            f.write(json.dumps({"schema_version": 99}))
        code, out, err = run(arbc, "run", d, "--plugin", plugin)
        expect_bad_input((code, out, err), "this arbc reads version 2, the file has 99")
        expect(err.count("rebuild") == 1, "the rebuild hint is not given exactly once", out, err)


def case_script_error_cites_the_script(arbc, plugin):
    code, out, err = run(arbc, "run", "tests/cli_input/script_error/script_error.spec",
                         "--plugin", plugin, "--duration", "3s")
    expect(code == 3, f"exit {code}, expected 3 (a quarantined connection)", out, err)
    expect("accept failed: tests/cli_input/script_error/go.lua:3: too many: 3" in err,
           "the error does not cite go.lua:3", out, err)
    expect("monitors/" not in err, "an error cites the generated monitor", out, err)


CASES = {name[len("case_"):]: fn for name, fn in globals().items() if name.startswith("case_")}

if __name__ == "__main__":
    if len(sys.argv) != 4 or sys.argv[3] not in CASES:
        sys.exit(__doc__ + "cases: " + ", ".join(sorted(CASES)))
    CASES[sys.argv[3]](os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]))
    print("ok")
