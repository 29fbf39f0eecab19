#!/usr/bin/env bash
# Golden tests of `arbc verify` as a whole process: output and exit code per case.
#   golden.sh ARBC            compare (run from the repository root)
#   ARBC_UPDATE_GOLDEN=1 golden.sh ARBC    rewrite the expected files (review them by eye)
# Each case: name, expected exit code, arguments. Expected stdout+stderr in tests/verify/golden/NAME.
set -uo pipefail
arbc=$1
dir=tests/verify/golden
mkdir -p "$dir"
failed=0
check() {
  local name=$1 want=$2
  shift 2
  local out rc
  out=$("$arbc" verify "$@" 2>&1)
  rc=$?
  if [ "$rc" != "$want" ]; then
    echo "FAIL $name: exit $rc, expected $want"; failed=1
  fi
  if [ -n "${ARBC_UPDATE_GOLDEN:-}" ]; then
    printf '%s\n' "$out" > "$dir/$name"
  elif ! diff -u "$dir/$name" <(printf '%s\n' "$out"); then
    echo "FAIL $name: output differs from $dir/$name"; failed=1
  fi
}
check proved.txt 0 tests/verify/table_clean.app.json tests/verify/search_and_track.app.json
check proved.json 0 --format json tests/verify/table_clean.app.json
check proved.sarif 0 --format sarif tests/verify/table_clean.app.json
check refuted.txt 1 tests/verify/table_clean_take_mutant.app.json
check refuted.json 1 --format json tests/verify/table_clean_take_mutant.app.json
check refuted.sarif 1 --format sarif tests/verify/table_clean_take_mutant.app.json
check warnings.txt 0 tests/verify/table_clean_warnings.app.json
check warnings_strict.txt 1 --strict tests/verify/table_clean_warnings.app.json
# Bad input: exit 2 and a message on stderr (pinned: stderr is captured with stdout).
check missing.txt 2 tests/verify/no_such_app.json
# Specs go through the compiler when this arbc has it (front end + lowering); else a clear error.
probe=$("$arbc" verify specs/search_and_track.spec 2>&1)
if [[ $probe == *"needs the spec compiler"* ]]; then
  check spec_without_compiler.txt 2 tests/verify/table_clean.spec
else
  check spec_proved.txt 0 specs/table_clean.spec specs/search_and_track.spec
  check spec_refuted.txt 1 tests/verify/table_clean_take_mutant.spec
  check spec_refuted.sarif 1 --format sarif tests/verify/table_clean_take_mutant.spec
  # Each proof check the fixtures above do not show: unfed, ownership, complete.
  check findings.txt 1 tests/verify/findings.spec
  # No time to decide is "unknown", exit 1, never "proved" (a surviving mutant, issue 13).
  check unknown_timeout.txt 1 --timeout 1e-9 tests/verify/overlap.spec
  check unknown_timeout.json 1 --timeout 1e-9 --format json tests/verify/overlap.spec
  # An event only an invariant or exclusive group mentions: the fix names them too.
  check invariant_only.txt 0 tests/verify/invariant_only.spec
  # Input with errors never looks clean: verdict "error", the diagnostics, exit 2.
  check bad_input.json 2 --format json tests/verify/bad.spec
  check bad_input.sarif 2 --format sarif tests/verify/bad.spec tests/verify/no_such_app.json \
    tests/verify/malformed.app.json
  check bad_input_mixed.txt 2 tests/verify/overlap.spec tests/verify/bad.spec
fi

# No arguments: specs/*.spec of the current directory (what the pre-commit hook runs).
root=$PWD
arbc=$(cd "$(dirname "$arbc")" && pwd)/$(basename "$arbc")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
dir=$root/$dir
check no_args_no_specs.txt 2
mkdir specs
cp "$root/tests/verify/table_clean_take_mutant.spec" specs/
if [[ $probe == *"needs the spec compiler"* ]]; then
  check no_args_without_compiler.txt 2
else
  check no_args.txt 1
fi
check bad_format.txt 2 --format xml tests/verify/table_clean.app.json
exit $failed
