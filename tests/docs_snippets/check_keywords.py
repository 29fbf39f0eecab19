#!/usr/bin/env python3
"""docs/language.md lists every keyword of the grammar, and arbc refuses each as a name.

usage: check_keywords.py ARBC        (run from the repository root)

The keywords are the words quoted in the parser rules of grammar/Arbc.g4 (above its lexer
section); the page lists them in the backquoted run after "Keywords cannot be names:". A
keyword missing from the page is a name a reader would try and see refused; a word on the page
that is no keyword is a name they would avoid for nothing. Each keyword, used as a constant's
name, must get arbc check's error that says a keyword cannot be a name (and what to do).
"""
import os
import re
import subprocess
import sys
import tempfile


def grammar_keywords(path):
    text = open(path, encoding="utf-8").read()
    parser_rules = text.split("// ---- Lexer", 1)[0]
    parser_rules = re.sub(r"//[^\n]*", "", parser_rules)
    return {w for w in re.findall(r"'([a-z]+)'", parser_rules)}


def page_keywords(path):
    text = open(path, encoding="utf-8").read()
    m = re.search(r"Keywords cannot be names:\s*`([^`]*)`", text)
    if not m:
        sys.exit(f"{path}: no 'Keywords cannot be names: `...`' list")
    return set(m.group(1).split())


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    arbc = os.path.abspath(sys.argv[1])
    grammar = grammar_keywords("grammar/Arbc.g4")
    page = page_keywords("docs/language.md")
    failures = []
    for w in sorted(grammar - page):
        failures.append(f"docs/language.md: keyword '{w}' of grammar/Arbc.g4 is not listed")
    for w in sorted(page - grammar):
        failures.append(f"docs/language.md: '{w}' is listed as a keyword but the grammar has none")
    with tempfile.TemporaryDirectory(prefix="arbc-keywords-") as tmp:
        for w in sorted(grammar):
            spec = os.path.join(tmp, "k.spec")
            with open(spec, "w", encoding="utf-8") as f:
                f.write(f"app k;\nconst {w} = 1;\n")
            proc = subprocess.run([arbc, "check", "k.spec"], cwd=tmp, capture_output=True,
                                  text=True, timeout=60)
            errors = [line for line in proc.stderr.splitlines() if ": error: " in line]
            want = f"k.spec:2:7: error: expected a name in the constant declaration, found '{w}'"
            if proc.returncode != 2 or len(errors) != 1 or not errors[0].startswith(want) or \
                    "a keyword cannot be used as a name" not in errors[0] or \
                    "choose another name" not in proc.stderr:
                failures.append(f"`const {w} = 1;`: exit {proc.returncode}, one error naming "
                                f"the keyword expected:\n{proc.stderr}")
    for f in failures:
        print("FAIL", f)
    print(f"{len(grammar)} keywords, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
