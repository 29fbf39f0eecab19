#!/usr/bin/env bash
# Properties over time (issue 19). Whole-process wall times, medians; beside each, in the same
# run, the same input without what is measured as "baseline":
#   verify_temporal_table_clean: specs/table_clean.spec (table_clean with its
#     seven properties over time: ask's spacing explored to the default bound, take's and
#     search-after-track's proved by k-induction, take's under the arm's assumed cycle, two
#     absences, put's precedence proved by k-induction under its environment assumption,
#     search's response given LookAround's rate explored to the default bound) against the same
#     spec without its properties over time, assumptions and rates.
#   verify_temporal_bound_20_rules_10s: the number of messages into a 20-rule port by priority
#     (bench/verify/gen_temporal_port.py) up to which `never two r0 within 1s` is explored within
#     `--timeout 10` (the property holds at every bound, so the checker goes on until the time
#     is up; 1024, the largest --temporal-bound, caps it); baseline: the same for a 5-rule port.
#     Wall-clock: on a loaded machine it reaches less.
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

spec=specs/table_clean.spec
grep -v -E '^(never|only|assume|after|stable|given) ' "$spec" > "$work/table_clean.spec"
expect_exit 0 "$arbc" verify "$spec"  # six proved, the response holds up to the bound
expect_exit 0 "$arbc" verify "$work/table_clean.spec"
value=$($median 11 "$arbc" verify "$spec")
baseline=$($median 11 "$arbc" verify "$work/table_clean.spec")
python3 -c "import json,sys; v,b=float(sys.argv[1]),float(sys.argv[2]); print(json.dumps({'name': 'verify_temporal_table_clean', 'value': round(v,4), 'unit': 's', 'target': 2.0, 'baseline': round(b,4), 'ratio': round(b/v,2)}))" "$value" "$baseline"

# The bound reached in 10 s (median of 3): "unknown (timeout) after N messages" or, at the
# cap, "holds up to 1024 messages".
reached() {
  local spec=$1 runs=() n
  for _ in 1 2 3; do
    n=$("$arbc" verify "$spec" --temporal-bound 1024 --timeout 10 2>&1 |
      sed -n 's/.*never two r0 within 1s.*\(after\|up to\) \([0-9]*\) messages.*/\2/p' || true)
    [ -n "$n" ] || { echo "verify_temporal.sh: no bound in the output for $spec" >&2; exit 1; }
    runs+=("$n")
  done
  printf '%s\n' "${runs[@]}" | sort -n | sed -n 2p
}
python3 "$root/bench/verify/gen_temporal_port.py" 20 > "$work/deep20.spec"
python3 "$root/bench/verify/gen_temporal_port.py" 5 > "$work/deep5.spec"
value=$(reached "$work/deep20.spec")
baseline=$(reached "$work/deep5.spec")
python3 -c "import json,sys; v,b=int(sys.argv[1]),int(sys.argv[2]); print(json.dumps({'name': 'verify_temporal_bound_20_rules_10s', 'value': v, 'unit': 'messages', 'baseline': b, 'baseline_is': '5-rule port', 'ratio': round(v/b,2)}))" "$value" "$baseline"
