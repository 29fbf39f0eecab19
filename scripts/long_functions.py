#!/usr/bin/env python3
"""Lists C++ functions longer than a limit (default 80 lines) and source files longer than 600
lines, and fails if any is not allowed.

A function's length is counted from the line of its name to the line of its closing brace, both
included. The scan strips comments, string and character literals (raw strings included) and
preprocessor lines, then matches braces: a `{` outside any function whose declaration head has a
parameter list opens a function body (member functions defined in a class included); braces
inside a body (blocks, lambdas, local classes) belong to that function.

Usage:
  scripts/long_functions.py [--limit N] [--file-limit N] [--all] [--allow FILE] [ROOT]

Without --all it scans every production folder (core/ compiler/ verify/ runtime/ cli/ lsp/ dds/
import/ harness/ report/), test code excepted: files named *_test.cc or *_test.h, test utilities (*test_util*),
and anything under a tests/, testing/ or testdata/ folder. A production file whose name merely
starts with test_ (harness/test_runner.cc, the `arbc test` engine) is production. It exits 1 if a
function over the limit or a file over the file limit is not in the allow-list
(scripts/long_functions.allow: `path function` per line, or `path (file)` for a long file), or
if an allowed one is no longer long (so the list only shrinks). With --all it lists every long
function in the repository (tests, benchmarks and fuzz targets included) and always exits 0.
"""

import argparse
import os
import re
import sys

LIBRARY_DIRS = ["core", "compiler", "verify", "runtime", "cli", "lsp", "dds", "import", "harness",
                "report"]
FILE_LIMIT = 600
ALL_DIRS = LIBRARY_DIRS + ["bench", "fuzz", "tests", "grammar"]
SOURCE_EXT = (".cc", ".cpp", ".h", ".hpp")
FILE_MARK = "(file)"  # the allow-list's name for a whole file over the file limit


def is_test_file(path):
    """Tests and the code that only tests use (test utilities, fixtures under testing/)."""
    name = os.path.basename(path)
    parts = path.split(os.sep)
    return (
        name.endswith(("_test.cc", "_test.h"))
        or "test_util" in name
        or "testing" in parts
        or "testdata" in parts
        or "tests" in parts
    )


def strip_code(text):
    """The text with comments, literals and preprocessor lines blanked (newlines kept)."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if c == "\n":
            out.append(c)
            i += 1
            at_line_start = True
            continue
        if at_line_start and c in " \t":
            out.append(c)
            i += 1
            continue
        if at_line_start and c == "#":  # a preprocessor line, continuations included
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        at_line_start = False
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        raw = re.match(r'(?:u8|u|U|L)?R"([^()\\ \n]{0,16})\(', text[i:i + 24])
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            close = ")" + raw.group(1) + '"'
            end = text.find(close, i + raw.end())
            end = n if end < 0 else end + len(close)
            out.append('""' + re.sub(r"[^\n]", " ", text[i + 2:end]))
            i = end
            continue
        if c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum() and
                                         re.search(r"\b\d[\w']*$", text[max(0, i - 40):i]))):
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + c)
            i = j + 1
            continue
        out.append(c)
        i += 1
    return "".join(out)


SCOPE_KEYWORD = re.compile(r"\b(namespace|class|struct|union|enum|extern)\b")
ACCESS = re.compile(r"\b(public|private|protected)\s*:(?!:)")


def strip_template_prefix(head):
    """`template <...> void f()` -> ` void f()` (nested angle brackets matched)."""
    while True:
        m = re.match(r"\s*template\s*<", head)
        if not m:
            return head
        depth, j = 1, m.end()
        while j < len(head) and depth:
            depth += {"<": 1, ">": -1}.get(head[j], 0)
            j += 1
        head = head[j:]


def top_level_paren(head):
    """Index of the first `(` outside brackets, or -1."""
    depth = 0
    for j, ch in enumerate(head):
        if ch in "[":
            depth += 1
        elif ch == "]":
            depth -= 1
        elif ch == "(" and depth == 0:
            return j
    return -1


def classify(head):
    """What a `{` after `head` opens at namespace or class scope: 'scope', 'func' or 'init'."""
    head = strip_template_prefix(ACCESS.sub(" ", head))
    paren = top_level_paren(head)
    before = head if paren < 0 else head[:paren]
    if SCOPE_KEYWORD.search(before):
        return "scope"
    if paren < 0:
        return "init"
    eq = re.search(r"(?<![=!<>])=(?!=)", before)
    if eq and not re.search(r"\boperator\s*\S*$", before[:eq.start() + 1]):
        # `auto f = [](...) {` is a function; `T x = f(...) {` cannot be, `= {` is data.
        return "func" if re.search(r"\]\s*$", before) else "init"
    # Skip the parameter list, then look for a constructor's initializer list.
    depth, j = 0, paren
    while j < len(head):
        depth += {"(": 1, ")": -1}.get(head[j], 0)
        j += 1
        if depth == 0:
            break
    rest = head[j:]
    if re.search(r"(?<!:):(?!:)", rest):
        return "func" if re.search(r"[)}]\s*$", head) else "init"
    return "func"


def function_name(head, head_start, code):
    """(name, line) of the function whose declaration head starts at `head_start`."""
    clean = strip_template_prefix(ACCESS.sub(lambda m: " " * len(m.group(0)), head))
    offset = len(head) - len(clean)
    m = re.search(r"operator\s*(\(\)|[^\s(]+)\s*\(", clean)
    paren = m.end() - 1 if m else top_level_paren(clean)
    before = clean[:paren] if paren >= 0 else clean
    name = re.search(r"([\w:]*operator\s*(?:\(\)|[^\s\w(]+|\w+)|~?[\w:]+|\])\s*$", before)
    if not name:
        return "?", code.count("\n", 0, head_start + offset) + 1
    pos = head_start + offset + name.start()
    text = name.group(1)
    if text == "]":
        text = "<lambda>"
    return text, code.count("\n", 0, pos) + 1


def scan(path):
    """[(name, first_line, last_line)] for every function defined in the file."""
    with open(path, encoding="utf-8", errors="replace") as f:
        code = strip_code(f.read())
    found = []
    stack = []  # kinds of open braces: 'scope', 'init', or ('func', name, line)
    head_start = 0
    paren = 0
    func_depth = 0  # braces open inside the current function body
    for i, ch in enumerate(code):
        if func_depth:
            if ch == "{":
                func_depth += 1
            elif ch == "}":
                func_depth -= 1
                if func_depth == 0:
                    _, name, line = stack.pop()
                    found.append((name, line, code.count("\n", 0, i) + 1))
                    head_start = i + 1
            continue
        if ch == "(":
            paren += 1
        elif ch == ")":
            paren = max(0, paren - 1)
        elif ch == ";" and paren == 0:
            head_start = i + 1
        elif ch == "{":
            if paren:
                stack.append("init")
                continue
            head = code[head_start:i]
            kind = classify(head)
            if kind == "func":
                name, line = function_name(head, head_start, code)
                stack.append(("func", name, line))
                func_depth = 1
            else:
                stack.append(kind)
                if kind == "scope":
                    head_start = i + 1
        elif ch == "}":
            kind = stack.pop() if stack else "scope"
            if kind == "scope":
                head_start = i + 1
            elif paren == 0 and not re.search(r"(?<!:):(?!:)", code[head_start:i]):
                # data `{...}` ends a declaration; inside a constructor's initializer list
                # it does not (the body's `{` follows).
                head_start = i + 1
    return found


def source_files(root, dirs, with_tests):
    for d in dirs:
        top = os.path.join(root, d)
        for base, subdirs, files in os.walk(top):
            subdirs[:] = sorted(s for s in subdirs if not s.startswith("."))
            for name in sorted(files):
                if not name.endswith(SOURCE_EXT):
                    continue
                rel = os.path.relpath(os.path.join(base, name), root)
                if with_tests or not is_test_file(rel):
                    yield rel


def read_allow(path):
    allowed = set()
    if not os.path.exists(path):
        return allowed
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                file, name = line.split()
                allowed.add((file, name))
    return allowed


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", nargs="?", default=os.path.dirname(here))
    parser.add_argument("--limit", type=int, default=80)
    parser.add_argument("--file-limit", type=int, default=FILE_LIMIT)
    parser.add_argument("--all", action="store_true", help="every directory, tests included")
    parser.add_argument("--allow", default=os.path.join(here, "long_functions.allow"))
    args = parser.parse_args()

    dirs = ALL_DIRS if args.all else LIBRARY_DIRS
    long = []
    for rel in source_files(args.root, dirs, with_tests=args.all):
        path = os.path.join(args.root, rel)
        for name, first, last in scan(path):
            if last - first + 1 > args.limit:
                long.append((last - first + 1, rel, name, first))
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = sum(1 for _ in f)
        if lines > args.file_limit and not args.all:
            long.append((lines, rel, FILE_MARK, 1))
    long.sort(key=lambda x: (-x[0], x[1], x[3]))
    allowed = read_allow(args.allow)
    bad = 0
    for lines, rel, name, first in long:
        ok = (rel, name) in allowed
        bad += 0 if ok or args.all else 1
        mark = " (allowed)" if ok else ""
        print(f"{lines:5d}  {rel}:{first}  {name}{mark}")
    if args.all:
        return 0
    present = {(rel, name) for _, rel, name, _ in long}
    for rel, name in sorted(allowed - present):
        print(f"{rel} {name} is allowed to be long but is not: remove it from {args.allow}")
        bad += 1
    if bad:
        print(f"{bad} problem(s): split functions over {args.limit} lines, and files over "
              f"{args.file_limit}, by what they do")
        return 1
    print(f"no function over {args.limit} lines and no file over {args.file_limit} outside the "
          "allow-list")
    return 0


if __name__ == "__main__":
    sys.exit(main())
