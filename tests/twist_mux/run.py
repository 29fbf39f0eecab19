"""Golden tests of `arbc import twist_mux` (docs/twist_mux.md), and the documented example's flow.

usage: run.py ARBC

Each folder CASE holds the YAML files of one configuration (all *.yaml, sorted) and CASE.out:
the import's exit code and stderr, then the spec and deployment it wrote. ARBC_UPDATE_GOLDEN=1
rewrites CASE.out instead of comparing (scripts/golden.py --bless twist_mux).

`documented` is twist_mux's own example configuration (its topics and locks files, values as
its documentation gives them): joystick and tablet share priority 100, so the import warns, the
spec it writes is refuted by `arbc verify` (those two rules), and once tablet's priority is 95
it is proved and its generated tests pass.
"""
import os
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def golden(arbc, case, out_dir):
    yamls = sorted(p.name for p in case.glob("*.yaml"))
    spec, deploy = out_dir / f"{case.name}.spec", out_dir / f"{case.name}.deploy.json"
    code, _, err = run([arbc, "import", "twist_mux", *yamls, "-o", str(spec), "--deploy",
                        str(deploy)], case)
    text = f"# arbc import twist_mux {' '.join(yamls)} (exit {code})\n## stderr\n{err}"
    for f in (spec, deploy):
        if f.exists():
            text += f"## {f.name}\n{f.read_text()}"
    text = text.replace(str(out_dir), "OUT")  # the scratch folder differs each run
    want_file = case / f"{case.name}.out"
    if os.environ.get("ARBC_UPDATE_GOLDEN"):
        want_file.write_text(text)
        return []
    want = want_file.read_text() if want_file.exists() else ""
    return [] if text == want else [f"{case.name}: output differs from {want_file}\n{text}"]


def documented_flow(arbc, work):
    case = HERE / "documented"
    topics = (case / "twist_mux_topics.yaml").read_text()
    locks = case / "twist_mux_locks.yaml"
    fails = []
    tied, fixed = work / "tied.spec", work / "fixed.spec"
    run([arbc, "import", "twist_mux", str(case / "twist_mux_topics.yaml"), str(locks), "-o",
         str(tied)], work)
    code, out, _ = run([arbc, "verify", str(tied)], work)
    if code != 1 or "rules 'joystick' and 'tablet' of Base.cmd_vel can both be selected" not in out:
        fails.append(f"the tied spec: verify exit {code}, want 1 naming joystick and tablet\n{out}")
    i = topics.rindex("priority: 100")  # tablet's
    (work / "topics.yaml").write_text(topics[:i] + "priority: 95" + topics[i + 13:])
    code, _, err = run([arbc, "import", "twist_mux", "topics.yaml", str(locks), "-o", str(fixed)],
                       work)
    if code != 0 or "twist-mux-choice" in err:
        fails.append(f"the resolved configuration: import exit {code}, warnings:\n{err}")
    code, out, _ = run([arbc, "verify", str(fixed)], work)
    if code != 0 or "proved: 1 port, 4 rules" not in out:
        fails.append(f"the resolved spec: verify exit {code}\n{out}")
    code, out, err = run([arbc, "test", str(fixed)], work)
    if code != 0 or "7 tests, 7 passed" not in out:
        fails.append(f"the resolved spec's tests: exit {code}\n{out}{err}")
    return fails


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    arbc = sys.argv[1]
    fails = []
    with tempfile.TemporaryDirectory() as tmp:
        for case in sorted(p for p in HERE.iterdir() if p.is_dir() and p.name != "__pycache__"):
            fails += golden(arbc, case, pathlib.Path(tmp))
        if not os.environ.get("ARBC_UPDATE_GOLDEN"):
            fails += documented_flow(arbc, pathlib.Path(tmp))
    for f in fails:
        print("FAIL", f)
    print(f"{len(fails)} failures")
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
