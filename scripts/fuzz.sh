#!/usr/bin/env bash
# Builds the libFuzzer targets with clang into build-fuzz/ and runs each for SECONDS
# (default 30) on a copy of its seed corpus. Crashes and hangs land in build-fuzz/findings/.
# ARBC_WERROR=ON builds with warnings as errors (clang's view of our code; .ci/run sets it).
# Ordinary builds replay the seed corpora without clang: the fuzz_corpus_* ctests.
#   scripts/fuzz.sh [SECONDS] [TARGET...]
# Without TARGETs: every target whose name ends in "fuzz" (fuzz/CMakeLists.txt): app_json_fuzz,
# cdr_read_fuzz, constraint_fuzz, lua_value_fuzz, spec_frontend_fuzz, spec_halves_fuzz.
# docs/reliability.md records their runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-30}
shift || true
build=${ARBC_FUZZ_BUILD:-$root/build-fuzz}
export CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DARBC_FUZZ=ON -DARBC_TESTS=OFF -DARBC_BENCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARBC_WERROR=${ARBC_WERROR:-OFF} >/dev/null
targets=("$@")
if ((${#targets[@]} == 0)); then
  mapfile -t targets < <(cmake --build "$build" --target help | sed -n 's/^\.\.\. \(.*fuzz\)$/\1/p' | sort)
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}"
mkdir -p "$build/findings"
status=0
for t in "${targets[@]}"; do
  exe=$(find "$build" -type f -name "$t" -perm -u+x | head -1)
  corpus="$build/corpus/$t"
  mkdir -p "$corpus"
  seeds="$root/fuzz/corpus/${t%_fuzz}"
  [ -d "$seeds" ] && cp -r "$seeds"/. "$corpus"/
  echo "== $t for ${seconds}s"
  if ! "$exe" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$build/findings/$t-" -print_final_stats=1 2>"$build/$t.log"; then
    echo "$t: FINDING, see $build/$t.log and $build/findings/"
    tail -30 "$build/$t.log"
    status=1
  fi
  grep -E 'stat::number_of_executed_units|Done [0-9]+ runs' "$build/$t.log" | tail -2 || true
done
exit $status
