#!/usr/bin/env bash
# Figure for CI's run time (.ci/run must end well under 90 minutes with nothing in ccache, and
# most of it is compiling): the cost of compiling a fixed sample of our sources for the
# sanitizer build as scripts/sanitize.sh does it (-O1 -g1, ASan + UBSan) against the baseline of
# -O2 -g with the same sanitizers (what it did until 2026-11-30), GCC both. Each file compiled
# once per flavour, ccache bypassed; the value is the sum of the sample's seconds and the ratio is
# sanitize.sh's over the baseline, both from this run.
# Env (set by bench/run): ARBC_ROOT, ARBC_BENCH_BUILD (its compile_commands.json).
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
build=${ARBC_BENCH_BUILD:-$root/build}
python3 - "$root" "$build/compile_commands.json" <<'EOF'
import json, os, shlex, subprocess, sys, tempfile, time

root, commands = sys.argv[1], sys.argv[2]
# Production files of the heavy folders (Z3, Lua, nlohmann-json, Fast-DDS headers).
SAMPLE = ["verify/report_json.cc", "verify/resource_checks.cc", "runtime/runtime.cc",
          "dds/topic_type.cc", "harness/test_expect.cc", "compiler/frontend/stray_field.cc"]
SANITIZERS = ["-fsanitize=address,undefined", "-fno-omit-frame-pointer",
              "-fno-sanitize-recover=undefined"]
by_file = {os.path.relpath(e["file"], root): e for e in json.load(open(commands))}
out = tempfile.NamedTemporaryFile(suffix=".o", delete=False).name


def seconds(compiler, entry, flags):
    args = shlex.split(entry["command"])
    if os.path.basename(args[0]) == "ccache":
        args = args[1:]
    keep, skip = [], False
    for a in args[1:]:
        if skip:
            skip = False
        elif a == "-o":
            skip = True
        elif not (a.startswith("-O") or a.startswith("-g") or a == "-DNDEBUG"):
            keep.append(a)
    start = time.monotonic()
    subprocess.run([compiler] + keep + flags + SANITIZERS + ["-o", out], cwd=entry["directory"],
                   check=True, capture_output=True)
    return time.monotonic() - start


base = ours = 0.0
for name in SAMPLE:
    entry = by_file.get(name)
    if entry is None:
        sys.exit(f"ci_compile.sh: {name} is not in {commands}")
    base += seconds("g++", entry, ["-O2", "-g", "-DNDEBUG"])
    ours += seconds("g++", entry, ["-O1", "-g1", "-DNDEBUG"])
os.unlink(out)
print(json.dumps({"name": "ci_sanitizer_compile_sample", "value": round(ours, 1), "unit": "s",
                  "baseline": round(base, 1), "ratio": round(ours / base, 3)}))
EOF
