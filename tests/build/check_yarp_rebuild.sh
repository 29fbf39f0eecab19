#!/usr/bin/env bash
# check_yarp_rebuild.sh ARBC SCRATCH: a rebuild with --target yarp keeps the <module>s the user
# filled in (docs/yarp.md#deploying-a-spec-on-yarp-step-by-step, step 3) and says so, while the
# placeholders of modules left alone stay as generated; one the spec no longer has is reported.
set -uo pipefail
arbc=$1 scratch=$2
rm -rf "$scratch" && mkdir -p "$scratch"
fail() { echo "FAIL: $*"; exit 1; }
"$arbc" build specs/search_and_track.spec --target yarp -o "$scratch" > /dev/null || fail "first build"
xml=$scratch/search_and_track/search_and_track.xml
python3 - "$xml" <<'PY' || fail "the placeholder of LookAround is not where expected"
import sys
p = sys.argv[1]
s = open(p).read()
old = "<module>\n    <name>LookAround</name>\n    <parameters></parameters>\n    <node>localhost</node>\n  </module>"
new = "<module>\n    <name>lookAround</name>\n    <parameters>--period 0.2</parameters>\n    <node>icub-head</node>\n  </module>"
if old not in s:
    sys.exit(1)
open(p, "w").write(s.replace(old, new))
PY
out=$("$arbc" build specs/search_and_track.spec --target yarp -o "$scratch") || fail "rebuild: $out"
[[ "$out" == *"kept the <module>s you filled in for LookAround from the search_and_track.xml it replaced"* ]] || fail "the rebuild did not say what it kept: $out"
grep -q '<parameters>--period 0.2</parameters>' "$xml" || fail "the rebuild lost the filled-in module: $(cat "$xml")"
grep -q '<node>icub-head</node>' "$xml" || fail "the rebuild lost the node"
grep -q '<name>HeadControl</name>' "$xml" || fail "a placeholder left alone changed"
# The application still reads back and proves.
"$arbc" verify "$xml" > /dev/null || fail "the rebuilt application does not verify"
# A filled-in module the spec no longer has is not carried over, and the build says so.
sed 's/module LookAround /module Explorer /; s/LookAround\.gaze/Explorer.gaze/g' \
  specs/search_and_track.spec > "$scratch/search_and_track.spec"
err=$("$arbc" build "$scratch/search_and_track.spec" --target yarp -o "$scratch" 2>&1 >/dev/null) || fail "rebuild without LookAround: $err"
[[ "$err" == *"the replaced search_and_track.xml had <module>s filled in for LookAround, which the spec no longer has"* ]] || fail "the drop was not said: $err"
echo ok
