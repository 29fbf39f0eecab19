#!/usr/bin/env bash
# check_yarp_build.sh ARBC LUAC SPEC APP SCRATCH [GOLDEN]: `arbc build --target yarp` twice;
# byte-identical output, the XML well-formed (xmllint and Python's parser), every monitor
# compiles with luac5.4 and loads YARP's bindings, every monitor the XML names exists,
# `arbc verify APP.xml` (the YARP importer) proves the generated application, and with GOLDEN
# the files match the reviewed ones there (ARBC_UPDATE_GOLDEN=1 rewrites them).
# docs/yarp.md#deploying-a-spec-on-yarp-step-by-step
set -euo pipefail
arbc=$1 luac=$2 spec=$3 app=$4 scratch=$5 golden=${6:-}
rm -rf "$scratch" && mkdir -p "$scratch"
"$arbc" build "$spec" --target yarp -o "$scratch/a" > "$scratch/summary.txt"
"$arbc" build "$spec" --target yarp -o "$scratch/b" > /dev/null
diff -r "$scratch/a/$app" "$scratch/b/$app" || { echo "FAIL: two builds differ"; exit 1; }
out=$scratch/a/$app
[ -f "$out/$app.xml" ] || { echo "FAIL: no $app.xml"; exit 1; }
# Well-formed XML for any reader, not only YARP's tolerant one (a comment holding "--" was not).
xmllint --noout "$out/$app.xml" || { echo "FAIL: xmllint refuses $app.xml"; exit 1; }
python3 -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' "$out/$app.xml" ||
  { echo "FAIL: Python's XML parser refuses $app.xml"; exit 1; }
count=0
for f in "$out"/contexts/"$app"/*.lua; do
  "$luac" -p "$f" || { echo "FAIL: luac5.4 -p rejects $f"; exit 1; }
  grep -q '^require("yarp")$' "$f" || { echo "FAIL: $f does not require yarp"; exit 1; }
  if grep -q 'setTrigInterval' "$f"; then echo "FAIL: $f calls setTrigInterval"; exit 1; fi
  count=$((count + 1))
done
# Every file.NAME of a carrier is a monitor that was written, and nothing else was.
named=$(grep -o 'file\.[A-Za-z0-9_]*' "$out/$app.xml" | sort -u | wc -l)
[ "$named" -eq "$count" ] || { echo "FAIL: the XML names $named monitors, $count written"; exit 1; }
# The YARP importer proves what was generated (exit 0; the verdict is printed on failure).
if ! "$arbc" verify "$out/$app.xml" > "$scratch/verify.txt" 2>&1; then
  cat "$scratch/verify.txt"; echo "FAIL: arbc verify $app.xml does not prove it"; exit 1
fi
if [ -n "$golden" ]; then
  sed "s|$scratch/a|OUT|" "$scratch/summary.txt" > "$out/summary.txt"
  if [ "${ARBC_UPDATE_GOLDEN:-0}" = 1 ]; then
    rm -rf "$golden" && mkdir -p "$golden" && cp -r "$out/." "$golden/"
    echo "updated $golden"
  fi
  diff -r "$golden" "$out" || { echo "FAIL: the YARP build differs from $golden"; exit 1; }
fi
echo "ok: $count YARP monitors, luac clean, deterministic, arbc verify proves $app.xml"
