#!/usr/bin/env bash
# A violated property over time is written as a tests file (--counterexamples) that states the
# property where the app broke it (docs/checks.md#temporal): `arbc test` of that file fails on
# the app, so the counterexample is real, and with --fixed FIXED_SPEC (the app without the
# mutation) the same file passes: it can be kept as a regression test. The same for a claim
# about single decisions (docs/testing.md#claims): RULE is then the end of the file's name,
# RULE.RULE.exclusive or RULE.assert.
# Usage: temporal_replay.sh ARBC SPEC RULE [--fixed FIXED_SPEC] [VERIFY OPTIONS...]
set -u
arbc=$1 spec=$2 rule=$3
shift 3
fixed=
if [ "${1:-}" = "--fixed" ]; then fixed=$2; shift 2; fi
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$arbc" verify --counterexamples "$dir" "$@" "$spec" >"$dir/out.txt"
code=$?
[ "$code" -eq 1 ] || { echo "FAIL: arbc verify exited $code, expected 1 (violated)"; exit 1; }
file=$(ls "$dir"/*."$rule".test.spec 2>/dev/null | head -1)
[ -n "$file" ] || { echo "FAIL: no tests file for rule $rule in $dir"; ls "$dir"; exit 1; }
grep -q "tests for " "$file" || { echo "FAIL: $file has no tests for"; exit 1; }
grep -q "kept as a regression" "$file" ||
  { echo "FAIL: $file does not state the property:"; cat "$file"; exit 1; }
"$arbc" test --no-verify "$file" >"$dir/test.txt" 2>&1
code=$?
cat "$dir/test.txt"
[ "$code" -eq 1 ] || { echo "FAIL: arbc test exited $code on the broken app, expected 1"; exit 1; }
grep -q "0 passed, 1 failed" "$dir/test.txt" || { echo "FAIL: the test did not fail"; exit 1; }
if [ -n "$fixed" ]; then
  sed "s|^tests for \".*\";|tests for \"$(realpath "$fixed")\";|" "$file" >"$dir/fixed.test.spec"
  "$arbc" test --no-verify "$dir/fixed.test.spec" >"$dir/fixed.txt" 2>&1
  code=$?
  cat "$dir/fixed.txt"
  [ "$code" -eq 0 ] || { echo "FAIL: arbc test exited $code on the fixed app $fixed"; exit 1; }
fi
echo "ok: $file fails on $spec${fixed:+ and passes on $fixed}"
