#!/usr/bin/env bash
# Instructions per message of the per-message paths (issue 21): monitored_delivery,
# bare_delivery, monitored_delivery_checked (the runtime checks on: issue 39 bounds their cost
# at 10%) and the Lua floors of bench/runtime/runtime_bench.cc, each counted by
# callgrind over a window of 10,000 messages after 2,000 of warm-up (bench/callgrind_window.sh).
# Needs valgrind (installed by bench/run).
set -euo pipefail
source "$(dirname "$0")/../callgrind_window.sh"
callgrind_bench instructions.sh bench/runtime/runtime_bench
count() { callgrind_window "$bench" "$1" "$work"; }
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
