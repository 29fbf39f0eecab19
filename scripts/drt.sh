#!/usr/bin/env bash
# Random differential testing of the proof against the runtime (issue 38 item 8;
# docs/reliability.md#random-differential-testing): random valid specs from SEED, each verified
# and run on the embedded runtime in simulated time under random inputs, for SECONDS; every
# disagreement shrunk and written as a case folder under $ARBC_DRT_OUT (default build/drt-found).
# The last line is exactly `drt: N specs, M steps, K disagreements`; exit 1 on a disagreement.
#   scripts/drt.sh [SECONDS] [SEED] [OPTIONS...]   (SECONDS default 60, SEED default 38;
#   options go to tests/drt/drt/campaign.py: --avoid-open, --specs N, --runs N, --no-shrink)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
seed=${2:-38}
shift $(( $# > 2 ? 2 : $# ))
arbc=${ARBC:-${ARBC_BUILD_DIR:-$root/build}/cli/arbc}
out=${ARBC_DRT_OUT:-${ARBC_BUILD_DIR:-$root/build}/drt-found}
export PYTHONDONTWRITEBYTECODE=1  # no __pycache__ in the source tree
cd "$root/tests/drt"
exec python3 -m drt.campaign "$arbc" "$seconds" "$seed" --out "$out" "$@"
