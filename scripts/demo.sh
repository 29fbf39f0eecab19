#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job (README's first command).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
arbc="${ARBC_BUILD_DIR:-$root/build}/cli/arbc"
cd "$root"
echo "== arbc check specs/*.spec"
"$arbc" check specs/*.spec
echo "== arbc verify specs/*.spec"
"$arbc" verify specs/*.spec
build="${ARBC_BUILD_DIR:-$root/build}"
echo "== arbc build specs/table_clean.spec -o out   (compile, prove, write the monitors)"
"$arbc" build specs/table_clean.spec -o out
echo "== arbc run out/table_clean --scenario mixed --report ...   (the paper's experiment, simulated)"
"$arbc" run out/table_clean --plugin "$build/examples/table_clean/libarbc_table_clean.so" \
  --scenario mixed --seed 1 --duration 120s --report out/table_clean-report.html
echo "== arbc docs specs/table_clean.spec -o out/table_clean-docs   (tables, decision tables, diagram)"
"$arbc" docs specs/table_clean.spec -o out/table_clean-docs
