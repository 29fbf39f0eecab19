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
