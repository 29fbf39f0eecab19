#!/usr/bin/env bash
# DDS figures (issue 15): dds_direct_latency_us, dds_mediated_latency_us (baseline: direct),
# dds_mediated_throughput_msgs (baseline: one writer straight into the reader). Plain Fast-DDS
# programs (bench/dds/dds_peer.cc, types from fastddsgen) around an arbc mediator; all on this
# machine (tests/dds/loopback_profile.xml). How they are taken: bench/dds/dds_figures.py.
set -euo pipefail
: "${ARBC:?set by bench/run}" "${ARBC_ROOT:?}" "${ARBC_BENCH_BUILD:?}"
peer=$ARBC_BENCH_BUILD/bench/dds/dds_peer
if [ ! -x "$peer" ]; then
  echo "dds.sh: $peer is missing (Fast-DDS or fastddsgen not installed?); no DDS figures" >&2
  exit 0
fi
python3 "$ARBC_ROOT/bench/dds/dds_figures.py" "$ARBC" "$peer"
