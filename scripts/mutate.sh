#!/usr/bin/env bash
# Mutation testing (docs/reliability.md, "Mutation testing"). No C++ mutation tool is packaged
# for Debian, so the mutants are a reviewed list of one-line changes to the critical logic
# (scripts/mutation_sites.txt: file, line, replacement, and why it is a bug). Each is applied in
# turn to a scratch copy of this tree, which is rebuilt (ccache) and tested with ctest; a mutant
# is killed when a test fails. Prints the score and the survivors.
#
#   scripts/mutate.sh                 every site (about 3 minutes each on 2 cores)
#   scripts/mutate.sh ID...           only these sites
#   scripts/mutate.sh --check         only check that every site still matches exactly one line
#                                     of the tree (ctest runs this: mutation_sites_match_the_tree)
#   scripts/mutate.sh --list          the sites' ids and kinds
#
# Environment: ARBC_MUTATE_DIR (scratch directory, default a new one under /tmp, kept for its
# logs), ARBC_MUTATE_EXCLUDE (a ctest -E regex; default: the installed-package and Chromium
# tests, which check packaging and HTML, not the logic mutated here, and the site-list checks,
# which fail on any mutated tree by construction and would "kill" every mutant), ARBC_MUTATE_JOBS (2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sites_py="python3 $root/scripts/mutation_sites.py"

case "${1:-}" in
  --check) exec $sites_py check "$root" ;;
  --list) exec $sites_py list ;;
  -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
esac
$sites_py check "$root" >/dev/null || { $sites_py check "$root"; exit 2; }
if [ $# -gt 0 ]; then ids=("$@"); else mapfile -t ids < <($sites_py list | cut -f1); fi

jobs=${ARBC_MUTATE_JOBS:-2}
exclude=${ARBC_MUTATE_EXCLUDE:-installed_package|report_in_chromium|mutation_site}
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
tar -C "$root" --exclude='./build*' --exclude='./.git' -cf - . | tar -C "$scratch/src" -xf -
export CCACHE_BASEDIR=$scratch/src CCACHE_NOHASHDIR=1

build() {  # build LOG: 0 when the tree builds
  cmake -S "$scratch/src" -B "$scratch/src/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    >"$1" 2>&1 && cmake --build "$scratch/src/build" -j"$jobs" >>"$1" 2>&1
}
run_tests() {  # run_tests LOG [--stop-on-failure]: ctest's exit code
  (cd "$scratch/src/build" && ctest -j"$jobs" --timeout 300 -E "$exclude" "${@:2}" >"$1" 2>&1)
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
  rm -f "$scratch/logs/$id-test.log" "$scratch/logs/$id-test-dds.log"
  start=$(date +%s)
  if ! build "$scratch/logs/$id-build.log"; then
    verdict="does not build (fix the site)"; broken=$((broken + 1)); unbuildable+=("$id")
  # The DDS runs take minutes; most mutants fail a faster test first.
  elif run_tests "$scratch/logs/$id-test.log" --stop-on-failure -LE dds &&
      run_tests "$scratch/logs/$id-test-dds.log" --stop-on-failure -L dds; then
    verdict="SURVIVED"; survived=$((survived + 1)); survivors+=("$id")
  else
    first=$(cat "$scratch/logs/$id-test.log" "$scratch/logs/$id-test-dds.log" 2>/dev/null |
      grep -v '(Skipped)$' | sed -n 's/^[[:space:]]*[0-9]* - \(.*\) (.*)$/\1/p' | head -1)
    verdict="killed by ${first:-a failing test}"; killed=$((killed + 1))
  fi
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
