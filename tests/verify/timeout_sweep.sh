#!/usr/bin/env bash
# arbc verify at many deadlines on one spec: each run ends in a verdict (exit 0 or 1, "unknown"
# when the time ran out), never an internal error (exit 3), wherever the deadline falls
# (verify/verify.cc: a "canceled" from Z3 after the watchdog fired is the time being up).
#   timeout_sweep.sh ARBC SPEC
set -u
arbc=$1 spec=$2
for t in 0.001 0.002 0.004 0.006 0.008 0.01 0.012 0.015 0.018 0.02 0.025 0.03 0.04 0.05 0.07 0.1; do
  "$arbc" verify "$spec" --timeout "$t" >/dev/null 2>/tmp/timeout_sweep.$$ ; code=$?
  if [ "$code" -gt 1 ] || grep -q "internal error" /tmp/timeout_sweep.$$; then
    echo "FAIL: --timeout $t: exit $code"; cat /tmp/timeout_sweep.$$; rm -f /tmp/timeout_sweep.$$; exit 1
  fi
done
rm -f /tmp/timeout_sweep.$$
echo "ok: every deadline gave a verdict"
