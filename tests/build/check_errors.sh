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
expect 2 "no such file" -- "$arbc" build "$scratch/missing.spec" -o "$scratch/out"
printf 'app broken;\nmodule A { out x: int; }\narbitrate A.x { r: from A.y; }\n' > "$scratch/broken.spec"
expect 2 "broken.spec:3:" -- "$arbc" build "$scratch/broken.spec" -o "$scratch/out"
# YARP cannot carry a delivery event (docs/language.md#delivery-events): bad input, exit 2.
expect 2 "delivery event 'e_arm_picking' (what PickAndPlace.cmd delivers) cannot be built for YARP" -- "$arbc" build specs/table_clean.spec --target yarp -o "$scratch/out"
[ ! -e "$scratch/out" ] || fail "a refused --target yarp build wrote $scratch/out"
expect 2 "unknown target 'ros'" -- "$arbc" build specs/face_filter.spec --target ros -o "$scratch/out"
expect 2 "unknown target 'yrp' (did you mean 'yarp'?); the targets are" -- "$arbc" build specs/face_filter.spec --target yrp -o "$scratch/out"
# The deployment file of --target yarp (docs/yarp.md#names-on-yarp).
# Each error at the line and column of its key or value, as a compiler reports a spec.
printf '{"topics": {"Nope.port": "/x"}}' > "$scratch/bad_port.json"
expect 2 "bad_port.json:1:13: error: \"topics\": \"Nope.port\" is not a port" -- "$arbc" build specs/face_filter.spec --target yarp --deploy "$scratch/bad_port.json" -o "$scratch/out"
# A misspelt port, and a misspelt "topics" (which would otherwise rename nothing, silently).
printf '{"topics": {"HeadControl.gase": "/x"}}' > "$scratch/typo_port.json"
expect 2 "did you mean \"HeadControl.gaze\"?" -- "$arbc" build specs/face_filter.spec --target yarp --deploy "$scratch/typo_port.json" -o "$scratch/out"
printf '{"domain": 3,\n "topic": {"HeadControl.gaze": "/robot/gaze:i"}}' > "$scratch/typo_topics.json"
expect 2 "typo_topics.json:2:2: error: unknown key \"topic\"; did you mean \"topics\"?" -- "$arbc" build specs/face_filter.spec --target yarp --deploy "$scratch/typo_topics.json" -o "$scratch/out"
expect 2 "missing.json: error: cannot read the deployment file (no such file)" -- "$arbc" build specs/face_filter.spec --target yarp --deploy "$scratch/missing.json" -o "$scratch/out"
printf '{"topics": {\n  "HeadControl.gaze": "/a",\n}}' > "$scratch/not_json.json"
expect 2 "not_json.json:3:1: error: not valid JSON: syntax error while parsing object key" -- "$arbc" build specs/face_filter.spec --target yarp --deploy "$scratch/not_json.json" -o "$scratch/out"
# A key given twice: the JSON library would keep the second without a word.
printf '{"topics": {\n  "HeadControl.gaze": "/a",\n  "HeadControl.gaze": "/b"}}' > "$scratch/twice.json"
expect 2 "twice.json:3:3: error: key \"HeadControl.gaze\" repeated in one object (the first is at line 2)" -- "$arbc" build specs/face_filter.spec --target yarp --deploy "$scratch/twice.json" -o "$scratch/out"
printf '{"topics": {"HeadControl.gaze": "no slash"}}' > "$scratch/bad_name.json"
expect 2 "is not a YARP port name" -- "$arbc" build specs/face_filter.spec --target yarp --deploy "$scratch/bad_name.json" -o "$scratch/out"
printf '{"topics": {"HeadControl.gaze": "/a", "FaceDetector.face": "/a"}}' > "$scratch/same.json"
expect 2 "same.json:1:60: error: \"topics\": HeadControl.gaze and FaceDetector.face are both named" -- "$arbc" build specs/face_filter.spec --target yarp --deploy "$scratch/same.json" -o "$scratch/out"
printf '{"topics": {"HeadControl.gaze": "/robot/gaze:i"}}' > "$scratch/good.json"
expect 2 "--deploy is for --target yarp" -- "$arbc" build specs/face_filter.spec --deploy "$scratch/good.json" -o "$scratch/out"
printf '{"topics": {"HeadControl.gaze": "/robot/gaze:i"}}' > "$scratch/good.json"
expect 0 "(YARP)" -- "$arbc" build specs/face_filter.spec --target yarp --deploy "$scratch/good.json" -o "$scratch/deployed"
grep -q '<to>/robot/gaze:i</to>' "$scratch/deployed/face_filter/face_filter.xml" || fail "--deploy did not name /robot/gaze:i"
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
# A refuted proof writes nothing (exit 1), unless --no-verify.
cat > "$scratch/overlap.spec" <<'SPEC'
app overlap;
module A { out x: float; }
module B { out y: float; }
module H { in z: float; }
event busy;
arbitrate H.z {
  first:  from A.x when busy;
  second: from B.y when busy;
}
SPEC
expect 1 "nothing was written" -- "$arbc" build "$scratch/overlap.spec" -o "$scratch/refuted"
[ ! -e "$scratch/refuted" ] || fail "a refuted build wrote $scratch/refuted"
expect 0 "not verified (--no-verify)" -- "$arbc" build "$scratch/overlap.spec" -o "$scratch/refuted" --no-verify
[ -f "$scratch/refuted/overlap/app.json" ] || fail "--no-verify did not write the build"
echo "ok"
