#!/usr/bin/env bash
# Figure for issue 2: `arbc check` on a generated spec with 10,000 rules over 50 arbitrated
# ports (bench/gen_spec.py). Target: at most 1 s, median of 5 runs.
# Env (set by bench/run): ARBC (Release arbc), ARBC_ROOT, ARBC_BENCH_BUILD.
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
arbc=${ARBC:-$root/build/cli/arbc}
work=${ARBC_BENCH_BUILD:-$root/build}/bench-data
mkdir -p "$work"
spec=$work/check_10000_rules.spec
python3 "$root/bench/gen_spec.py" --rules 10000 --ports 50 --name check_10000_rules > "$spec"
# The figure only means something if the spec is valid: a failing check would time an error path.
if ! "$arbc" check "$spec" >/dev/null 2>&1; then
  echo "check.sh: arbc check rejected the generated spec $spec" >&2
  exit 1
fi
seconds=$(python3 "$root/bench/median.py" 5 "$arbc" check "$spec")
printf '{"name": "check_10000_rules", "value": %s, "unit": "s"}\n' "$seconds"
