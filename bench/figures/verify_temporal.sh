#!/usr/bin/env bash
# Properties over time (issue 19). Whole-process wall times, medians; beside each, in the same
# run, the same input without what is measured as "baseline":
#   verify_temporal_table_clean: tests/verify/table_clean_temporal.spec (table_clean with its
#     properties over time: ask's spacing explored to the default bound, take's refuted and the
#     trace replayed on the runtime) against the same spec without the `never` declarations.
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
build=${ARBC_BENCH_BUILD:-$root/build-bench}
arbc=${ARBC:-$build/cli/arbc}
median="python3 $root/bench/median.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$root"

expect_exit() {
  local want=$1
  shift
  local rc=0
  "$@" > /dev/null 2>&1 || rc=$?
  if [ "$rc" != "$want" ]; then
    echo "verify_temporal.sh: '$*' exited $rc, expected $want" >&2
    exit 1
  fi
}

spec=tests/verify/table_clean_temporal.spec
grep -v '^never ' "$spec" > "$work/table_clean.spec"
expect_exit 1 "$arbc" verify "$spec"  # take's spacing is violated (replayed)
expect_exit 0 "$arbc" verify "$work/table_clean.spec"
value=$($median 11 "$arbc" verify "$spec")
baseline=$($median 11 "$arbc" verify "$work/table_clean.spec")
python3 -c "import json,sys; v,b=float(sys.argv[1]),float(sys.argv[2]); print(json.dumps({'name': 'verify_temporal_table_clean', 'value': round(v,4), 'unit': 's', 'target': 2.0, 'baseline': round(b,4), 'ratio': round(b/v,2)}))" "$value" "$baseline"
