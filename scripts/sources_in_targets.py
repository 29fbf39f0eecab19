#!/usr/bin/env python3
"""Every tracked C++ source is compiled by some CMake target (ctest sources_in_targets).

usage: sources_in_targets.py SOURCE_DIR BUILD_DIR

A .cc file in no target is not noticed by the build: a MODULE plugin that misses one of its
files links anyway (a shared object may leave symbols undefined) and fails only when `arbc run`
loads it. This compares `git ls-files '*.cc' '*.cpp'` with what the build compiles, read from
BUILD_DIR/compile_commands.json (CMAKE_EXPORT_COMPILE_COMMANDS; every object file of every
target is there, MODULE plugins and OBJECT libraries included).

Some files are built only in some configurations (YARP's tests and benchmark without YARP, the
DDS interop programs without fastddsgen) or by another CMake project that a test builds
(tests/install/*). Such a file passes when a tracked CMakeLists.txt names it as a source, outside
comments (by its path from that file's folder or from ${PROJECT_SOURCE_DIR}, or made by a
`foreach` as `interop/${program}.cc` is), and is listed as "not built here". A file that no
CMakeLists.txt names fails. Exit 0 all fine,
1 a file in no target, 77 (skipped) outside a git checkout.
"""
import json
import os
import re
import subprocess
import sys


def tracked_sources(source_dir):
    proc = subprocess.run(["git", "-C", source_dir, "ls-files", "*.cc", "*.cpp"],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        print(f"not a git checkout ({proc.stderr.strip()}): nothing to compare")
        sys.exit(77)
    return proc.stdout.split()


def tracked_lists(source_dir):
    proc = subprocess.run(["git", "-C", source_dir, "ls-files", "CMakeLists.txt",
                           "*/CMakeLists.txt"], capture_output=True, text=True, check=True)
    return proc.stdout.split()


def compiled_sources(build_dir):
    path = os.path.join(build_dir, "compile_commands.json")
    try:
        with open(path, encoding="utf-8") as f:
            entries = json.load(f)
    except OSError as e:
        sys.exit(f"{path}: {e.strerror}: configure with CMAKE_EXPORT_COMPILE_COMMANDS=ON "
                 "(the top-level CMakeLists.txt sets it) and a Makefile or Ninja generator")
    return {os.path.realpath(os.path.join(e["directory"], e["file"])) for e in entries}


SOURCE = re.compile(r"[\w${}/.+-]+\.(?:cc|cpp)\b")
FOREACH = re.compile(r"foreach\s*\(\s*(\w+)\s+([^)]*)\)", re.I)
ROOTS = ("${PROJECT_SOURCE_DIR}/", "${CMAKE_SOURCE_DIR}/")


def named_sources(source_dir, lists):
    """The sources a CMakeLists.txt (relative path) names, as paths from the repository root:
    written out (`rake.cc`, `modules/speak.cc`, `${PROJECT_SOURCE_DIR}/tests/x.cc`) or made
    by a foreach (`foreach(program interop_pub interop_sub)` ... `interop/${program}.cc`)."""
    with open(os.path.join(source_dir, lists), encoding="utf-8") as f:
        text = re.sub(r"#.*", "", f.read())
    tokens = SOURCE.findall(text)
    for var, items in FOREACH.findall(text):
        for token in [t for t in tokens if "${" + var + "}" in t]:
            tokens += [token.replace("${" + var + "}", item) for item in items.split()]
    folder = os.path.dirname(lists)
    named = set()
    for token in tokens:
        token = token.replace("${CMAKE_CURRENT_SOURCE_DIR}/", "")
        root = next((r for r in ROOTS if token.startswith(r)), None)
        path = token[len(root):] if root else os.path.join(folder, token)
        if "${" not in path:
            named.add(os.path.normpath(path))
    return named


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    source_dir, build_dir = sys.argv[1], sys.argv[2]
    compiled = compiled_sources(build_dir)
    tracked = tracked_sources(source_dir)
    named = {}  # source -> the CMakeLists.txt that names it
    for lists in [t for t in tracked_lists(source_dir) if t.endswith("CMakeLists.txt")]:
        for path in named_sources(source_dir, lists):
            named.setdefault(path, lists)
    missing, elsewhere = [], []
    for relative in tracked:
        if os.path.realpath(os.path.join(source_dir, relative)) in compiled:
            continue
        lists = named.get(os.path.normpath(relative))
        (elsewhere if lists else missing).append((relative, lists))
    for relative, lists in elsewhere:
        print(f"not built here: {relative} (named in {lists}, under a condition this "
              "configuration does not meet, or by another project)")
    for relative, _ in missing:
        print(f"{relative}: error: this file is in no CMake target, so nothing compiles it: add "
              "it to its target's sources in the CMakeLists.txt of its folder (a MODULE plugin "
              "without it still links, and fails only when it is loaded)")
    if missing:
        return 1
    print(f"ok: every tracked C++ source is in a target ({len(elsewhere)} not built here)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
