#!/usr/bin/env python3
"""Runs `arbc docs SPEC -o OUT` and checks what it wrote.

usage: check_docs.py ARBC SPEC GOLDEN_DIR OUT_DIR [TEXT...]
  - index.md contains each TEXT (what the golden is there to show, said by the test);
  - index.md, app.dot and app.mmd equal the goldens in GOLDEN_DIR
    (ARBC_UPDATE_GOLDEN=1 rewrites them instead);
  - `dot -Tsvg` accepts app.dot, and app.svg is an SVG naming every module;
  - every Markdown table row has as many cells as its header;
  - no file names a path of the machine that built it (the checkout, the build tree, OUT_DIR):
    the pages are published, and a spec given by a relative path is named by it.
"""
import os
import re
import shutil
import subprocess
import sys

arbc, spec, golden, out = sys.argv[1:5]
wanted = sys.argv[5:]
shutil.rmtree(out, ignore_errors=True)
run = subprocess.run([arbc, "docs", spec, "-o", out], capture_output=True, text=True)
failures = []
if run.returncode != 0:
    sys.exit(f"arbc docs exited {run.returncode}: {run.stderr}")

for name in ("index.md", "app.dot", "app.mmd"):
    with open(os.path.join(out, name)) as f:
        text = f.read()
    path = os.path.join(golden, name)
    if os.environ.get("ARBC_UPDATE_GOLDEN"):
        os.makedirs(golden, exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
        continue
    with open(path) as f:
        if f.read() != text:
            failures.append(f"{name} differs from {path}; diff it, then ARBC_UPDATE_GOLDEN=1 if intended")

with open(os.path.join(out, "index.md")) as f:
    index = f.read()
failures += [f"index.md does not say {text!r}" for text in wanted if text not in index]

machine = {os.getcwd(), os.path.dirname(os.path.dirname(os.path.abspath(arbc))),
           os.path.abspath(out)}
for name in sorted(os.listdir(out)):
    with open(os.path.join(out, name), errors="replace") as f:
        text = f.read()
    for path in sorted(machine):
        if path in text:
            failures.append(f"{name} names {path}, a path of the machine that built it")

dot = subprocess.run(["dot", "-Tsvg", os.path.join(out, "app.dot")], capture_output=True, text=True)
if dot.returncode != 0:
    failures.append(f"dot -Tsvg rejects app.dot: {dot.stderr}")
with open(os.path.join(out, "app.svg")) as f:
    svg = f.read()
modules = re.findall(r"^module (\w+)", open(spec).read(), re.M)
if "<svg" not in svg or not modules or any(m not in svg for m in modules):
    failures.append("app.svg is not an SVG naming every module")


def cells(row):
    return len(re.findall(r"(?<!\\)\|", row))


with open(os.path.join(out, "index.md")) as f:
    header = None
    for number, line in enumerate(f, 1):
        if not line.startswith("|"):
            header = None
            continue
        if header is None:
            header = cells(line)
        elif cells(line) != header:
            failures.append(f"index.md:{number}: {cells(line)} cells, header has {header}")

for failure in failures:
    print(failure)
print(f"{1 if not failures else 0} passed, {1 if failures else 0} failed")
sys.exit(1 if failures else 0)
