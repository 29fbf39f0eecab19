#!/bin/sh
# scripts/package-vscode.sh makes a .vsix holding the extension, its grammar and the language
# client it starts `arbc lsp` with. Skipped (77) without Node or the npm packages.
# usage: vscode_package_test.sh OUT_DIR   (from the repository root)
set -eu
if ! command -v node >/dev/null 2>&1 || [ ! -x editors/vscode/node_modules/.bin/vsce ]; then
  echo "SKIPPED: node or editors/vscode/node_modules is missing (run scripts/install-deps.sh --test)"
  exit 77
fi
out=$1/arbc.vsix
rm -f "$out"
scripts/package-vscode.sh "$out" >/dev/null
listing=$(python3 -c 'import sys, zipfile; print("\n".join(zipfile.ZipFile(sys.argv[1]).namelist()))' "$out")
for f in extension/package.json extension/extension.js extension/syntaxes/arbc.tmLanguage.json \
         extension/language-configuration.json \
         extension/node_modules/vscode-languageclient/node.js; do
  echo "$listing" | grep -qx "$f" || { echo "FAIL: $out lacks $f"; exit 1; }
done
if echo "$listing" | grep -q "extension/test/\|vscode-textmate\|@vscode/vsce"; then
  echo "FAIL: $out holds test files or development packages"; exit 1
fi
echo "1 passed, 0 failed"
