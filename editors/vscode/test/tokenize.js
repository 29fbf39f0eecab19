// Tokenizes arbc specs with the extension's TextMate grammar, as VS Code does: vscode-textmate
// with the Oniguruma regex engine compiled to WebAssembly (vscode-oniguruma).
"use strict";
const fs = require("fs");
const path = require("path");
const oniguruma = require("vscode-oniguruma");
const textmate = require("vscode-textmate");

const here = path.dirname(__dirname);

async function loadGrammar() {
  const wasm = fs.readFileSync(require.resolve("vscode-oniguruma/release/onig.wasm"));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new textmate.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (s) => new oniguruma.OnigString(s),
    }),
    loadGrammar: async (scopeName) => {
      if (scopeName !== "source.arbc") return null;
      const file = path.join(here, "syntaxes", "arbc.tmLanguage.json");
      return textmate.parseRawGrammar(fs.readFileSync(file, "utf8"), file);
    },
  });
  return registry.loadGrammar("source.arbc");
}

// [{line, text, scopes}] for every token, and whether the last line ends at the top level
// (no string or block comment left open).
function tokenize(grammar, text) {
  const tokens = [];
  let stack = textmate.INITIAL;
  const lines = text.split(/\r?\n/);
  lines.forEach((line, i) => {
    const r = grammar.tokenizeLine(line, stack);
    for (const t of r.tokens) {
      tokens.push({ line: i + 1, text: line.slice(t.startIndex, t.endIndex), scopes: t.scopes });
    }
    stack = r.ruleStack;
  });
  return { tokens, closed: stack.depth === 1 };
}

// One line per token that is not whitespace: `line  text  scopes` (the base scope left out).
function render(tokens) {
  return tokens
    .filter((t) => t.text.trim() !== "")
    .map((t) => `${t.line}\t${t.text}\t${t.scopes.slice(1).join(" ")}`)
    .join("\n") + "\n";
}

module.exports = { loadGrammar, tokenize, render };

if (require.main === module) {  // node tokenize.js FILE: print its tokens
  loadGrammar().then((g) => {
    process.stdout.write(render(tokenize(g, fs.readFileSync(process.argv[2], "utf8")).tokens));
  });
}
