#!/usr/bin/env python3
"""Random edits to a spec in a real `arbc lsp` process (docs/reliability.md#the-language-server-arbc-lsp).

usage: random_edits.py ARBC SPEC --seed N --cases N   (run from the repository root)

Each case is one incremental didChange at a random range (past line ends and past the end of
the text, across lines, inside a surrogate pair) with a random piece of text (syntax, UTF-8 of
1 to 4 bytes, line breaks). Every 10th case, position requests at random places, answered while
the next edits arrive; every 50th, a save (the proof runs beside the edits). The script keeps
its own copy of the text, applying each change as the protocol says; at the end the server's
diagnostics of the last version must be `arbc check`'s of that copy (the server's text is the
client's; a proof's findings hold only for the text saved), the server must still answer, and its log must show no crash. Exit 0 when all hold.
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lsp_client import SCRATCH_PREFIX, LspClient, file_uri  # noqa: E402

PIECES = ["{", "}", ";", "when", " not ", "e_taken", ".", "->", "\"", "//", "/*", "*/", "\n",
          "é", "€", "😀", "arbitrate X.y {", "0.5s", "(", ")", "test \"t\" on take {",
          "tests for \"x.spec\";", "", "  ", "and", "set e_arm_idle;"]
REQUESTS = ["textDocument/hover", "textDocument/definition", "textDocument/documentHighlight",
            "textDocument/completion", "textDocument/prepareRename", "textDocument/references",
            "textDocument/rename", "textDocument/codeAction", "textDocument/documentSymbol"]
# Errors a request may get on text being typed: bad parameters, a refused rename.
ALLOWED_ERRORS = (-32602, -32803)


def utf16_offset(text, line, character):
    """The index in `text` of an LSP position, as the server reads it: a line past the end is
    the end of the text, a character past the line's end is its end, and a position inside a
    surrogate pair is after the pair."""
    lines = text.split("\n")
    if line >= len(lines):
        return len(text)
    index = sum(len(l) + 1 for l in lines[:line])
    units = 0
    for ch in lines[line]:
        if units >= character:
            break
        units += 2 if ord(ch) > 0xFFFF else 1
        index += 1
    return index


def random_range(rng, text):
    lines = text.split("\n")
    line = rng.randrange(len(lines) + 2)
    start = (line, rng.randrange(0, 90))
    end = (line + rng.randrange(0, 3), rng.randrange(0, 90))
    start, end = min(start, end), max(start, end)
    return ({"start": {"line": start[0], "character": start[1]},
             "end": {"line": end[0], "character": end[1]}})


def check_diagnostics(arbc, text, spec):
    """(id, 0-based line) of `arbc check --format json` on text saved beside spec."""
    with tempfile.NamedTemporaryFile("w", prefix=SCRATCH_PREFIX, suffix=".spec",
                                     dir=os.path.dirname(spec),
                                     delete=False, encoding="utf-8") as f:
        f.write(text)
    try:
        out = subprocess.run([arbc, "check", "--format", "json", f.name], capture_output=True,
                             text=True, timeout=60).stdout
        return sorted((d["id"], d["line"] - 1 if d.get("line", 0) > 0 else 0)
                      for d in json.loads(out)["diagnostics"])
    finally:
        os.unlink(f.name)


def ask(c, rng, uri, text):
    """Sends every kind of request at random positions; returns their ids."""
    ids = []
    for method in rng.sample(REQUESTS, 4):
        r = random_range(rng, text)
        params = {"textDocument": {"uri": uri}, "position": r["start"]}
        if method == "textDocument/references":
            params["context"] = {"includeDeclaration": rng.random() < 0.5}
        elif method == "textDocument/rename":
            params["newName"] = rng.choice(["e_new", "take2", "not", "1x"])
        elif method == "textDocument/codeAction":
            params = {"textDocument": {"uri": uri}, "range": r, "context": {"diagnostics": []}}
        elif method == "textDocument/documentSymbol":
            params = {"textDocument": {"uri": uri}}
        ids.append((method, c.request_async(method, params)))
    return ids


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("arbc")
    parser.add_argument("spec")
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--cases", type=int, required=True)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    spec = os.path.abspath(args.spec)
    text = open(spec, encoding="utf-8").read()
    uri = file_uri(spec)
    failures = []
    with LspClient([args.arbc, "lsp"]) as c:
        c.initialize(os.getcwd())
        c.open(uri, text)
        pending = []
        for version in range(2, args.cases + 2):
            r = random_range(rng, text)
            piece = rng.choice(PIECES)
            c.change(uri, version, [{"range": r, "text": piece}])
            begin = utf16_offset(text, r["start"]["line"], r["start"]["character"])
            end = utf16_offset(text, r["end"]["line"], r["end"]["character"])
            text = text[:begin] + piece + text[max(begin, end):]
            for method, rid in pending:  # answered while this edit arrived
                reply = c.response(rid)
                if "error" in reply and reply["error"]["code"] not in ALLOWED_ERRORS:
                    failures.append(f"version {version}: {method}: {reply['error']}")
            pending = ask(c, rng, uri, text) if version % 10 == 0 else []
            if version % 50 == 0 and version != args.cases + 1:  # the last text is unproved
                c.notify("textDocument/didSave", {"textDocument": {"uri": uri}})
        last = args.cases + 1
        got = sorted((d.get("code", ""), d["range"]["start"]["line"])
                     for d in c.wait_diagnostics(uri, version=last, timeout=120))
        want = check_diagnostics(args.arbc, text, spec)
        if got != want:
            failures.append(f"version {last}: the server's diagnostics {got} are not "
                            f"`arbc check`'s {want} of the same text")
        if "result" not in c.response(c.request_async("textDocument/documentSymbol",
                                                      {"textDocument": {"uri": uri}})):
            failures.append("no outline after the edits")
        if c.proc.poll() is not None:
            failures.append(f"the server exited with {c.proc.returncode}")
        c.proc.stdin.close()
        c.proc.wait(timeout=60)
        log = "".join(c.stderr_lines)
        for sign in ("terminate called", "Sanitizer", "Segmentation", "Aborted"):
            if sign in log:
                failures.append(f"the server's log shows '{sign}':\n{log[-2000:]}")
    for f in failures:
        print("FAIL:", f)
    print(f"{args.cases} random edits (seed {args.seed}): "
          f"{'ok' if not failures else str(len(failures)) + ' failures'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
