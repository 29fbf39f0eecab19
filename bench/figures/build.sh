#!/usr/bin/env bash
# Figure for issue 4: `arbc build` (compile, verify, generate, write) of a generated spec with
# 10,000 rules with monitor bodies over 50 arbitrated ports (bench/gen_spec.py), each port fed
# by a status stream: 10,050 monitors. Target: at most
# 2 s, median of 5 runs, rebuilding into the same directory (the edit-build loop). Baseline: the same build with --no-verify, so the ratio shows what the
# proof adds to code generation.
# Env (set by bench/run): ARBC (Release arbc), ARBC_ROOT, ARBC_BENCH_BUILD.
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
arbc=${ARBC:-$root/build/cli/arbc}
work=${ARBC_BENCH_BUILD:-$root/build}/bench-data
mkdir -p "$work"
spec=$work/build_10000_rules.spec
# gen_spec.py declares each port's events for monitor code to set; here a status stream per
# port feeds them instead (`events from`), so the spec verifies and each port gets a feed.
python3 "$root/bench/gen_spec.py" --rules 10000 --ports 50 --bodies --name build_10000_rules |
  python3 -c '
import re, sys
for line in sys.stdin:
    m = re.match(r"event (e(\d+)_0(?:, e\d+_\d+)*) lifetime (\S+);", line)
    if m:
        print("module Status%s { out status: list<string>; }" % m.group(2))
        print("events from Status%s.status { %s } lifetime %s;" % (m.group(2), m.group(1), m.group(3)))
    else:
        sys.stdout.write(line)
' > "$spec"
# The figure only means something if the build succeeds: a failure would time an error path.
if ! "$arbc" build "$spec" -o "$work/build_out" >/dev/null 2>&1; then
  echo "build.sh: arbc build failed on the generated spec $spec" >&2
  exit 1
fi
monitors=$(ls "$work/build_out/build_10000_rules/monitors" | wc -l)
if [ "$monitors" -lt 10000 ]; then
  echo "build.sh: expected at least 10000 monitors, got $monitors" >&2
  exit 1
fi
seconds=$(python3 "$root/bench/median.py" 5 "$arbc" build "$spec" -o "$work/build_out")
baseline=$(python3 "$root/bench/median.py" 5 "$arbc" build "$spec" -o "$work/build_out" --no-verify)
ratio=$(python3 -c "print(round($seconds / $baseline, 2))")
printf '{"name": "build_10000_rules", "value": %s, "unit": "s", "baseline": %s, "ratio": %s}\n' \
  "$seconds" "$baseline" "$ratio"
# A rebuild links the monitors whose bytes did not change; a first build into an empty
# directory writes all 10,050 files. Same baseline, so the ratio is the price of a cold output.
fresh_root=$work/build_fresh
rm -rf "$fresh_root" && mkdir -p "$fresh_root"
fresh=$(python3 "$root/bench/median.py" 5 sh -c "exec \"\$0\" build \"\$1\" -o \"\$(mktemp -d -p \"\$2\")\"" \
  "$arbc" "$spec" "$fresh_root")
rm -rf "$fresh_root"
ratio=$(python3 -c "print(round($fresh / $baseline, 2))")
printf '{"name": "build_10000_rules_fresh_output", "value": %s, "unit": "s", "baseline": %s, "ratio": %s}\n' \
  "$fresh" "$baseline" "$ratio"
