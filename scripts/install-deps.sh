#!/usr/bin/env bash
# Installs the Debian 12 packages arbc needs, only those missing; safe to run twice.
# Usage: scripts/install-deps.sh [--test | --bench]
#   --test adds what only the test suite needs, --bench what only bench/run needs
set -euo pipefail

packages=(
  build-essential cmake pkg-config ccache git
  antlr4 libantlr4-runtime-dev uuid-dev      # grammar tool + C++ runtime (its cmake targets link -luuid)
  liblua5.4-dev lua5.4                       # monitors; lua5.4 gives luac5.4 for `luac -p` checks
  libz3-dev                                  # the proof
  nettle-dev                                 # SHA-256 of monitors and app.json (core/sha256.h)
  libeigen3-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libtinyxml2-dev                            # arbc verify APP.xml: yarpmanager applications
  libyaml-cpp-dev                            # arbc import twist_mux: its parameter files
  graphviz                                   # arbc docs: app.svg
  libfastrtps-dev libfastcdr-dev fastddsgen  # arbc_dds: the distributed runtime (Fast-DDS 2.9)
)
if [[ "${1:-}" == "--bench" ]]; then
  packages+=(valgrind)                       # bench/figures/instructions.sh: callgrind's counts
fi
if [[ "${1:-}" == "--test" ]]; then
  packages+=(clang libclang-rt-14-dev python3 python3-jsonschema
             libxml2-utils                   # tests/artifacts: xmllint reads the XML and SVG arbc writes
             clang-format                    # tests/code_shape: code_format (scripts/format.sh)
             chromium                        # tests/report: the run report in headless Chromium
             neovim tmux                     # tests/lsp: Neovim's LSP client in a terminal
             iproute2)                       # tests/dds: two hosts as network namespaces (ip netns)
  # tests/lsp: the VS Code grammar test runs on Node. A Node.js from elsewhere (with its own
  # npm) is kept: Debian's npm package would conflict with it.
  command -v node >/dev/null || packages+=(nodejs)
  command -v npm >/dev/null || packages+=(npm)
fi

# The npm packages of editors/vscode (vscode-textmate and vscode-oniguruma for the grammar
# test, vsce to package the extension), exactly as package-lock.json pins them; again only
# when the lock file changed. Without the registry the grammar test is skipped, not failed.
npm_packages() {
  local dir=$root/editors/vscode
  [[ -f $dir/node_modules/.arbc-lock ]] && cmp -s "$dir/package-lock.json" "$dir/node_modules/.arbc-lock" &&
    return 0
  echo "install-deps: npm ci in editors/vscode"
  if (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error); then
    cp "$dir/package-lock.json" "$dir/node_modules/.arbc-lock"
  else
    echo "install-deps: npm ci failed; the VS Code grammar test will be skipped" >&2
  fi
}
# The official SARIF 2.1.0 JSON schema for tests/artifacts/sarif_official.py: the npm registry
# carries it inside @microsoft/jest-sarif; only the schema is kept, checked by its SHA-256.
# Without the registry that test is skipped, not failed.
sarif_schema() {
  local dir=$root/tests/artifacts/official file=sarif-2.1.0-rtm.5.json tmp
  local sum=2d99159ae54a3eea97f81781cff48780548657c35949f4b7f25e99a2ba4de4f8
  [[ -f $dir/$file ]] && echo "$sum  $dir/$file" | sha256sum -c --status && return 0
  echo "install-deps: the official SARIF schema (npm: @microsoft/jest-sarif)"
  tmp=$(mktemp -d)
  if (cd "$tmp" && npm pack --silent @microsoft/jest-sarif@1.0.0-beta.0 >/dev/null &&
    tar xzf ./*.tgz "package/lib/schemas/$file") &&
    echo "$sum  $tmp/package/lib/schemas/$file" | sha256sum -c --status; then
    mkdir -p "$dir" && cp "$tmp/package/lib/schemas/$file" "$dir/"
  else
    echo "install-deps: could not fetch the official SARIF schema; its test will be skipped" >&2
  fi
  rm -rf "$tmp"
}
root=$(cd "$(dirname "$0")/.." && pwd)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt_prefix=()
  [[ $(id -u) -ne 0 ]] && apt_prefix=(sudo)
  "${apt_prefix[@]}" apt-get update -qq
  "${apt_prefix[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [[ "${1:-}" == "--test" ]]; then
  npm_packages
  sarif_schema
fi
