#!/usr/bin/env bash
# One YARP hop (issues 15 and 16), on real YARP when the Release tree found it
# (scripts/install-yarp.sh; CMAKE_PREFIX_PATH=/opt/arbc-yarp):
#   yarp_direct_latency_us      a BufferedPort<Bottle> to one in another process over tcp,
#                               round trip halved
#   yarp_arbitrated_latency_us  the same hop through the portmonitor carrier: a Lua monitor
#                               with a constraint over an event, beside an idle second
#                               connection into the same port (baseline: the direct hop)
# bench/yarp/yarp_hop_bench.cc alternates the two, round by round; each round's figure is the
# median of its pings, and the figure printed is the median of the rounds.
set -euo pipefail
build=${ARBC_BENCH_BUILD:-${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}/build-bench}
bench=$build/bench/yarp/yarp_hop_bench
if [ ! -x "$bench" ]; then
  echo "yarp.sh: SKIPPED, YARP was not found when $build was configured (scripts/install-yarp.sh)" >&2
  exit 0
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! "$bench" "${ARBC_BENCH_ROUNDS:-7}" "${ARBC_BENCH_PINGS:-1000}" >"$log" 2>&1; then
  echo "yarp.sh: yarp_hop_bench failed:" >&2
  grep -v '^\[INFO\]' "$log" | tail -20 >&2
  exit 1
fi
python3 - "$log" <<'PY'
import json, statistics, sys
rounds = {"direct": [], "arbitrated": []}
for line in open(sys.argv[1]):
    words = line.split()
    if len(words) == 2 and words[0] in rounds:  # YARP's own log lines start with "["
        rounds[words[0]].append(float(words[1]))
direct = statistics.median(rounds["direct"])
arbitrated = statistics.median(rounds["arbitrated"])
print(json.dumps({"name": "yarp_direct_latency_us", "value": round(direct, 1), "unit": "us",
                  "rounds": len(rounds["direct"])}))
print(json.dumps({"name": "yarp_arbitrated_latency_us", "value": round(arbitrated, 1), "unit": "us",
                  "baseline": round(direct, 1), "ratio": round(arbitrated / direct, 2)}))
PY
