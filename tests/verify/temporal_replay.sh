#!/usr/bin/env bash
# A violated property over time is written as a tests file (--counterexamples) that `arbc test`
# replays on the runtime, and the replay passes: the counterexample is real
# (docs/checks.md#temporal). Usage: temporal_replay.sh ARBC SPEC RULE [VERIFY OPTIONS...]
set -u
arbc=$1 spec=$2 rule=$3
shift 3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$arbc" verify --counterexamples "$dir" "$@" "$spec" >"$dir/out.txt"
code=$?
[ "$code" -eq 1 ] || { echo "FAIL: arbc verify exited $code, expected 1 (violated)"; exit 1; }
file=$(ls "$dir"/*."$rule".test.spec 2>/dev/null | head -1)
[ -n "$file" ] || { echo "FAIL: no tests file for rule $rule in $dir"; ls "$dir"; exit 1; }
grep -q "tests for " "$file" || { echo "FAIL: $file has no tests for"; exit 1; }
"$arbc" test --no-verify "$file" >"$dir/test.txt" 2>&1
code=$?
cat "$dir/test.txt"
[ "$code" -eq 0 ] || { echo "FAIL: arbc test exited $code on the counterexample"; exit 1; }
grep -q "1 passed, 0 failed" "$dir/test.txt" || { echo "FAIL: the replay did not pass"; exit 1; }
echo "ok: $file replays"
