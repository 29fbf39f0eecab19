#!/usr/bin/env bash
# Proofs over message data (issue 18). Whole-process wall times, medians; beside each, in the
# same run, the same input without what is measured as "baseline":
#   verify_table_clean_data: specs/table_clean.spec (its arm resource, data refinement) against
#     the same spec without the `resource` declaration (the event proof alone);
#   verify_resource_100_rules: a resource over 4 ports with 100 data-guarded rules of one
#     source against the same spec without the resource (the per-port proofs alone).
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
build=${ARBC_BENCH_BUILD:-$root/build-bench}
arbc=${ARBC:-$build/cli/arbc}
median="python3 $root/bench/median.py"
gen="python3 $root/bench/verify/gen_resource_spec.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$root"

expect_exit() {
  local want=$1
  shift
  local rc=0
  "$@" > /dev/null 2>&1 || rc=$?
  if [ "$rc" != "$want" ]; then
    echo "verify_data.sh: '$*' exited $rc, expected $want" >&2
    exit 1
  fi
}

# figure NAME RUNS SPEC BASELINE_SPEC
figure() {
  local value baseline
  value=$($median "$2" "$arbc" verify "$3")
  baseline=$($median "$2" "$arbc" verify "$4")
  python3 -c "import json,sys; v,b=float(sys.argv[2]),float(sys.argv[3]); print(json.dumps({'name': sys.argv[1], 'value': round(v,4), 'unit': 's', 'baseline': round(b,4), 'ratio': round(b/v,2)}))" "$1" "$value" "$baseline"
}

grep -v '^resource arm' specs/table_clean.spec > "$work/table_clean.spec"
expect_exit 0 "$arbc" verify specs/table_clean.spec
expect_exit 0 "$arbc" verify "$work/table_clean.spec"
figure verify_table_clean_data 21 specs/table_clean.spec "$work/table_clean.spec"

$gen 100 4 "$work/resource_100.spec"
$gen 100 4 "$work/resource_100_baseline.spec" --no-resource
expect_exit 0 "$arbc" verify "$work/resource_100.spec"
expect_exit 0 "$arbc" verify "$work/resource_100_baseline.spec"
figure verify_resource_100_rules 5 "$work/resource_100.spec" "$work/resource_100_baseline.spec"
