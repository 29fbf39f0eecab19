#!/usr/bin/env bash
# Runtime figures (issue 5): constraint_decision (baseline: the YARP way), monitored_delivery
# (baseline: lua_floor_tables, the Lua work alone), bare_delivery, monitor_memory,
# lua_floor_reused (the Lua work with the message's tables reused: the lower bound of the table
# form) and lua_floor_userdata (the Lua work were a message a userdata; issue 21). Medians over
# repetitions of Google Benchmark runs; times are CPU time per operation, which the other jobs
# on the shared 2-core machine disturb far less than wall time (wall-time medians are printed
# beside them as "wall"). bench/figures/instructions.sh counts the same paths' instructions.
set -euo pipefail
build=${ARBC_BENCH_BUILD:-${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}/build-bench}
bench=$build/bench/runtime/runtime_bench
if [ ! -x "$bench" ]; then
  echo "runtime.sh: $bench is missing; build the Release tree first (bench/run does)" >&2
  exit 2
fi
out=$(mktemp)
trap 'rm -f "$out"' EXIT
"$bench" --benchmark_repetitions=${ARBC_BENCH_REPETITIONS:-9} --benchmark_report_aggregates_only=true \
  --benchmark_format=json --benchmark_out="$out" --benchmark_out_format=json >/dev/null 2>&1
python3 - "$out" <<'PY'
import json, sys
runs = json.load(open(sys.argv[1]))["benchmarks"]
median = {b["run_name"]: b for b in runs if b.get("aggregate_name") == "median"}
def cpu(name): return median[name]["cpu_time"]
def wall(name): return median[name]["real_time"]
def line(**kv): print(json.dumps(kv))
decision, yarp = cpu("BM_ConstraintDecision"), cpu("BM_YarpDecision")
line(name="constraint_decision", value=round(decision, 2), unit="ns", baseline=round(yarp, 1),
     ratio=round(yarp / decision, 1), wall=round(wall("BM_ConstraintDecision"), 2))
monitored, floor = cpu("BM_MonitoredDelivery"), cpu("BM_LuaFloorTables")
line(name="monitored_delivery", value=round(monitored, 1), unit="ns", baseline=round(floor, 1),
     ratio=round(monitored / floor, 2), wall=round(wall("BM_MonitoredDelivery"), 1))
line(name="lua_floor_reused", value=round(cpu("BM_LuaFloorReused"), 1), unit="ns",
     baseline=round(floor, 1), ratio=round(cpu("BM_LuaFloorReused") / floor, 2))
line(name="lua_floor_userdata", value=round(cpu("BM_LuaFloorUserdata"), 1), unit="ns",
     baseline=round(floor, 1), ratio=round(cpu("BM_LuaFloorUserdata") / floor, 2))
line(name="bare_delivery", value=round(cpu("BM_BareDelivery"), 1), unit="ns",
     wall=round(wall("BM_BareDelivery"), 1))
memory = median["BM_MonitorMemory/iterations:1000"]["bytes"]
line(name="monitor_memory", value=int(memory), unit="bytes")
PY
