#!/usr/bin/env bash
# check_yarp_directory.sh ARBC SCRATCH: a directory written by `arbc build --target yarp` is one
# `arbc verify DIR` proves (its application XML) and `arbc run DIR` explains, and a folder that
# holds a yarpmanager application gets the XML to give, not "cannot read DIR/app.json".
set -uo pipefail
arbc=$1 scratch=$2
rm -rf "$scratch" && mkdir -p "$scratch"
fail() { echo "FAIL: $*"; exit 1; }
"$arbc" build specs/face_filter.spec --target yarp -o "$scratch" > /dev/null || fail "build"
out=$("$arbc" verify "$scratch/face_filter" 2>&1); rc=$?
[ "$rc" -eq 0 ] || fail "verify of the YARP build exited $rc: $out"
[[ "$out" == *"face_filter ($scratch/face_filter/face_filter.xml):"* ]] || fail "verify did not prove the XML: $out"
out=$("$arbc" run "$scratch/face_filter" --stub --duration 1s 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "run of the YARP build exited $rc: $out"
[[ "$out" == *"a build for YARP (arbc build --target yarp), which runs on YARP"* ]] || fail "run did not say why: $out"
out=$("$arbc" verify tests/yarp_verify/ball_line 2>&1); rc=$?
[ "$rc" -eq 2 ] || fail "verify of a folder with an XML exited $rc: $out"
[[ "$out" == *"give the yarpmanager application XML itself (arbc verify tests/yarp_verify/ball_line/ball_line.xml)"* ]] || fail "verify did not name the XML: $out"
echo ok
