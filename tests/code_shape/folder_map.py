#!/usr/bin/env python3
"""docs/design.md's folder map is the tree's: every folder is listed, and every include of the
production code goes where the map says its folder may depend.

usage: folder_map.py ROOT          check the tree at ROOT (its tracked files)
       folder_map.py --self-test   check that each kind of mismatch is caught

The map is the table under "## Folder map": `| `folder/` | what | depends on |`. A folder is
named with its slash (`compiler/frontend/` for a part of one); a file belongs to the longest
folder of the map that holds it. The "depends on" cell lists, in backticks, the folders whose
headers the folder's code may include (`core/`, `runtime/`); a cell saying "anything" allows
every folder, and a cell with no folder in backticks allows none (`grammar/`: the ANTLR
runtime only). A folder's own files may include each other.

Fails when a top-level folder that holds tracked files has no row (a row for one of its parts
is enough), when a row names a folder the tree does not have, or when a production file (not
a *_test.cc, a test utility or a file under tests/, testing/ or testdata/) includes a header of
a folder its row does not allow. Exit 0 all fine, 1 otherwise, 77 (skipped) outside a git
checkout.
"""
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import long_functions  # noqa: E402  (is_test_file: the one definition of test code)

ROW = re.compile(r"^\|\s*`([\w./-]+/)`\s*\|(.*)\|(.*)\|\s*$")
FOLDER = re.compile(r"`([\w.-]+(?:/[\w.-]+)*)/`")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
SOURCES = (".cc", ".cpp", ".h", ".hpp")


def read_map(design_text):
    """{folder: set of allowed folders, or None for anything}, from the folder map's table."""
    rows = {}
    in_map = False
    for line in design_text.splitlines():
        if line.startswith("## "):
            in_map = line.strip() == "## Folder map"
            continue
        m = ROW.match(line) if in_map else None
        if not m:
            continue
        folder, depends = m.group(1).rstrip("/"), m.group(3)
        rows[folder] = None if "anything" in depends else {f for f in FOLDER.findall(depends)}
    return rows


def owner(path, folders):
    """The longest folder of the map that holds `path`, or None."""
    best = None
    for f in folders:
        if path.startswith(f + "/") and (best is None or len(f) > len(best)):
            best = f
    return best


def check(files, read, design_text):
    """Problems, as lines. `files`: tracked paths; `read(path)`: a file's text."""
    rows = read_map(design_text)
    problems = []
    if not rows:
        return ["docs/design.md has no folder map table under '## Folder map'"]
    tracked_dirs = {p.split("/")[0] for p in files if "/" in p and not p.startswith(".")}
    for top in sorted(tracked_dirs):
        if not any(f == top or f.startswith(top + "/") for f in rows):
            problems.append(f"{top}/ holds tracked files but the folder map has no row for it")
    for f in sorted(rows):
        if not any(p.startswith(f + "/") for p in files):
            problems.append(f"the folder map lists {f}/, which holds no tracked file")
    known = set(files)
    for path in files:
        if not path.endswith(SOURCES) or long_functions.is_test_file(path):
            continue
        source = owner(path, rows)
        if source is None or rows[source] is None:
            continue
        for target in INCLUDE.findall(read(path)):
            if target not in known:
                continue  # a system or generated header (the parser: grammar's, at build time)
            dest = owner(target, rows)
            if dest is None or dest == source:
                continue
            allowed = rows[source]
            if not any(dest == a or dest.startswith(a + "/") for a in allowed):
                problems.append(f"{path} includes {target}: {source}/ may depend on "
                                f"{', '.join(sorted(a + '/' for a in allowed)) or 'no folder of ours'}"
                                f" (docs/design.md#folder-map), not {dest}/")
    return problems


def main_check(root):
    proc = subprocess.run(["git", "-C", root, "ls-files"], capture_output=True, text=True)
    if proc.returncode != 0:
        print(f"not a git checkout ({proc.stderr.strip()}): nothing to compare")
        return 77
    files = proc.stdout.split()

    def read(path):
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            return f.read()

    problems = check(files, read, read("docs/design.md"))
    for p in problems:
        print(p)
    print(f"{len(files)} files, {len(problems)} problems with the folder map")
    return 1 if problems else 0


def self_test():
    design = ("# Design\n\n## Folder map\n\n| folder | what | depends on |\n|---|---|---|\n"
              "| `core/` | the model | nothing of ours |\n"
              "| `compiler/frontend/` | parsing | `core/` |\n"
              "| `verify/` | the proof | `core/` |\n"
              "| `cli/` | the command | anything |\n"
              "| `gone/` | removed | `core/` |\n\n## Reporting errors\n")
    texts = {
        "core/a.h": "",
        "compiler/frontend/p.cc": '#include "core/a.h"\n#include <vector>\n',
        "verify/v.cc": '#include "compiler/frontend/p.h"\n',  # not allowed
        "verify/v_test.cc": '#include "cli/c.h"\n',             # test code: not checked
        "compiler/frontend/p.h": "",
        "cli/c.h": '#include "verify/v.h"\n',
        "lsp/s.cc": '#include "core/a.h"\n',                     # no row for lsp/
    }
    problems = check(sorted(texts), lambda p: texts[p], design)
    expected = ["lsp/ holds tracked files", "lists gone/",
                "verify/v.cc includes compiler/frontend/p.h"]
    bad = [e for e in expected if not any(e in p for p in problems)]
    bad += [p for p in problems if not any(e in p for e in expected)]
    for b in bad:
        print("FAIL", b)
    print(f"self-test: {len(problems)} problems found, {len(bad)} wrong")
    return 1 if bad else 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main_check(sys.argv[1]))
