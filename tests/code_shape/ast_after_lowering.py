#!/usr/bin/env python3
"""Nothing after lowering sees the AST (docs/design.md#pipeline): no source under the folders
that read the core model includes a header of compiler/frontend/ other than the front end's
entry points, and the lowered app that code generation reads does not include the AST.

usage: ast_after_lowering.py ROOT
"""
import os
import re
import sys

root = sys.argv[1]
# Folders downstream of lowering, and the front-end headers each may include: frontend.h (read,
# parse, check: the commands that start from a spec) and lua_syntax.h (a Lua syntax check that
# code generation shares with the checker of `script` files).
DOWNSTREAM = ["compiler/codegen", "compiler/docs", "verify", "runtime", "cli", "import", "dds"]
ALLOWED = {"compiler/frontend/frontend.h", "compiler/frontend/lua_syntax.h"}
# Headers of compiler/lower/ that code generation and the commands include.
LOWERED = ["compiler/lower/lowered_app.h", "compiler/lower/compile_spec.h"]

include = re.compile(r'#include\s+"(compiler/frontend/[^"]+)"')
bad = []


def check(path, allowed):
    with open(os.path.join(root, path), encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            m = include.search(line)
            if m and m.group(1) not in allowed:
                bad.append(f"{path}:{n}: includes {m.group(1)}")


checked = 0
for folder in DOWNSTREAM:
    for dirpath, _, files in os.walk(os.path.join(root, folder)):
        for name in files:
            if name.endswith((".cc", ".h")):
                check(os.path.relpath(os.path.join(dirpath, name), root), ALLOWED)
                checked += 1
for path in LOWERED:
    check(path, set())
    checked += 1
for b in bad:
    print(b)
print(f"{checked} files, {len(bad)} that see the AST after lowering")
sys.exit(1 if bad or checked < 100 else 0)
