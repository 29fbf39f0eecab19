#!/usr/bin/env bash
# Figures for issue 14: `arbc docs` on large applications (bench/gen_spec.py, each port's events
# fed by a status stream so the spec verifies, as in build.sh).
#   docs_40000_modules: 13,334 sources, 13,333 arbitrated ports and their 13,333 status modules
#     (40,000 modules, 26,666 rules): over the drawing limit, so index.md only, and arbc says
#     the diagram is skipped. Target: under 30 s (it ran six minutes in Graphviz before).
#   docs_1800_elements_drawn: 400 sources, 200 ports, 600 rules: under the limit (2,000), drawn.
# Baseline for both: `arbc verify` of the same spec, which `docs` runs too, so the ratio is what
# writing the tables (and drawing) adds. Medians of 3 runs.
# Env (set by bench/run): ARBC (Release arbc), ARBC_ROOT, ARBC_BENCH_BUILD.
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
arbc=${ARBC:-$root/build/cli/arbc}
work=${ARBC_BENCH_BUILD:-$root/build}/bench-data
mkdir -p "$work"

# gen SPEC NAME RULES PORTS SOURCES: a generated spec whose port events come from status streams.
gen() {
  python3 "$root/bench/gen_spec.py" --rules "$3" --ports "$4" --sources "$5" --name "$2" |
    python3 -c '
import re, sys
for line in sys.stdin:
    m = re.match(r"event (e(\d+)_0(?:, e\d+_\d+)*) lifetime (\S+);", line)
    if m:
        print("module Status%s { out status: list<string>; }" % m.group(2))
        print("events from Status%s.status { %s } lifetime %s;" % (m.group(2), m.group(1), m.group(3)))
    else:
        sys.stdout.write(line)
' > "$1"
}

# figure NAME SPEC EXPECT: checks that docs writes what EXPECT says, then times docs and verify.
figure() {
  local name=$1 spec=$2 expect=$3 out=$work/docs_out_$1
  rm -rf "$out"
  # The figure only means something if the spec verifies and docs does what is expected.
  if ! "$arbc" verify "$spec" >/dev/null 2>&1; then
    echo "docs.sh: arbc verify rejected the generated spec $spec" >&2
    exit 1
  fi
  if ! "$arbc" docs "$spec" -o "$out" | grep -q "$expect"; then
    echo "docs.sh: arbc docs on $spec did not print '$expect'" >&2
    exit 1
  fi
  local seconds baseline ratio
  seconds=$(python3 "$root/bench/median.py" 3 "$arbc" docs "$spec" -o "$out")
  baseline=$(python3 "$root/bench/median.py" 3 "$arbc" verify "$spec")
  ratio=$(python3 -c "print(round($seconds / $baseline, 2))")
  printf '{"name": "%s", "value": %s, "unit": "s", "baseline": %s, "ratio": %s}\n' \
    "$name" "$seconds" "$baseline" "$ratio"
}

gen "$work/docs_40000_modules.spec" docs_40000_modules 26666 13333 13334
modules=$(grep -c '^module ' "$work/docs_40000_modules.spec")
if [ "$modules" -ne 40000 ]; then
  echo "docs.sh: expected 40000 modules, generated $modules" >&2
  exit 1
fi
figure docs_40000_modules "$work/docs_40000_modules.spec" "diagram is skipped for size"
gen "$work/docs_1800_elements.spec" docs_1800_elements 600 200 400
figure docs_1800_elements_drawn "$work/docs_1800_elements.spec" "app.svg"
