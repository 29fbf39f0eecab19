#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (README's second command).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh" --test
"$root/scripts/build.sh"
cd "${ARBC_BUILD_DIR:-$root/build}"
ctest --output-on-failure -j"$(nproc)"
