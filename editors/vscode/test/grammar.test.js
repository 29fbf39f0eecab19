// The TextMate grammar on every spec of the repository, and the exact scopes of a golden
// sample. Run by ctest (tests/lsp) with ARBC_ROOT set to the repository; UPDATE=1 rewrites the
// golden file (review the diff by eye).
"use strict";
const assert = require("node:assert");
const fs = require("fs");
const path = require("path");
const test = require("node:test");
const { loadGrammar, tokenize, render } = require("./tokenize");

const root = process.env.ARBC_ROOT || path.resolve(__dirname, "../../..");
const golden = path.join(__dirname, "golden", "table_clean.tokens");

function specs(dir, out = []) {
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    if (entry.name.startsWith(".") || entry.name === "node_modules" || entry.name.startsWith("build"))
      continue;
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) specs(full, out);
    else if (entry.name.endsWith(".spec")) out.push(full);
  }
  return out;
}

test("every spec in the repository tokenizes and ends at the top level", async () => {
  const grammar = await loadGrammar();
  const files = specs(root);
  assert.ok(files.length >= 100, `only ${files.length} specs found under ${root}`);
  for (const file of files) {
    const text = fs.readFileSync(file, "utf8");
    const { tokens, closed } = tokenize(grammar, text);
    // Specs that end inside a string or comment on purpose say so in their name.
    if (!/unterminated/.test(file)) assert.ok(closed, `${file} ends inside a string or comment`);
    for (const t of tokens) {
      const inComment = t.scopes.some((s) => s.startsWith("comment"));
      const inString = t.scopes.some((s) => s.startsWith("string"));
      if (!inComment && !inString && t.text.includes("//"))
        assert.fail(`${file}:${t.line}: '//' outside a comment: ${JSON.stringify(t)}`);
    }
  }
});

test("the golden sample's scopes", async () => {
  const grammar = await loadGrammar();
  const text = fs.readFileSync(path.join(root, "specs", "table_clean.spec"), "utf8");
  const actual = render(tokenize(grammar, text).tokens);
  if (process.env.UPDATE === "1" || process.env.ARBC_UPDATE_GOLDEN) fs.writeFileSync(golden, actual);
  assert.strictEqual(actual, fs.readFileSync(golden, "utf8"));
});

test("keywords, names, durations, strings and comments get their scopes", async () => {
  const grammar = await loadGrammar();
  const { tokens } = tokenize(grammar,
    'arbitrate Speak.text by priority {\n  ask: from Face.face when not e_x hold 1s then set e_y { emit "hi\\n"; } // c\n}\n/* a\n b */');
  const scope = (text) => tokens.find((t) => t.text === text).scopes.slice(1).join(" ");
  assert.strictEqual(scope("arbitrate"), "keyword.declaration.arbc");
  assert.strictEqual(scope("Speak"), "entity.name.type.module.arbc");
  assert.strictEqual(scope("text"), "variable.other.member.port.arbc");
  assert.strictEqual(scope("ask"), "entity.name.function.rule.arbc");
  assert.strictEqual(scope("not"), "keyword.operator.logical.arbc");
  assert.strictEqual(scope("then"), "keyword.other.arbc");
  assert.strictEqual(scope("1s"), "constant.numeric.duration.arbc");
  assert.strictEqual(scope("\\n"), "string.quoted.double.arbc constant.character.escape.arbc");
  assert.strictEqual(scope("// c"), "comment.line.double-slash.arbc");
  assert.strictEqual(scope(" b "), "comment.block.arbc");
});

test("test declarations: keywords, the rule, the arrow and the window", async () => {
  const grammar = await loadGrammar();
  const { tokens } = tokenize(grammar,
    'tests for "gaze.spec";\ntest "t" on track {\n  at 0s Face.face <- { certainty: 0.9 };\n' +
    '  expect search drops "not-selected" within 1s..2s;\n  expect Head.gaze receives nothing;\n}\n');
  const scope = (text, n = 0) =>
    tokens.filter((t) => t.text === text)[n].scopes.slice(1).join(" ");
  assert.strictEqual(scope("tests"), "keyword.declaration.arbc");
  assert.strictEqual(scope("for"), "keyword.other.arbc");
  assert.strictEqual(scope("test"), "keyword.declaration.arbc");
  assert.strictEqual(scope("on"), "keyword.other.arbc");
  assert.strictEqual(scope("track"), "entity.name.function.rule.arbc");
  assert.strictEqual(scope("at"), "keyword.control.test.arbc");
  assert.strictEqual(scope("<-"), "keyword.operator.arrow.arbc");
  assert.strictEqual(scope("expect"), "keyword.control.test.arbc");
  assert.strictEqual(scope("search"), "entity.name.function.rule.arbc");
  assert.strictEqual(scope("drops"), "keyword.control.test.arbc");
  assert.strictEqual(scope("within"), "keyword.control.test.arbc");
  assert.strictEqual(scope(".."), "punctuation.separator.range.arbc");
  assert.strictEqual(scope("2s"), "constant.numeric.duration.arbc");
  assert.strictEqual(scope("receives"), "keyword.control.test.arbc");
  assert.strictEqual(scope("nothing"), "keyword.control.test.arbc");
});

test("properties over time and environment assumptions", async () => {
  const grammar = await loadGrammar();
  const { tokens } = tokenize(grammar,
    "assume not e_arm_idle for 1s after take;\nassume e_taken only after take until put;\n" +
    "never search within 1s after track;\nnever two ask within 5s;\n");
  const scope = (text, n = 0) =>
    tokens.filter((t) => t.text === text)[n].scopes.slice(1).join(" ");
  assert.strictEqual(scope("assume"), "keyword.declaration.arbc");
  assert.strictEqual(scope("not"), "keyword.operator.logical.arbc");
  assert.strictEqual(scope("for"), "keyword.other.arbc");
  assert.strictEqual(scope("1s"), "constant.numeric.duration.arbc");
  assert.strictEqual(scope("only"), "keyword.declaration.arbc");
  assert.strictEqual(scope("until"), "keyword.control.test.arbc");
  assert.strictEqual(scope("never"), "keyword.declaration.arbc");
  assert.strictEqual(scope("within"), "keyword.control.test.arbc");
  assert.strictEqual(scope("two"), "keyword.control.test.arbc");
});
