#!/usr/bin/env bash
# check_what_runs.sh ARBC PLUGIN SCRATCH: each case runs arbc as a user would and checks the exit
# code and the message (the file, the connection, what to do).
set -uo pipefail
arbc=$1 plugin=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
# expect NAME CODE PATTERN COMMAND...: COMMAND exits CODE and its output contains PATTERN.
expect() {
  local name=$1 code=$2 pattern=$3
  shift 3
  local out rc
  out=$("$@" 2>&1)
  rc=$?
  [ "$rc" = "$code" ] || fail "$name: exit $rc, expected $code"$'\n'"$out"
  [[ $out == *"$pattern"* ]] || fail "$name: no '$pattern' in"$'\n'"$out"
}
run=(--plugin "$plugin" --scenario appear_and_leave --duration 20s)

# A proved app runs, and says it was proved.
"$arbc" build specs/search_and_track.spec -o "$scratch/ok" > /dev/null || fail "build"
app=$scratch/ok/search_and_track
expect proved-dir-runs 0 "verified: 1 arbitrated port proved exclusive" "$arbc" run "$app" "${run[@]}"
expect proved-dir-verifies 0 "proved" "$arbc" verify "$app"

# The build recorded its proof (proof.json), and `arbc run` of exactly that app.json trusts it
# rather than proving the same bytes again; any change to app.json, or another arbc binary,
# and run proves again.
reused="(by arbc build, for this very app.json)"
expect proved-dir-reuses-build-proof 0 "$reused" "$arbc" run "$app" "${run[@]}"
cp -r "$app" "$scratch/tampered"
sed -i 's|"constraint": "not e_face_detected"|"constraint": "true"|' "$scratch/tampered/app.json"
grep -q '"constraint": "true"' "$scratch/tampered/app.json" || fail "the app.json edit did not apply"
expect app-json-edited-after-build-is-proved-again 1 "arbc run: verification refuted; nothing was run" \
  "$arbc" run "$scratch/tampered" "${run[@]}"
# An app.json whose model of a monitor is not the monitor (right's `must_set` claims an event its
# Lua never sets, which left's constraint excludes) is proved again, and proved; the runtime then
# selects right on what the proof assumed (its effective guard), so the two arms never both
# deliver on one state: right's message is not selected.
"$arbc" build tests/what_runs/gripper.spec -o "$scratch/gripper" > /dev/null || fail "gripper build"
python3 - "$scratch/gripper/gripper/app.json" <<'PY'
import json, sys
path = sys.argv[1]
app = json.load(open(path))
for c in app["connections"]:
    if c["name"] == "right":
        c.update(constraint="true", sets=["e_claimed"], must_set=["e_claimed"])
    if c["name"] == "left":
        c["constraint"] = "e_left_owns and not e_claimed"
json.dump(app, open(path, "w"), indent=2)
PY
cat > "$scratch/gripper.jsonl" <<'LINES'
{"t": 0.0, "port": "Gripper.status", "value": ["e_left_owns"]}
{"t": 0.1, "port": "LeftArm.grip", "value": {"verb": "close", "force": 1.0}}
{"t": 0.1, "port": "RightArm.grip", "value": {"verb": "open", "force": 1.0}}
LINES
out=$("$arbc" run "$scratch/gripper/gripper" --stub --inputs "$scratch/gripper.jsonl" \
  --duration 1s 2>&1) || fail "gripper-run: exit $?"$'\n'"$out"
[[ $out == *"verified: 1 arbitrated port proved exclusive"* ]] ||
  fail "gripper-run: the edited app.json was not proved"$'\n'"$out"
grep -Eq '^right +1 +0 +0 +0 +1 ' <<< "$out" ||
  fail "gripper-run: right delivered though its monitor does not set what app.json says"$'\n'"$out"

cp -r "$app" "$scratch/other_arbc"
sed -i 's|"arbc_build_id": "[0-9a-f]*"|"arbc_build_id": "0000"|' "$scratch/other_arbc/proof.json"
out=$("$arbc" run "$scratch/other_arbc" "${run[@]}" 2>&1) || fail "other-arbc: exit $?"$'\n'"$out"
[[ $out == *"verified: 1 arbitrated port proved exclusive"* && $out != *"$reused"* ]] ||
  fail "other-arbc: a proof recorded by another arbc was trusted or nothing was proved"$'\n'"$out"

# A monitor edited after the build (here: it tries to select every message) is refused.
cp -r "$app" "$scratch/edited"
monitor=$scratch/edited/monitors/HeadControl.gaze__search.lua
printf 'PortMonitor.create = function(o) PortMonitor.setConstraint("true") return true end\n' \
  >> "$monitor"
changed="$monitor: this monitor of connection 'search' is not the one \`arbc build\` wrote"
expect edited-verify 2 "$changed" "$arbc" verify "$scratch/edited"
expect edited-verify-json 2 "$changed" "$arbc" verify "$scratch/edited/app.json"
expect edited-run 2 "$changed" "$arbc" run "$scratch/edited" "${run[@]}"
expect edited-run-says-rebuild 2 "rebuild the app with \`arbc build\`" \
  "$arbc" run "$scratch/edited" "${run[@]}" --no-verify

# A hand-written script that sets another constraint builds and verifies (the proof is about
# app.json's constraint) but does not load: exit 2 naming the
# hand-written file and line (not the generated monitor), the connection, both.
mkdir -p "$scratch/script"
sed 's|  search: from LookAround.gaze when not e_face_detected;|  search: from LookAround.gaze when not e_face_detected { script "search_true.lua"; }|' \
  specs/search_and_track.spec > "$scratch/script/app.spec"
cp tests/what_runs/search_true.lua "$scratch/script/"
grep -q 'search_true.lua' "$scratch/script/app.spec" || fail "the spec edit did not apply"
"$arbc" build "$scratch/script/app.spec" -o "$scratch/script/out" > /dev/null || fail "script build"
expect script-run 2 "search_true.lua:4:" \
  "$arbc" run "$scratch/script/out/search_and_track" "${run[@]}"
expect script-run-names-both 2 \
  "setConstraint: \"true\" would replace the constraint of connection 'search', \"not e_face_detected\"" \
  "$arbc" run "$scratch/script/out/search_and_track" "${run[@]}"

# An app built without the proof, that the proof refutes: `arbc run DIR` proves it and refuses;
# with --no-verify it runs, says so in the output and the report, and conflicts (exit 3) as the
# proof said it would.
sed 's|  search: from LookAround.gaze when not e_face_detected;|  search: from LookAround.gaze;|' \
  specs/search_and_track.spec > "$scratch/refuted.spec"
"$arbc" build "$scratch/refuted.spec" -o "$scratch/refuted" --no-verify > /dev/null ||
  fail "unverified build"
app=$scratch/refuted/search_and_track
[ ! -e "$app/proof.json" ] || fail "a build with --no-verify recorded a proof"
expect refuted-run 1 "arbc run: verification refuted; nothing was run" "$arbc" run "$app" "${run[@]}"
expect refuted-run-no-verify-output 3 "not verified (--no-verify)" \
  "$arbc" run "$app" "${run[@]}" --no-verify --report "$scratch/report.html"
grep -q 'id="proof" class="bad">not verified (--no-verify)<' "$scratch/report.html" ||
  fail "the report does not say the run was not verified"

[ "$failed" = 0 ] && echo "ok: every case"
exit $failed
