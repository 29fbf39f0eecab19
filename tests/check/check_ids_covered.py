#!/usr/bin/env python3
"""Every diagnostic id arbc can report is registered (core/check_ids.cc) and has a golden case.

usage: check_ids_covered.py ARBC REPO_ROOT

`arbc check --list-ids` prints `id stage meaning` per id. An id of stage "check" must appear as
`[id]` at the end of a line of some tests/check/<case>/<case>.err; one of stage "verify" as
`[id]`, `"check": "id"` or `"ruleId": "id"` in some tests/verify/golden/ file; one of stage
"yarp" as `[id]` in some tests/yarp_verify/<case>/<case>.out; one of stage "import" (`arbc
import twist_mux`) in some tests/twist_mux/<case>/<case>.out. Ids of stage "internal" name bugs in arbc that no input should reach, so they have no golden case. The other
way round, every id a golden file shows must be registered.
"""
import pathlib
import re
import subprocess
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    arbc, root = sys.argv[1], pathlib.Path(sys.argv[2])
    listed = subprocess.run([arbc, "check", "--list-ids"], capture_output=True, text=True,
                            check=True, timeout=60).stdout
    stage = {}
    for line in listed.splitlines():
        if line.strip():
            words = line.split()
            stage[words[0]] = words[1]
    check_text = "".join(p.read_text(encoding="utf-8", errors="replace")
                         for p in (root / "tests/check").glob("*/*.err"))
    verify_text = "".join(p.read_text(encoding="utf-8", errors="replace")
                          for p in (root / "tests/verify/golden").iterdir())
    yarp_text = "".join(p.read_text(encoding="utf-8", errors="replace")
                        for p in (root / "tests/yarp_verify").glob("*/*.out"))
    import_text = "".join(p.read_text(encoding="utf-8", errors="replace")
                          for p in (root / "tests/twist_mux").glob("*/*.out"))
    shown = {
        "import": set(re.findall(r"\[([a-z0-9-]+)\]$", import_text, re.M)),
        "yarp": set(re.findall(r"\[([a-z0-9-]+)\]$", yarp_text, re.M)),
        "check": set(re.findall(r"\[([a-z0-9-]+)\]$", check_text, re.M)),
        "verify": set(re.findall(r"\[([a-z0-9-]+)\]$", verify_text, re.M))
        | set(re.findall(r'"(?:check|ruleId)": "([a-z0-9-]+)"', verify_text)),
    }
    failures = []
    for id_, st in sorted(stage.items()):
        if st == "internal":
            continue
        if st not in shown:
            failures.append(f"[{id_}] has an unknown stage {st!r}")
        elif id_ not in shown[st]:
            where = {"check": "tests/check/", "verify": "tests/verify/golden/",
                     "yarp": "tests/yarp_verify/", "import": "tests/twist_mux/"}[st]
            failures.append(f"diagnostic id [{id_}] ({st}) has no golden case in {where}")
    for st, ids in shown.items():
        for id_ in sorted(ids - set(stage)):
            failures.append(f"golden files of stage {st} use id [{id_}], which --list-ids lacks")
    for f in failures:
        print("FAIL", f)
    print(f"{len(stage)} ids, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
