#!/usr/bin/env bash
# Configures and builds arbc into build/ (or $ARBC_BUILD_DIR). Extra arguments go to cmake.
# ARBC_WERROR=ON makes warnings in our code errors (.ci/run sets it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ARBC_BUILD_DIR:-$root/build}
# Paths relative to the checkout let ccache share objects between clones (CI builds a fresh one).
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
export CCACHE_NOHASHDIR=1
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=${ARBC_BUILD_TYPE:-RelWithDebInfo} \
  -DARBC_WERROR=${ARBC_WERROR:-OFF} "$@" >/dev/null
cmake --build "$build" -j"$(nproc)"
