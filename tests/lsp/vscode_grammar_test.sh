#!/bin/sh
# The VS Code grammar test (editors/vscode/test/grammar.test.js) under Node's test runner.
# Skipped (77) when Node or the npm packages are absent: scripts/install-deps.sh --test runs
# `npm ci` in editors/vscode.
if ! command -v node >/dev/null 2>&1; then
  echo "SKIPPED: node is not installed"; exit 77
fi
for p in vscode-textmate vscode-oniguruma; do
  if [ ! -d "node_modules/$p" ]; then
    echo "SKIPPED: node_modules/$p is missing (run scripts/install-deps.sh --test)"; exit 77
  fi
done
exec node --test test/grammar.test.js
