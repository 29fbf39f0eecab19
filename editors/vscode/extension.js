// The VS Code extension: starts `arbc lsp` for .spec files (docs/editors.md#vs-code).
// Highlighting needs no code: package.json contributes the TextMate grammar.
"use strict";
const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const config = vscode.workspace.getConfiguration("arbc");
  const args = ["lsp"];
  if (!config.get("verifyOnSave", true)) args.push("--no-verify");
  const server = { command: config.get("path", "arbc"), args };
  client = new LanguageClient("arbc", "arbc", { run: server, debug: server }, {
    documentSelector: [{ scheme: "file", language: "arbc" }, { scheme: "untitled", language: "arbc" }],
  });
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
