#!/usr/bin/env bash
# `arbc verify --timeout T` ends within the run's deadline (plus the watchdog's 5 s grace for a
# query Z3 does not stop), whatever context asks: deadline_witness.spec (drt seed 38 spec 186)
# asks the claim tests' own context for witnesses of 1e308 float vectors, which was not
# watched, and took 45 s (66 s under load) with --timeout 10. The bound below is three times
# the deadline, wide enough for a loaded machine and far below what the unwatched run took.
#   run_deadline.sh ARBC SPEC
set -u
arbc=$1 spec=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
start=$(date +%s%N)
"$arbc" verify "$spec" --timeout 10 --counterexamples "$out/cex" >"$out/report" 2>&1
code=$?
took=$(( ($(date +%s%N) - start) / 1000000 ))
if [ "$code" -gt 1 ]; then
  echo "FAIL: exit $code"; cat "$out/report"; exit 1
fi
if [ "$took" -gt 30000 ]; then
  echo "FAIL: --timeout 10 took $took ms"; cat "$out/report"; exit 1
fi
echo "ok: --timeout 10 ended in $took ms with exit $code"
