#!/usr/bin/env bash
# Simulation (issue 6): specs/table_clean.spec built by `arbc build` and run by `arbc run` on
# the simulated world, scenario `mixed` (10 objects, all zones), seed 1.
#   simulation_mixed_speedup          simulated time / median wall time of the whole process
#                                     (baseline: real time, ratio 1)
#   simulation_mixed_speedup_run_only the same without process start-up (median wall time of
#                                     `arbc --version` subtracted: loading libraries, not running)
#   simulation_mixed_peak_rss         peak resident memory of the run (/usr/bin/time -v)
set -euo pipefail
: "${ARBC:?set by bench/run}" "${ARBC_ROOT:?}" "${ARBC_BENCH_BUILD:?}"
plugin=$ARBC_BENCH_BUILD/examples/table_clean/libarbc_table_clean.so
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$ARBC" build "$ARBC_ROOT/specs/table_clean.spec" -o "$work" >/dev/null
run=("$ARBC" run "$work/table_clean" --plugin "$plugin" --scenario mixed --seed 1 --duration 120s)

sim=$("${run[@]}" 2>/dev/null | awk '/^simulated time:/ {print $3}')
[ -n "$sim" ] || { echo "simulation.sh: the mixed run printed no simulated time" >&2; exit 1; }
wall=$(python3 "$ARBC_ROOT/bench/median.py" 31 "${run[@]}")
startup=$(python3 "$ARBC_ROOT/bench/median.py" 31 "$ARBC" --version)
/usr/bin/time -v -o "$work/time.txt" "${run[@]}" >/dev/null 2>&1
rss=$(awk -F: '/Maximum resident set size/ {gsub(/ /, "", $2); print $2}' "$work/time.txt")

python3 - "$sim" "$wall" "$startup" "$rss" <<'PY'
import json, sys
sim, wall, startup, rss = map(float, sys.argv[1:])
run_only = max(wall - startup, 1e-6)
print(json.dumps({"name": "simulation_mixed_speedup", "value": round(sim / wall, 1),
                  "unit": "x real time", "baseline": 1, "ratio": round(sim / wall, 1),
                  "simulated_s": sim, "wall_s": wall}))
print(json.dumps({"name": "simulation_mixed_speedup_run_only", "value": round(sim / run_only, 1),
                  "unit": "x real time", "baseline": 1, "ratio": round(sim / run_only, 1),
                  "startup_s": startup}))
print(json.dumps({"name": "simulation_mixed_peak_rss", "value": round(rss / 1024, 1),
                  "unit": "MiB"}))
PY
