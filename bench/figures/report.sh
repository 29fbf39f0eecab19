#!/usr/bin/env bash
# Run report (issue 7): `arbc run --report` on the table_clean `mixed` run (seed 1; it stops
# when the table is clean, at 44.9 s simulated).
#   run_report_mixed_wall   median wall time of the run with --report (baseline: the same run
#                           without it, so the ratio is what the report costs)
#   run_report_mixed_size   the report's size (budget: < 2 MiB)
set -euo pipefail
: "${ARBC:?set by bench/run}" "${ARBC_ROOT:?}" "${ARBC_BENCH_BUILD:?}"
plugin=$ARBC_BENCH_BUILD/examples/table_clean/libarbc_table_clean.so
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$ARBC" build "$ARBC_ROOT/specs/table_clean.spec" -o "$work" >/dev/null
run=("$ARBC" run "$work/table_clean" --plugin "$plugin" --scenario mixed --seed 1 --duration 120s)

"${run[@]}" --report "$work/report.html" >/dev/null 2>&1 ||
  { echo "report.sh: the mixed run with --report failed" >&2; exit 1; }
size=$(stat -c %s "$work/report.html")
with=$(python3 "$ARBC_ROOT/bench/median.py" 21 "${run[@]}" --report "$work/report.html")
without=$(python3 "$ARBC_ROOT/bench/median.py" 21 "${run[@]}")

python3 - "$with" "$without" "$size" <<'PY'
import json, sys
with_report, without, size = map(float, sys.argv[1:])
print(json.dumps({"name": "run_report_mixed_wall", "value": with_report, "unit": "s",
                  "baseline": without, "ratio": round(with_report / without, 2)}))
print(json.dumps({"name": "run_report_mixed_size", "value": round(size / 1024, 1),
                  "unit": "KiB"}))
PY
