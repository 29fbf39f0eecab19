#!/usr/bin/env bash
# Soak (issue 8): specs/table_clean.spec built by `arbc build`, then 100 million connection
# messages (ARBC_SOAK_MESSAGES to change) through its 14 connections and generated monitors
# in simulated time, every module a stand-in publishing every millisecond. Prints resident
# memory after a 1% warm-up and at the end (soak_rss_start, soak_rss_end, soak_rss_growth,
# soak_rss_peak), the Lua states' memory, the rate and the wall time. Takes minutes: not in CI.
set -euo pipefail
: "${ARBC:?set by bench/run}" "${ARBC_ROOT:?}" "${ARBC_BENCH_BUILD:?}"
bench=$ARBC_BENCH_BUILD/bench/soak/soak_bench
if [ ! -x "$bench" ]; then
  echo "soak.sh: $bench is missing; build the Release tree first (bench/run does)" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$ARBC" build "$ARBC_ROOT/specs/table_clean.spec" -o "$work" >/dev/null
"$bench" "$work/table_clean" "${ARBC_SOAK_MESSAGES:-100000000}"
