#!/usr/bin/env python3
"""Runs every spec snippet of a documentation page through arbc (issue 9).

usage: check_snippets.py ARBC PAGE.md [--base SPEC]      (run from the repository root)

Every fenced block tagged ```spec in PAGE is a snippet. Other fenced blocks must carry a tag
too (```text, ```lua, ```sh, ...): an untagged block fails the test, so that no spec snippet
escapes it by mistake.

A snippet is a *fragment* of the base spec (default specs/table_clean.spec): it is spliced into
the base, replacing every base declaration that declares one of the same names, and the result
is checked. A declaration "declares" its kind and name: `app`, `type N`, `const N`, `module N`,
each event of `event a, b` / `event e = ...` / `events from M.p { a, b }`, `resource N`, the
destination port of `arbitrate M.p` or `connect X.q -> M.p`, and `test "NAME"`. An `assert M.p: ...` of the base goes with its
port: it is dropped when the snippet replaces `M.p`; the base's tests are dropped unless the
snippet is a test itself; its properties over time, assumptions and rates are dropped when the
snippet replaces a port or states any of those itself. The snippet takes the place of the first
declaration it replaces (so line numbers stay near the base's), or goes at the end.

An HTML comment on the last non-blank line before the fence changes what is done:

    <!-- snippet: whole -->                   the block is a whole spec: checked alone
    <!-- snippet: expect=unknown-event -->    `arbc check` must fail with exactly these ids
    <!-- snippet: verify expect=dead,unused --> `arbc check` passes, then `arbc verify --format
                                              json` reports exactly these check ids (none: proved)
    <!-- snippet: output ... -->              also: the next fenced block (```text) is what
                                              `arbc check` (or, with `verify`, `arbc verify`)
                                              prints on the spliced spec, saved as BASENAME in
                                              a temporary folder: stdout then stderr, byte for
                                              byte

Without a comment the snippet must pass `arbc check` with no diagnostic at all.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from markdown_blocks import fenced_blocks  # noqa: E402


def snippet_blocks(text):
    """fenced_blocks with only `<!-- snippet: ... -->` comments kept, as their text after the
    colon."""
    for line, tag, body, note, end in fenced_blocks(text):
        if note is not None and note.startswith("snippet:"):
            note = note[len("snippet:"):].strip()
        else:
            note = None
        yield line, tag, body, note, end


def split_declarations(text):
    """Splits spec text into top-level declarations: (text, start offset) pairs. A declaration
    ends at a `;` outside braces, or at the `}` closing a module, arbitrate or connect body.
    Comments and strings are skipped; the text between declarations (comments, blank lines)
    is attached to the declaration that follows."""
    decls, depth, i, start = [], 0, 0, 0
    n = len(text)
    first_word = None
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            i = text.find("\n", i)
            i = n if i < 0 else i
            continue
        if text.startswith("/*", i):
            i = text.find("*/", i + 2)
            i = n if i < 0 else i + 2
            continue
        if c == '"':
            i += 1
            while i < n and text[i] != '"':
                i += 2 if text[i] == "\\" else 1
            i += 1
            continue
        if first_word is None and (c.isalpha() or c == "_"):
            m = re.match(r"[A-Za-z_]\w*", text[i:])
            first_word = m.group(0)
            i += len(first_word)
            continue
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0 and first_word in ("module", "arbitrate", "connect", "test"):
                # `connect A.b -> C.d { ... }` and bodies end here, unless a `;` follows.
                rest = text[i + 1:].lstrip(" \t")
                if not rest.startswith(";"):
                    decls.append((text[start:i + 1], start))
                    start, first_word = i + 1, None
        elif c == ";" and depth == 0:
            decls.append((text[start:i + 1], start))
            start, first_word = i + 1, None
        i += 1
    tail = text[start:]
    return decls, tail


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r'"(\\.|[^"\\])*"', '""', text)
    return re.sub(r"//[^\n]*", "", text)


# Properties over time, assumptions and rates: they speak of rules and sources across ports.
TEMPORAL = ("never", "only", "after", "stable", "assume", "given")


def declared_keys(decl):
    """The names a declaration declares (see the module comment), and the port an assert
    belongs to."""
    code = strip_comments(decl).strip()
    words = code.split()
    if not words:
        return set(), None
    kind = words[0]
    if kind == "app":
        return {"app"}, None
    if kind in ("type", "const", "module"):
        return {f"{kind}:{words[1]}"}, None
    if kind == "resource":
        return {f"resource:{words[1]}"}, None
    if kind == "events":
        m = re.match(r"events\s+from\s+([\w.]+)\s*\{(.*?)\}", code, re.S)
        names = [part.split("=")[0].strip() for part in m.group(2).split(",") if part.strip()]
        return {f"event:{n}" for n in names}, None
    if kind == "event":
        head = code[len("event"):].split("=")[0]
        head = re.sub(r"\blifetime\b.*", "", head, flags=re.S).rstrip(";")
        return {f"event:{n.strip()}" for n in head.split(",") if n.strip()}, None
    if kind == "arbitrate":
        return {f"port:{words[1]}"}, None
    if kind == "connect":
        m = re.match(r"connect\s+[\w.]+\s*->\s*([\w.]+)", code)
        return {f"port:{m.group(1)}"}, None
    if kind == "test":  # by its name, which strip_comments blanked
        m = re.search(r'\btest\s+"((?:\\.|[^"\\])*)"', re.sub(r"//[^\n]*", "", decl))
        return {f"test:{m.group(1)}"} if m else set(), None
    if kind == "assert":
        m = re.match(r"assert\s+([\w.]+)\s*:", code)
        return set(), f"port:{m.group(1)}" if m else None
    if kind in TEMPORAL:
        return {"temporal"}, None
    return set(), None


def code_offset(decl):
    """Where the declaration's code starts, after blank space and comments."""
    i = 0
    while True:
        m = re.match(r"\s*(//[^\n]*|/\*.*?\*/)", decl[i:], re.S)
        if not m:
            break
        i += m.end()
    return i + len(decl[i:]) - len(decl[i:].lstrip())


def splice(base, snippet):
    """The base spec with the snippet in place of the declarations it replaces."""
    snippet_decls, _ = split_declarations(snippet)
    replaced = set()
    for decl, _ in snippet_decls:
        replaced |= declared_keys(decl)[0]
    base_decls, tail = split_declarations(base)
    # The base's tests speak of the base's rules: a snippet that is not a test drops them. Its
    # properties over time, assumptions and rates go when the snippet replaces a port (whose
    # rules they may name) or brings its own.
    drop_tests = not any(k.startswith("test:") for k in replaced)
    drop_temporal = any(k.startswith("port:") or k == "temporal" for k in replaced)
    out, placed = [], False
    for decl, _ in base_decls:
        keys, owner = declared_keys(decl)
        if (drop_tests and any(k.startswith("test:") for k in keys)) or \
                (drop_temporal and "temporal" in keys):
            out.append(decl[:code_offset(decl)])
            continue
        if (keys - {"temporal"}) & replaced or owner in replaced:
            # Keep the blank lines and comments before the declaration, so that line numbers
            # move only by the difference in length.
            out.append(decl[:code_offset(decl)])
            if not placed:
                out.append(snippet.rstrip("\n"))
                placed = True
            continue
        out.append(decl)
    if not placed:
        out.append("\n" + snippet.rstrip("\n"))
    return "".join(out) + tail


def parse_annotation(note):
    options = {"whole": False, "verify": False, "output": False, "expect": []}
    for word in (note or "").split():
        if word in ("whole", "verify", "output"):
            options[word] = True
        elif word.startswith("expect="):
            options["expect"] = sorted(x for x in word[len("expect="):].split(",") if x)
        else:
            raise ValueError(f"unknown snippet option '{word}'")
    return options


def run(cmd, cwd):
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=120)


def check_snippet(arbc, spec_text, name, options, expected_output):
    """Returns a list of problems (empty: the snippet behaves as documented)."""
    with tempfile.TemporaryDirectory(prefix="arbc-snippet-") as tmp:
        with open(os.path.join(tmp, name), "w", encoding="utf-8") as f:
            f.write(spec_text)
        checked = run([arbc, "check", "--format", "json", name], tmp)
        try:
            ids = sorted({d["id"] for d in json.loads(checked.stdout)["diagnostics"]})
        except (ValueError, KeyError):
            return [f"arbc check printed no JSON (exit {checked.returncode}): {checked.stderr}"]
        want_check = [] if options["verify"] else options["expect"]
        text = run([arbc, "check", name], tmp)
        if ids != want_check:
            return [f"arbc check ids {ids}, documented {want_check}:\n{text.stderr}"]
        if options["output"] and not options["verify"] and \
                text.stdout + text.stderr != expected_output:
            return ["arbc check output differs from the page\n--- page\n"
                    f"{expected_output}--- actual\n{text.stdout}{text.stderr}"]
        if want_check:
            return [] if checked.returncode == 2 else [f"arbc check exit {checked.returncode}"]
        if checked.returncode != 0:
            return [f"arbc check exit {checked.returncode}"]
        if not options["verify"]:
            return []
        verified = run([arbc, "verify", "--format", "json", name], tmp)
        try:
            report = json.loads(verified.stdout)
        except ValueError:
            return [f"arbc verify printed no JSON (exit {verified.returncode}): {verified.stderr}"]
        found = set()
        for item in report["inputs"]:
            found |= {f["check"] for f in item["findings"]}
            for port in item["ports"]:
                found |= {f["check"] for f in port["findings"]}
        found = sorted(found)
        problems = []
        if found != options["expect"]:
            text = run([arbc, "verify", name], tmp)
            problems.append(f"arbc verify checks {found}, documented {options['expect']}:\n"
                            f"{text.stdout}{text.stderr}")
        if options["output"]:
            text = run([arbc, "verify", name], tmp)
            if text.stdout + text.stderr != expected_output:
                problems.append("arbc verify output differs from the page\n--- page\n"
                                f"{expected_output}--- actual\n{text.stdout}{text.stderr}")
        return problems


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    arbc, page = os.path.abspath(args[0]), args[1]
    base_path = args[args.index("--base") + 1] if "--base" in args else "specs/table_clean.spec"
    base = open(base_path, encoding="utf-8").read()
    blocks = list(snippet_blocks(open(page, encoding="utf-8").read()))
    failures, count = [], 0
    for index, (line, tag, body, note, _) in enumerate(blocks):
        where = f"{page}:{line}"
        if tag == "":
            failures.append(f"{where}: fenced block without a language tag (spec, text, ...)")
            continue
        if tag != "spec":
            if note is not None:
                failures.append(f"{where}: snippet annotation on a ```{tag} block")
            continue
        count += 1
        try:
            options = parse_annotation(note)
        except ValueError as e:
            failures.append(f"{where}: {e}")
            continue
        expected_output = None
        if options["output"]:
            following = blocks[index + 1] if index + 1 < len(blocks) else None
            if following is None or following[1] != "text":
                failures.append(f"{where}: `output` needs a ```text block after the snippet")
                continue
            expected_output = following[2]
        spec_text = body if options["whole"] else splice(base, body)
        name = "snippet.spec" if options["whole"] else os.path.basename(base_path)
        for problem in check_snippet(arbc, spec_text, name, options, expected_output):
            failures.append(f"{where}: {problem}")
    for f in failures:
        print(f"FAIL {f}")
    print(f"{page}: {count} spec snippets, {len(failures)} failures")
    return 1 if failures or count == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
