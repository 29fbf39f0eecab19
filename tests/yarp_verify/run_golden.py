#!/usr/bin/env python3
"""Golden tests of `arbc verify APP.xml` and `arbc import yarp` (tests/yarp_verify/<case>/).

usage: run_golden.py ARBC [--update] [CASE...]

For each case folder holding <case>.xml, runs `arbc verify <case>.xml` inside it and compares
its exit code, stdout and stderr with <case>.out. When the case has <case>.spec, it also copies
the folder to a temporary one, runs `arbc import yarp <case>.xml -o <case>.spec` there, compares
the written spec with <case>.spec, and the import's exit code and stderr (its warnings) followed
by `arbc verify <case>.spec`'s output with <case>.import.out; it checks that `arbc check` accepts
the spec and that `arbc verify` gives it the XML's verdict, with and without --strict, and counts
the XML's rules (a feed, `when false`, is none). Finally
every yarp-* id of `arbc check --list-ids` must appear in some <case>.out or <case>.import.out
(yarp-spec-name is the import's alone). --update rewrites the .out, .import.out and .spec files
(review them by eye). Cases share the monitors of monitors/ through symbolic links (YARP follows
them, tests/yarp_real runs them); the temporary copies hold the files themselves.
YARP_DATA_HOME and YARP_DATA_DIRS are cleared, so monitors are found only beside the XML.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ENV = {k: v for k, v in os.environ.items() if k not in ("YARP_DATA_HOME", "YARP_DATA_DIRS")}


def run(args, cwd):
    p = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=120, env=ENV)
    return p.returncode, p.stdout, p.stderr


def verify_text(arbc, name, folder):
    code, out, err = run([arbc, "verify", name + ".xml"], folder)
    return code, f"# arbc verify {name}.xml (exit {code})\n## stdout\n{out}## stderr\n{err}"


def rules_counted(out):
    """The summary's rule count ("proved: 1 port, 2 rules; ..."), or None."""
    m = re.search(r"^[a-z]+: \d+ ports?, (\d+) rules?;", out, re.M)
    return m and int(m.group(1))


def check_import(arbc, name, folder, update, xml_code, xml_rules):
    """Failures of the import half of a case, as a list of strings."""
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        copy = os.path.join(tmp, name)
        shutil.copytree(folder, copy)
        os.remove(os.path.join(copy, name + ".spec"))
        code, _, err = run([arbc, "import", "yarp", name + ".xml", "-o", name + ".spec"], copy)
        if code != 0:
            return [f"{name}: arbc import exited {code}\n{err}"]
        said = (f"# arbc import yarp {name}.xml -o {name}.spec (exit {code})\n"
                f"## stderr\n{err}")
        written = open(os.path.join(copy, name + ".spec"), encoding="utf-8").read()
        golden = os.path.join(folder, name + ".spec")
        if update:
            open(golden, "w", encoding="utf-8").write(written)
        if written != open(golden, encoding="utf-8").read():
            failures.append(f"{name}: imported spec differs from {name}.spec\n{written}")
        code, _, err = run([arbc, "check", name + ".spec"], copy)
        if code != 0:
            failures.append(f"{name}: arbc check rejects the imported spec\n{err}")
        code, out, err = run([arbc, "verify", name + ".spec"], copy)
        said += f"# arbc verify {name}.spec (exit {code})\n## stdout\n{out}## stderr\n{err}"
        if code != xml_code:
            failures.append(f"{name}: the spec verifies with exit {code}, the XML with "
                            f"{xml_code}\n{out}{err}")
        # A feed (`when false`) is not a rule that delivers, in the XML or in the spec.
        if xml_rules is not None and rules_counted(out) != xml_rules:
            failures.append(f"{name}: the spec's summary counts {rules_counted(out)} rules, the "
                            f"XML's {xml_rules}\n{out}")
        # --strict makes dead and unused rules errors: a feed (`when false`) must not be one.
        strict = [run([arbc, "verify", "--strict", f], copy)[0]
                  for f in (name + ".xml", name + ".spec")]
        if strict[0] != strict[1]:
            failures.append(f"{name}: with --strict the spec verifies with exit {strict[1]}, "
                            f"the XML with {strict[0]}")
        said_path = os.path.join(folder, name + ".import.out")
        if update:
            open(said_path, "w", encoding="utf-8").write(said)
        if not os.path.exists(said_path):
            failures.append(f"{name}: no {name}.import.out (run with --update and review it)")
        elif said != open(said_path, encoding="utf-8").read():
            failures.append(f"{name}: the import's output differs from {name}.import.out\n{said}")
    return failures


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    arbc = os.path.abspath(args[0])
    update = "--update" in args or bool(os.environ.get("ARBC_UPDATE_GOLDEN"))  # scripts/golden.py --bless
    only = [a for a in args[1:] if a != "--update"]
    cases = sorted(d for d in os.listdir(HERE)
                   if os.path.isfile(os.path.join(HERE, d, d + ".xml")))
    if only:
        cases = [c for c in cases if c in only]
    failures, seen = [], set()
    for name in cases:
        folder = os.path.join(HERE, name)
        code, text = verify_text(arbc, name, folder)
        xml_rules = rules_counted(text)
        out_path = os.path.join(folder, name + ".out")
        if update:
            open(out_path, "w", encoding="utf-8").write(text)
        expected = open(out_path, encoding="utf-8").read() if os.path.exists(out_path) else None
        seen.update(re.findall(r"\[(yarp-[a-z-]+)\]$", expected or "", re.M))
        if code < 0:
            failures.append(f"{name}: killed by signal {-code}")
        elif expected is None:
            failures.append(f"{name}: no {name}.out (run with --update and review it)")
        elif text != expected:
            failures.append(f"{name}: output differs\n--- expected\n{expected}--- actual\n{text}")
        if os.path.exists(os.path.join(folder, name + ".spec")):
            failures += check_import(arbc, name, folder, update, code, xml_rules)
            said_path = os.path.join(folder, name + ".import.out")
            if os.path.exists(said_path):
                said = open(said_path, encoding="utf-8").read()
                seen.update(re.findall(r"\[(yarp-[a-z-]+)\]$", said, re.M))
    if not only:
        listed = run([arbc, "check", "--list-ids"], HERE)[1]
        declared = {l.split()[0] for l in listed.splitlines() if l.startswith("yarp-")}
        for missing in sorted(declared - seen):
            failures.append(f"diagnostic id [{missing}] has no golden case in tests/yarp_verify/")
    for f in failures:
        print("FAIL", f)
    print(f"{len(cases)} cases, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
