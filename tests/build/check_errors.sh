#!/usr/bin/env bash
# check_errors.sh ARBC SCRATCH: exit codes and messages of `arbc build` on bad input; nothing is
# written on failure.
set -uo pipefail
arbc=$1 scratch=$2
rm -rf "$scratch" && mkdir -p "$scratch"
fail() { echo "FAIL: $*"; exit 1; }
expect() {  # expect CODE TEXT -- command...
  local code=$1 text=$2; shift 3
  out=$("$@" 2>&1); rc=$?
  [ "$rc" -eq "$code" ] || fail "'$*' exited $rc, expected $code: $out"
  [[ "$out" == *"$text"* ]] || fail "'$*' output lacks '$text': $out"
}
expect 0 "--no-verify" -- "$arbc" build --help
expect 2 "SPEC is required" -- "$arbc" build
expect 2 "cannot read" -- "$arbc" build "$scratch/missing.spec" -o "$scratch/out"
printf 'app broken;\nmodule A { out x: int; }\narbitrate A.x { r: from A.y; }\n' > "$scratch/broken.spec"
expect 2 "broken.spec:3:" -- "$arbc" build "$scratch/broken.spec" -o "$scratch/out"
expect 2 "unknown target 'yarp'" -- "$arbc" build specs/face_filter.spec --target yarp -o "$scratch/out"
[ ! -e "$scratch/out" ] || fail "a failed build wrote $scratch/out"
# An existing directory that is not an arbc build is never replaced.
mkdir -p "$scratch/keep/face_filter" && echo mine > "$scratch/keep/face_filter/notes.txt"
expect 2 "refusing to replace" -- "$arbc" build specs/face_filter.spec -o "$scratch/keep"
[ -f "$scratch/keep/face_filter/notes.txt" ] || fail "the user's directory was touched"
# A rebuild replaces an earlier build, dropping monitors of rules that no longer exist.
expect 0 "face_filter" -- "$arbc" build specs/face_filter.spec -o "$scratch/re"
touch "$scratch/re/face_filter/monitors/stale.lua"
expect 0 "face_filter" -- "$arbc" build specs/face_filter.spec -o "$scratch/re"
[ ! -e "$scratch/re/face_filter/monitors/stale.lua" ] || fail "a stale monitor survived a rebuild"
echo "ok"
