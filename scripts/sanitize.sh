#!/usr/bin/env bash
# The sanitizer jobs of CI (issue 8):
#   1. AddressSanitizer + UndefinedBehaviorSanitizer build of everything; the whole test suite.
#   2. ThreadSanitizer build; the tests of the real-time executor (ctest -R RealTime).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)

ARBC_BUILD_DIR=$root/build-asan "$root/scripts/build.sh" -DARBC_SANITIZE=ON -DARBC_BENCH=OFF
(cd "$root/build-asan" &&
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -j"$jobs")

ARBC_BUILD_DIR=$root/build-tsan "$root/scripts/build.sh" -DARBC_TSAN=ON -DARBC_BENCH=OFF
(cd "$root/build-tsan" && TSAN_OPTIONS=halt_on_error=1 ctest --output-on-failure -j"$jobs" -R RealTime)
