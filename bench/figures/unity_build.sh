#!/usr/bin/env bash
# Figure for CI's run time (.ci/run must end well under 90 minutes with nothing in ccache, and
# most of it is compiling): one slice of the tree, the runtime library and its tests
# (runtime_test, with arbc_core and the Lua glue it needs), built from nothing twice in this run:
# as every build now does it (ARBC_UNITY=ON, each target's sources compiled in batches of 16)
# and file by file (ARBC_UNITY=OFF, the baseline), the same flags (-O2 -g1), ccache bypassed.
# The value is the unity build's seconds; the ratio is unity over file by file.
# Env (set by bench/run): ARBC_ROOT.
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
seconds() {  # seconds UNITY: configure a fresh tree and build runtime_test in it
  local dir=$scratch/unity-$1
  CCACHE_DISABLE=1 cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARBC_UNITY="$1" \
    -DARBC_BENCH=OFF >/dev/null
  local start=$EPOCHREALTIME
  CCACHE_DISABLE=1 cmake --build "$dir" -j"$(nproc)" --target runtime_test >/dev/null
  python3 -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$start" "$EPOCHREALTIME"
}
base=$(seconds OFF)
ours=$(seconds ON)
python3 -c "import json,sys; b,o=float(sys.argv[1]),float(sys.argv[2]); print(json.dumps({'name': 'unity_build_runtime_test', 'value': round(o,1), 'unit': 's', 'baseline': round(b,1), 'ratio': round(o/b,3)}))" "$base" "$ours"
