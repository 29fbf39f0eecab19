#!/usr/bin/env python3
"""README.md's short demo cannot go stale: its commands run and print what it shows.

usage: check_readme.py BUILD_DIR        (run from the repository root)

The README's block of `$ arbc ...` commands is what scripts/demo.sh shows, in short. In a
scratch folder with a copy of `specs/` and `build` linked to BUILD_DIR, after the demo's
`arbc build specs/table_clean.spec -o out`, each command runs (`arbc` is BUILD_DIR/cli/arbc)
and the lines shown under it must be in its output in that order; a line `...` stands for any
lines, and lines shown one after the other must follow one another. Then the paragraph after
the block: without `not e_taken and` in the `take` rule, `arbc verify` exits 1 naming take, put
and the event state the README names, and `arbc run --no-verify` reports a take while holding.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile


def demo_block(readme):
    m = re.search(r"```\n(\$ arbc .*?)```", readme, re.S)
    if not m:
        sys.exit("README.md: no ``` block of `$ arbc ...` commands")
    commands, current = [], None
    for line in m.group(1).splitlines():
        if line.startswith("$ "):
            current = (line[2:], [])
            commands.append(current)
        elif line.strip():
            current[1].append(line)
    return commands


def shown_in(shown, actual):
    """Whether the shown lines are in the actual ones in order, `...` standing for any lines."""
    groups, group = [], []
    for line in shown:
        if line.strip() == "...":
            groups.append(group)
            group = []
        else:
            group.append(line)
    groups.append(group)
    at = 0
    for index, group in enumerate(groups):
        if not group:
            continue
        anchored = index == 0  # the first group starts the output
        found = None
        for start in ([at] if anchored else range(at, len(actual) - len(group) + 1)):
            if actual[start:start + len(group)] == group:
                found = start
                break
        if found is None:
            return False
        at = found + len(group)
    return not groups[-1] or at == len(actual)  # the last group ends it


def run(cmd, cwd, arbc):
    cmd = re.sub(r"^arbc ", arbc + " ", cmd)
    return subprocess.run(["bash", "-c", cmd], cwd=cwd, capture_output=True, text=True,
                          timeout=600)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    build = os.path.abspath(sys.argv[1])
    arbc = os.path.join(build, "cli", "arbc")
    readme = open("README.md", encoding="utf-8").read()
    failures = []
    with tempfile.TemporaryDirectory(prefix="arbc-readme-") as scratch:
        shutil.copytree("specs", os.path.join(scratch, "specs"))
        os.symlink(build, os.path.join(scratch, "build"))
        built = run("arbc build specs/table_clean.spec -o out", scratch, arbc)
        if built.returncode != 0:
            sys.exit(f"arbc build failed: {built.stderr}")
        for cmd, shown in demo_block(readme):
            proc = run(cmd, scratch, arbc)
            actual = (proc.stdout + proc.stderr).splitlines()
            if proc.returncode != 0:
                failures.append(f"`{cmd}` exited {proc.returncode}")
            if not shown_in(shown, proc.stdout.splitlines()) and not shown_in(shown, actual):
                failures.append(f"`{cmd}`: the README shows\n" + "\n".join(shown) +
                                "\n--- but it printed\n" + proc.stdout + proc.stderr)
        # The paragraph after the block: the mutant without `not e_taken and` in take.
        m = re.search(r"Remove `([^`]+)` from the `take` rule.*?\(`([^`]+)`\)", readme, re.S)
        if not m:
            failures.append("README.md: no 'Remove `...` from the `take` rule' paragraph")
        else:
            removed, state = m.group(1), m.group(2)
            spec = open("specs/table_clean.spec", encoding="utf-8").read()
            take = re.search(r"^  take: from .*$", spec, re.M).group(0)
            if removed not in take:
                failures.append(f"the take rule has no `{removed}`: {take}")
            with open(os.path.join(scratch, "mutant.spec"), "w", encoding="utf-8") as f:
                f.write(spec.replace(take, take.replace(removed, "")))
            proc = run("arbc verify mutant.spec", scratch, arbc)
            if proc.returncode != 1 or "rules 'take' and 'put'" not in proc.stdout + proc.stderr \
                    or f"present: {state}; absent:" not in proc.stdout + proc.stderr:
                failures.append(f"the mutant's verify (exit {proc.returncode}) does not name "
                                f"take, put and {state}:\n{proc.stdout}{proc.stderr}")
            proc = run("arbc run mutant.spec --no-verify --plugin "
                       "build/examples/table_clean/libarbc_table_clean.so --scenario mixed "
                       "--seed 1", scratch, arbc)
            if "take_while_holding" not in proc.stdout:
                failures.append(f"the mutant's run shows no take while holding:\n{proc.stdout}")
    for f in failures:
        print("FAIL", f)
    print(f"README.md: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
