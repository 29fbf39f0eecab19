#!/usr/bin/env bash
# The sanitizer jobs of CI (issue 8):
#   1. AddressSanitizer + UndefinedBehaviorSanitizer build of everything; the whole test suite.
#   2. ThreadSanitizer build of the runtime's tests; the real-time executor's tests (ctest -R Realtime).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)

ARBC_BUILD_DIR=$root/build-asan "$root/scripts/build.sh" -DARBC_SANITIZE=ON -DARBC_BENCH=OFF
# The DDS split runs (label dds) replay the paper's experiment in two processes at ten times
# real time and judge the robot's outcome: a sanitized build on two cores cannot keep that pace,
# so of them only the runs that check what the processes do on signals and with a program
# without arbc (not how fast) run here; the rest run in the normal build (scripts/test.sh).
(cd "$root/build-asan" &&
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 &&
  ctest --output-on-failure -j"$jobs" -LE dds &&
  ctest --output-on-failure -j"$jobs" -R 'dds_split_signals|dds_interop')

export CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1
cmake -S "$root" -B "$root/build-tsan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARBC_TSAN=ON -DARBC_BENCH=OFF \
  -DARBC_WERROR=${ARBC_WERROR:-OFF} >/dev/null
cmake --build "$root/build-tsan" -j"$jobs" --target runtime_test
(cd "$root/build-tsan" &&
  TSAN_OPTIONS=halt_on_error=1 ctest --output-on-failure -j"$jobs" -R Realtime --no-tests=error)
