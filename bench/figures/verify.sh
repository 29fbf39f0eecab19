#!/usr/bin/env bash
# `arbc verify` benchmarks (issue 3). Whole-process wall times, medians; beside each, in the same
# run, the naive approach (one solver query per pair of rules: bench/verify/verify_naive) as
# "baseline", with "ratio" = baseline / value. Prints one JSON object per line.
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
build=${ARBC_BENCH_BUILD:-$root/build-bench}
arbc=${ARBC:-$build/cli/arbc}
naive=$build/bench/verify/verify_naive
median="python3 $root/bench/median.py"
gen="python3 $root/bench/verify/gen_verify_app.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$root"

# expect_exit CODE CMD...: the benchmark is meaningless if the verdict is wrong.
expect_exit() {
  local want=$1
  shift
  local rc=0
  "$@" > /dev/null 2>&1 || rc=$?
  if [ "$rc" != "$want" ]; then
    echo "verify.sh: '$*' exited $rc, expected $want" >&2
    exit 1
  fi
}

# figure NAME RUNS BASELINE_RUNS APP [limit]: median of arbc and of the naive baseline.
figure() {
  local name=$1 runs=$2 baseline_runs=$3 app=$4
  local value baseline
  value=$($median "$runs" "$arbc" verify "$app")
  if [ "$baseline_runs" -gt 0 ]; then
    baseline=$($median "$baseline_runs" "$naive" "$app")
    python3 -c "import json,sys; v,b=float(sys.argv[2]),float(sys.argv[3]); print(json.dumps({'name': sys.argv[1], 'value': round(v,4), 'unit': 's', 'baseline': round(b,4), 'ratio': round(b/v,2)}))" "$name" "$value" "$baseline"
  else
    python3 -c "import json,sys; print(json.dumps({'name': sys.argv[1], 'value': round(float(sys.argv[2]),4), 'unit': 's'}))" "$name" "$value"
  fi
}

table_clean=tests/verify/table_clean.app.json
expect_exit 0 "$arbc" verify "$table_clean"
figure verify_table_clean_process 21 21 "$table_clean"

$gen 1 1000 200 0 "$work/exclusive_1000.json"
expect_exit 0 "$arbc" verify "$work/exclusive_1000.json"
figure verify_one_port_1000_rules_200_events 5 1 "$work/exclusive_1000.json"

# The same port with two-cube (DNF) guards: the cube shortcut cannot settle it, Z3 proves it.
$gen 1 1000 200 0 "$work/exclusive_1000_dnf.json" dnf
expect_exit 0 "$arbc" verify "$work/exclusive_1000_dnf.json"
figure verify_one_port_1000_dnf_rules_200_events 5 1 "$work/exclusive_1000_dnf.json"
$gen 100 100 30 0 "$work/ports_100x100.json"
expect_exit 0 "$arbc" verify "$work/ports_100x100.json"
figure verify_100_ports_100_rules 3 1 "$work/ports_100x100.json"

$gen 1 1000 200 50 "$work/refuted_1000.json"
expect_exit 1 "$arbc" verify "$work/refuted_1000.json"
figure verify_refuted_port_1000_rules_capped_report 5 1 "$work/refuted_1000.json"

# Scaling: one exclusive port, rules over 200 events (naive only where it takes seconds).
for rules in 100 250 500 2000; do
  $gen 1 "$rules" 200 0 "$work/scale_$rules.json"
  expect_exit 0 "$arbc" verify "$work/scale_$rules.json"
  if [ "$rules" -le 500 ]; then b=1; else b=0; fi
  figure "verify_scaling_one_port_${rules}_rules" 3 "$b" "$work/scale_$rules.json"
done
