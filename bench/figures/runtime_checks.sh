#!/usr/bin/env bash
# The cost of the runtime checks (issue 39: at most 10%): instructions of `arbc run` on the
# simulated table_clean world (scenario mixed, seed 1, 60 s simulated, --no-verify so that only
# the run is counted), with --runtime-checks warn against the same run with them off, each
# counted by callgrind over the whole process. A count does not move with what else the shared
# machine runs. Needs valgrind (installed by bench/run).
#   runtime_checks_cost   instructions with the checks / without (baseline: off, ratio)
set -euo pipefail
: "${ARBC:?set by bench/run}" "${ARBC_ROOT:?}" "${ARBC_BENCH_BUILD:?}"
if ! command -v valgrind >/dev/null; then
  echo "runtime_checks.sh: valgrind is missing (apt-get install valgrind)" >&2
  exit 2
fi
plugin=$ARBC_BENCH_BUILD/examples/table_clean/libarbc_table_clean.so
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$ARBC" build "$ARBC_ROOT/specs/table_clean.spec" -o "$work" >/dev/null
count() {  # count MODE: instructions of the whole run
  local out=$work/callgrind.$1
  valgrind --tool=callgrind --callgrind-out-file="$out" "$ARBC" run "$work/table_clean" \
    --plugin "$plugin" --scenario mixed --seed 1 --duration 60s --no-verify \
    --runtime-checks "$1" >"$work/run.$1.txt" 2>&1 || true
  grep -q '^result:' "$work/run.$1.txt" || {
    echo "runtime_checks.sh: the run with --runtime-checks $1 printed no result:" >&2
    cat "$work/run.$1.txt" >&2
    exit 1
  }
  awk '/^(summary|totals):/ {print $2; exit}' "$out"
}
off=$(count off)
on=$(count warn)
python3 - "$on" "$off" <<'PY'
import json, sys
on, off = map(int, sys.argv[1:])
print(json.dumps({"name": "runtime_checks_cost", "value": on, "unit": "instructions",
                  "baseline": off, "ratio": round(on / off, 3)}))
PY
