#!/usr/bin/env bash
# Installs the Debian 12 packages arbc needs, only those missing; safe to run twice.
# Usage: scripts/install-deps.sh [--test]   (--test adds what only the test suite needs)
set -euo pipefail

packages=(
  build-essential cmake pkg-config ccache git
  antlr4 libantlr4-runtime-dev uuid-dev      # grammar tool + C++ runtime (its cmake targets link -luuid)
  liblua5.4-dev lua5.4                       # monitors; lua5.4 gives luac5.4 for `luac -p` checks
  libz3-dev                                  # the proof
  libeigen3-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libtinyxml2-dev                            # arbc verify APP.xml: yarpmanager applications
  graphviz                                   # arbc docs: app.svg
)
if [[ "${1:-}" == "--test" ]]; then
  packages+=(clang libclang-rt-14-dev python3 python3-jsonschema
             chromium)                       # tests/report: the run report in headless Chromium
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt_prefix=()
[[ $(id -u) -ne 0 ]] && apt_prefix=(sudo)
"${apt_prefix[@]}" apt-get update -qq
"${apt_prefix[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
