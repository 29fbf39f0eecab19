#!/usr/bin/env bash
# Packages the VS Code extension (editors/vscode) into a .vsix with @vscode/vsce, the version
# package-lock.json pins. Usage: scripts/package-vscode.sh [OUT.vsix]   (default: build/arbc.vsix)
# Install it with `code --install-extension OUT.vsix`; it starts `arbc lsp` (docs/editors.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-$root/build/arbc.vsix}")
dir=$root/editors/vscode
if [[ ! -x $dir/node_modules/.bin/vsce ]]; then
  (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error)
fi
mkdir -p "$(dirname "$out")"
cd "$dir"
node_modules/.bin/vsce package --allow-missing-repository --skip-license --out "$out"
echo "package-vscode: $out"
