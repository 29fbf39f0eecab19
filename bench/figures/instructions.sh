#!/usr/bin/env bash
# Instructions per message of the per-message paths (issue 21): monitored_delivery,
# bare_delivery, monitored_delivery_checked (the runtime checks on: issue 39 bounds their cost
# at 10%) and the Lua floors of bench/runtime/runtime_bench.cc, each counted by
# callgrind over a window of 10,000 messages after 2,000 of warm-up (InstructionWindow there).
# A count does not move with what else the shared machine runs, so two builds compare exactly
# where their times only compare by interleaved medians. Needs valgrind (installed by bench/run).
set -euo pipefail
build=${ARBC_BENCH_BUILD:-${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}/build-bench}
bench=$build/bench/runtime/runtime_bench
if [ ! -x "$bench" ]; then
  echo "instructions.sh: $bench is missing; build the Release tree first (bench/run does)" >&2
  exit 2
fi
if ! command -v valgrind >/dev/null; then
  echo "instructions.sh: valgrind is missing (apt-get install valgrind)" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
count() {  # count BENCHMARK: instructions per message of its window
  local out=$work/$1
  # Long enough a run that one of the benchmark's runs reaches the end of the window.
  valgrind --tool=callgrind --collect-atstart=yes --callgrind-out-file="$out" \
    "$bench" --benchmark_filter="^$1\$" --benchmark_min_time=3 >/dev/null 2>&1
  python3 - "$out.1" <<'PY'
import sys
try:
    lines = open(sys.argv[1]).read().splitlines()
except OSError:
    sys.exit("instructions.sh: no window was dumped (the benchmark ran fewer than 12,000 messages)")
totals = [l for l in lines if l.startswith("totals:") or l.startswith("summary:")]
print(int(totals[0].split()[1]) / 10000)
PY
}
monitored=$(count BM_MonitoredDelivery)
bare=$(count BM_BareDelivery)
tables=$(count BM_LuaFloorTables)
reused=$(count BM_LuaFloorReused)
checked=$(count BM_MonitoredDeliveryChecked)
python3 - "$monitored" "$bare" "$tables" "$reused" "$checked" <<'PY'
import json, sys
monitored, bare, tables, reused, checked = map(float, sys.argv[1:])
def line(**kv): print(json.dumps(kv))
line(name="monitored_delivery_instructions", value=round(monitored), unit="instructions",
     baseline=round(tables), ratio=round(monitored / tables, 2))
line(name="bare_delivery_instructions", value=round(bare), unit="instructions")
line(name="runtime_checks_per_message", value=round(checked), unit="instructions",
     baseline=round(monitored), ratio=round(checked / monitored, 3))
line(name="lua_floor_reused_instructions", value=round(reused), unit="instructions",
     baseline=round(tables), ratio=round(reused / tables, 2))
PY
