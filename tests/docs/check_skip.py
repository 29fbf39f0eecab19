#!/usr/bin/env python3
"""`arbc docs` on an application too large to draw writes index.md only and says so.

usage: check_skip.py ARBC GEN_SPEC OUT_DIR

Generates a spec of 1,200 modules, 600 arbitrated ports and 600 rules (2,400 diagram elements,
over the limit of compiler/docs/graph_docs.h) with bench/gen_spec.py, puts stale drawings in
OUT_DIR, runs `arbc docs`, and checks: exit 0; stdout names the sizes and the skip; index.md
carries the same note where the diagram would be, and its tables still list every module;
app.dot, app.svg and app.mmd are gone (a stale drawing would contradict index.md).
"""
import os
import shutil
import subprocess
import sys

arbc, gen_spec, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
spec = os.path.join(out, "large.spec")
with open(spec, "w") as f:
    subprocess.run([sys.executable, gen_spec, "--rules", "600", "--ports", "600", "--sources", "600",
                    "--name", "large"], stdout=f, check=True)
docs = os.path.join(out, "docs")
os.makedirs(docs)
for stale in ("app.dot", "app.svg", "app.mmd"):
    with open(os.path.join(docs, stale), "w") as f:
        f.write("from an earlier run\n")

run = subprocess.run([arbc, "docs", spec, "-o", docs], capture_output=True, text=True, timeout=600)
failures = []
note = ("The diagram is skipped for size: 1200 modules, 600 arbitrated ports and 600 connections "
        "(2400 elements, more than 2000).")
if run.returncode != 0:
    failures.append(f"exit {run.returncode}: {run.stderr}")
if note not in run.stdout:
    failures.append(f"stdout does not say the diagram is skipped: {run.stdout!r}")
index = open(os.path.join(docs, "index.md")).read()
if note not in index or "![" in index:
    failures.append("index.md does not carry the note instead of the diagram")
if "| Source599 |" not in index or "| Actuator599 |" not in index:
    failures.append("index.md lacks modules")
left = [n for n in ("app.dot", "app.svg", "app.mmd") if os.path.exists(os.path.join(docs, n))]
if left:
    failures.append(f"stale drawings left: {left}")
for failure in failures:
    print("FAIL", failure)
sys.exit(1 if failures else 0)
