#!/bin/sh
# `arbc import yarp` writes each `script` path relative to the written spec's folder
# (docs/yarp.md#moving-to-a-spec), however the XML and -o are given, so the spec and its monitors
# can be committed and moved together, and the spec checks, verifies and builds from any working
# directory.
# usage: import_elsewhere.sh ARBC CASE_DIR SCRATCH   (CASE_DIR: tests/yarp_verify/ball_line)
set -u
arbc=$1 case=$2 scratch=$3
name=$(basename "$case")
fail() { echo "FAIL: $*"; exit 1; }

rm -rf "$scratch" && mkdir -p "$scratch/a/app" "$scratch/a/spec" || exit 1
cp -L "$case"/*.xml "$case"/*.lua "$scratch/a/app/" || exit 1

# An absolute XML into a relative -o in another folder, and a relative XML into an absolute -o.
(cd "$scratch/a" && "$arbc" import yarp "$scratch/a/app/$name.xml" -o "spec/$name.spec") ||
  fail "import with an absolute XML path"
(cd "$scratch/a/app" && "$arbc" import yarp "$name.xml" -o "$scratch/a/spec/${name}_2.spec") ||
  fail "import with an absolute -o"
for spec in "$scratch/a/spec/$name.spec" "$scratch/a/spec/${name}_2.spec"; do
  grep 'script ' "$spec"
  grep -q 'script "/' "$spec" && fail "$spec has an absolute script path"
  grep -q "script \"../app/selector.lua\"" "$spec" || fail "$spec: script not relative to its folder"
done

# Moved together, used from another working directory.
mv "$scratch/a" "$scratch/moved" || exit 1
cd / || exit 1
for spec in "$scratch/moved/spec/$name.spec" "$scratch/moved/spec/${name}_2.spec"; do
  "$arbc" check "$spec" || fail "arbc check $spec from /"
  "$arbc" verify "$spec" >/dev/null || fail "arbc verify $spec from /"
done
"$arbc" build "$scratch/moved/spec/$name.spec" -o "$scratch/out" >/dev/null ||
  fail "arbc build from /"
echo "ok"
