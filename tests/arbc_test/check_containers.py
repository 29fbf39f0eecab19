#!/usr/bin/env python3
"""`arbc test`'s event states read one container (issue 38 item 4, docs/testing.md).

usage: check_containers.py ARBC CASE        (run from the repository root)

Every arbitrated port owns an event container; the same event name in two ports is two facts.
`e_lock` is set by rule `lock` into X.x's container only, and `never b while e_lock` over Y.y
says nothing (verify calls it vacuous): b delivers at 100 ms while e_lock is present in X.x.
"""
import os
import subprocess
import sys
import tempfile

SPEC = """app vacuous;
type Cmd = { v: float };
module B { out b: Cmd; }
module L { out l: Cmd; }
module S { out flags: list<string>; }
module X { in x: Cmd; }
module Y { in y: Cmd; }
events from S.flags { e_idle } lifetime 1s;
event e_lock lifetime 1s;
arbitrate X.x {
  lock: from L.l when e_idle { set e_lock; }
}
arbitrate Y.y {
  b: from B.b when e_idle;
}
never b while e_lock;
test "lock" {
  at 0s S.flags <- ["e_idle"];
  at 0s L.l <- { v: 1.0 };
  at 100ms B.b <- { v: 1.0 };
  expect Y.y receives { v: 1.0 } at 100ms;
  expect never b while e_lock;
  EXPECT
}
"""


def run(arbc, tmp, expectation):
    path = os.path.join(tmp, "vacuous.spec")
    with open(path, "w", encoding="utf-8") as f:
        f.write(SPEC.replace("EXPECT", expectation))
    proc = subprocess.run([arbc, "test", path], capture_output=True, text=True, timeout=300)
    return proc.returncode, proc.stdout, proc.stderr


def expect(cond, what, out="", err=""):
    if not cond:
        sys.exit(f"FAIL: {what}\n--- stdout\n{out}\n--- stderr\n{err}")


def case_expect_reads_the_named_container(arbc, tmp):
    """`in M.p` reads M.p's container: e_lock is there in X.x, not in Y.y (where b's property
    reads it, and it holds); the bare form reads the one container e_lock lives in, X.x's."""
    for expectation in ["expect e_lock in X.x at 100ms;", "expect e_lock at 100ms;",
                        "expect not e_lock in Y.y at 100ms;", "expect e_idle in Y.y at 100ms;"]:
        code, out, err = run(arbc, tmp, expectation)
        expect(code == 0 and "1 passed, 0 failed" in out, f"{expectation}: exit {code}", out, err)
    code, out, err = run(arbc, tmp, "expect e_lock in Y.y at 100ms;")
    expect(code == 1 and "expected e_lock in Y.y at 100ms" in out, f"exit {code}", out, err)
    expect("but at 100ms e_lock is absent from Y.y's container (present in the container of X.x, "
           "another fact)" in out, "the failure does not say where e_lock is", out, err)


def case_expect_names_a_container(arbc, tmp):
    """A bare event state over an event fed into two containers, or in none, is bad input (exit
    2) at its line and column, naming the containers and what to write."""
    code, out, err = run(arbc, tmp, "expect e_idle and e_lock at 100ms;")
    expect(code == 2, f"exit {code}", out, err)
    expect("vacuous.spec:23:3: error: 'e_idle' lives in 2 event containers (X.x, Y.y)" in err and
           "[test-container]" in err, "no error at the expectation", out, err)
    expect("write `expect e_idle and e_lock in X.x at 100ms;`" in err, "no fix offered", out, err)
    code, out, err = run(arbc, tmp, "at 200ms set e_lock;\n  expect e_lock at 200ms;")
    expect(code == 0, f"a test's own set: exit {code}", out, err)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    arbc, case = os.path.abspath(sys.argv[1]), sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        globals()["case_" + case](arbc, tmp)
    print("ok")


if __name__ == "__main__":
    main()
