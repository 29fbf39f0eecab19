#!/usr/bin/env bash
# check_build.sh ARBC LUAC SPEC APP SCRATCH: builds SPEC twice, checks the monitors with luac,
# byte-identical output, and the goldens in tests/build/APP/ (ARBC_UPDATE_GOLDEN=1 rewrites them).
set -euo pipefail
arbc=$1 luac=$2 spec=$3 app=$4 scratch=$5
golden=tests/build/$app
rm -rf "$scratch" && mkdir -p "$scratch"
"$arbc" build "$spec" -o "$scratch/a" > "$scratch/summary.txt"
"$arbc" build "$spec" -o "$scratch/b" > /dev/null
diff -r "$scratch/a/$app" "$scratch/b/$app" || { echo "FAIL: two builds differ"; exit 1; }
count=0
for f in "$scratch/a/$app"/monitors/*.lua; do
  "$luac" -p "$f" || { echo "FAIL: luac5.4 -p rejects $f"; exit 1; }
  count=$((count + 1))
done
connections=$(grep -c '"monitor": "monitors/' "$scratch/a/$app/app.json")
[ "$count" -eq "$connections" ] || { echo "FAIL: $count monitors for $connections connections"; exit 1; }
if [ "$count" -lt "${ARBC_MIN_MONITORS:-1}" ]; then
  echo "FAIL: $count monitors, expected at least ${ARBC_MIN_MONITORS}"; exit 1
fi
# app.json follows docs/app.schema.json (python3-jsonschema: scripts/install-deps.sh --test).
if ! python3 -c "import jsonschema" 2>/dev/null; then
  echo "FAIL: python3 has no jsonschema module; run scripts/install-deps.sh --test"; exit 1
fi
python3 - "$scratch/a/$app/app.json" docs/app.schema.json <<'PY' || { echo "FAIL: app.json does not follow docs/app.schema.json"; exit 1; }
import json, sys, jsonschema
jsonschema.Draft202012Validator(json.load(open(sys.argv[2]))).validate(json.load(open(sys.argv[1])))
PY
# The proof is recorded for app.json's bytes (verify/proof_record.h); the record names the arbc
# binary, so it is checked here and left out of the golden.
record=$scratch/a/$app/proof.json
[ -f "$record" ] || { echo "FAIL: no proof.json beside app.json"; exit 1; }
digest=$(sha256sum "$scratch/a/$app/app.json" | cut -d' ' -f1)
grep -q "\"app_json_sha256\": \"$digest\"" "$record" ||
  { echo "FAIL: proof.json is not about this app.json"; cat "$record"; exit 1; }
rm "$record"
# The summary is part of the golden too (minus the output directory).
sed "s|$scratch/a|OUT|" "$scratch/summary.txt" > "$scratch/a/$app/summary.txt"
if [ "${ARBC_UPDATE_GOLDEN:-0}" = 1 ]; then
  rm -rf "$golden" && mkdir -p "$golden" && cp -r "$scratch/a/$app/." "$golden/"
  echo "updated $golden"
fi
diff -r "$golden" "$scratch/a/$app" || { echo "FAIL: artifacts differ from $golden"; exit 1; }
echo "ok: $count monitors, luac clean, deterministic, golden matches"
