#!/usr/bin/env bash
# A counterexample that `arbc test` cannot replay faithfully is written by --counterexamples as
# DIR/APP.….NAME.txt that says why (WHY, a fixed part of its text), and as no tests file: a test
# that could not fail would pass for a broken app (docs/testing.md#claims).
# Usage: counterexample_note.sh ARBC SPEC NAME WHY
set -u
arbc=$1 spec=$2 name=$3 why=$4
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$arbc" verify --counterexamples "$dir" "$spec" >"$dir/out.txt"
code=$?
[ "$code" -eq 1 ] || { echo "FAIL: arbc verify exited $code, expected 1 (refuted)"; exit 1; }
file=$(ls "$dir"/*."$name".txt 2>/dev/null | head -1)
[ -n "$file" ] || { echo "FAIL: no $name note in $dir"; ls "$dir"; exit 1; }
cat "$file"
grep -q "^Not written as a test: .*$why" "$file" || { echo "FAIL: $file does not say why"; exit 1; }
if ls "$dir"/*."$name".test.spec >/dev/null 2>&1; then
  echo "FAIL: a tests file was written for $name"; exit 1
fi
echo "ok: $file says why $name is not a test"
