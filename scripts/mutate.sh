#!/usr/bin/env bash
# Mutation testing (docs/reliability.md, "Mutation testing"). No C++ mutation tool is packaged
# for Debian, so the mutants are a reviewed list of one-line changes to the critical logic
# (scripts/mutation_sites.txt: file, line, replacement, and why it is a bug). Each is applied in
# turn to a scratch copy of this tree, which is rebuilt (ccache) and tested with ctest: first the
# unit tests of the mutated file's stage, then the rest, then the DDS runs. A mutant is killed
# when a test fails. Prints the score and the survivors.
#
#   scripts/mutate.sh                 every site
#   scripts/mutate.sh ID...           only these sites
#   scripts/mutate.sh --check         only check that every site still matches exactly one line
#                                     of the tree (ctest runs this: mutation_sites_match_the_tree)
#   scripts/mutate.sh --list          the sites' ids and kinds
#
# Environment: ARBC_MUTATE_DIR (scratch directory, default a new one under /tmp, kept for its
# logs), ARBC_MUTATE_EXCLUDE (a ctest -E regex; default: the installed-package and Chromium
# tests, which check packaging and HTML, not the logic mutated here, and the site-list checks,
# which fail on any mutated tree by construction and would "kill" every mutant, and code_format,
# which a mutant's line may fail without any behaviour changing), ARBC_MUTATE_JOBS (2),
# ARBC_WERROR (as scripts/build.sh: ON shares ccache's objects with CI's builds).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sites_py="python3 $root/scripts/mutation_sites.py"

case "${1:-}" in
  --check) exec $sites_py check "$root" ;;
  --list) exec $sites_py list ;;
  -h|--help) sed -n '2,/^set /{/^#/p}' "$0"; exit 0 ;;
esac
$sites_py check "$root" >/dev/null || { $sites_py check "$root"; exit 2; }
if [ $# -gt 0 ]; then ids=("$@"); else mapfile -t ids < <($sites_py list | cut -f1); fi

jobs=${ARBC_MUTATE_JOBS:-2}
exclude=${ARBC_MUTATE_EXCLUDE:-installed_package|report_in_chromium|mutation_site|code_format}
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?')  # the tree tested
git -C "$root" diff --quiet HEAD 2>/dev/null || commit="$commit with uncommitted changes"
scratch=${ARBC_MUTATE_DIR:-$(mktemp -d /tmp/arbc-mutate.XXXXXX)}
mkdir -p "$scratch/logs"
echo "scratch copy: $scratch (logs in $scratch/logs)"
# A fresh copy of the tree as it is now (uncommitted changes included). The build directory
# sits inside it, as build/ does in a checkout, so that ccache finds the objects of the
# checkout's own builds (CCACHE_BASEDIR makes the paths relative, as scripts/build.sh does).
mkdir -p "$scratch/src"
find "$scratch/src" -mindepth 1 -maxdepth 1 ! -name build -exec rm -rf {} +
# Extracted with the time of the copy (-m), not the files' own: a build directory kept from an
# earlier run has objects newer than a source edited before that run's copy, and make would
# keep them (ccache makes the rebuild of unchanged files cheap).
tar -C "$root" --exclude='./build*' --exclude='./.git' -cf - . | tar -C "$scratch/src" -xmf -
export CCACHE_BASEDIR=$scratch/src CCACHE_NOHASHDIR=1

build() {  # build LOG [TARGET]: 0 when the tree (or only TARGET) builds
  cmake -S "$scratch/src" -B "$scratch/src/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DARBC_WERROR="${ARBC_WERROR:-OFF}" >>"$1" 2>&1 &&
    cmake --build "$scratch/src/build" -j"$jobs" ${2:+--target "$2"} >>"$1" 2>&1
}
run_tests() {  # run_tests LOG [--stop-on-failure]: ctest's exit code
  (cd "$scratch/src/build" && ctest -j"$jobs" --timeout 300 -E "$exclude" "${@:2}" >"$1" 2>&1)
}

# Cheapest first: most mutants fail a unit test of their own stage within seconds, and that
# needs only the stage's test programs (the arbc_unit_STAGE target, CMakeLists.txt); the rest of
# the suite needs the whole tree rebuilt and minutes, the DDS runs minutes more. A survivor
# passes all three. Prints the verdict.
test_mutant() {  # test_mutant BUILD_LOG STAGE UNIT_LOG REST_LOG DDS_LOG
  local unit_target=arbc_unit_$2
  if grep -q "$unit_target" "$scratch/src/build/Makefile" 2>/dev/null; then
    build "$1" "$unit_target" || { echo "does not build (fix the site)"; return; }
    run_tests "$3" --stop-on-failure -L "^unit:$2\$" || { echo "killed by $(first_failure "$3")"; return; }
  fi
  build "$1" || { echo "does not build (fix the site)"; return; }
  run_tests "$4" --stop-on-failure -LE "^dds\$|^unit:$2\$" || { echo "killed by $(first_failure "$4")"; return; }
  run_tests "$5" --stop-on-failure -L '^dds$' || { echo "killed by $(first_failure "$5")"; return; }
  echo SURVIVED
}
first_failure() {  # first_failure LOG: the first test ctest reports as failed in LOG
  local name
  name=$(grep -v '(Skipped)$' "$1" | sed -n 's/^[[:space:]]*[0-9]* - \(.*\) (.*)$/\1/p' | head -1)
  echo "${name:-a failing test}"
}

echo "baseline: building and testing the unmutated tree"
build "$scratch/logs/baseline-build.log" || { echo "the unmutated tree does not build"; exit 2; }
run_tests "$scratch/logs/baseline-test.log" || {
  echo "the unmutated tree fails its tests ($scratch/logs/baseline-test.log): fix that first"
  exit 2
}

killed=0 survived=0 broken=0
survivors=() unbuildable=()
for id in "${ids[@]}"; do
  file=$($sites_py show "$id" | sed -n 's/^file: //p')
  cp -p "$scratch/src/$file" "$scratch/original"
  where=$($sites_py apply "$scratch/src" "$id")
  stage=${file%%/*}
  logs=("$scratch/logs/$id-test-unit.log" "$scratch/logs/$id-test.log" "$scratch/logs/$id-test-dds.log")
  rm -f "${logs[@]}" "$scratch/logs/$id-build.log"
  start=$(date +%s)
  verdict=$(test_mutant "$scratch/logs/$id-build.log" "$stage" "${logs[@]}")
  case $verdict in
    SURVIVED) survived=$((survived + 1)); survivors+=("$id") ;;
    "does not build"*) broken=$((broken + 1)); unbuildable+=("$id") ;;
    *) killed=$((killed + 1)) ;;
  esac
  printf '%-36s %-45s %4ss  %s\n' "$id" "$verdict" "$(( $(date +%s) - start ))" "$where"
  cp "$scratch/original" "$scratch/src/$file"
  touch "$scratch/src/$file"  # newer than the mutant's objects: the next build recompiles it
done

total=$((killed + survived))
echo
echo "mutation score: $killed killed of $total mutants ($(( total ? 100 * killed / total : 0 ))%)," \
  "$(date -u +%Y-%m-%d), $commit"
[ "$broken" -eq 0 ] || echo "sites that do not build (not counted): ${unbuildable[*]}"
for id in "${survivors[@]}"; do
  echo "survivor $id: $($sites_py show "$id" | sed -n 's/^why: //p')"
done
[ "$survived" -eq 0 ] && [ "$broken" -eq 0 ]
