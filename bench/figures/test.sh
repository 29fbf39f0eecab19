#!/usr/bin/env bash
# Figure for issue 17: `arbc test` on 1,000 tests of a table_clean-sized app: the app of
# specs/table_clean.spec with its tests repeated (renamed) up to 1,000. Target: under 5 s,
# median of 3 runs. Baseline, in the same run: the same spec with --filter choosing one test
# (the fixed cost: compile, prove, write the monitors).
# Env (set by bench/run): ARBC (Release arbc), ARBC_ROOT, ARBC_BENCH_BUILD.
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
arbc=${ARBC:-$root/build/cli/arbc}
work=${ARBC_BENCH_BUILD:-$root/build}/bench-data
mkdir -p "$work"
spec=$work/test_1000_cases.spec
python3 - "$root/specs/table_clean.spec" "$spec" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
start = text.index('\ntest "')
app, tests = text[:start], re.findall(r'^test "([^"]*)"(.*?^})', text[start:], re.M | re.S)
out = [app]
for k in range(1000):
    name, body = tests[k % len(tests)]
    out.append(f'\ntest "{name} #{k}"{body}\n')
open(sys.argv[2], "w", encoding="utf-8").write("".join(out))
PY
# The figure only means something if every test passes: a failing suite would time an error path.
if ! "$arbc" test "$spec" >/dev/null 2>&1; then
  echo "test.sh: arbc test failed on the generated spec $spec" >&2
  exit 1
fi
seconds=$(python3 "$root/bench/median.py" 3 "$arbc" test "$spec")
baseline=$(python3 "$root/bench/median.py" 3 "$arbc" test "$spec" --filter "put after take #2")
ratio=$(python3 -c "print(f'{$seconds / $baseline:.2f}')")
printf '{"name": "test_1000_cases", "value": %s, "unit": "s", "baseline": %s, "ratio": %s}\n' \
  "$seconds" "$baseline" "$ratio"
