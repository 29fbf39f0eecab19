#!/usr/bin/env python3
"""A term fresh from Z3's C API is owned before Z3 is called again.

A `Z3_mk_*` call returns a term with no reference: the context keeps it alive only until the
next API call that returns another object, then frees it. The code wraps such a term at once
(`wrap(ctx, Z3_mk_...)`, `z3::expr(ctx, Z3_mk_...)`). Passing it straight to another call is
safe only while no other argument of that call calls Z3: C++ leaves the order in which a call's
arguments are evaluated unspecified, so in `Z3_mk_fpa_to_fp_float(ctx, Z3_mk_fpa_rne(ctx), x,
float_sort(ctx))` GCC made the sort first and the rounding mode last (fine), clang the other way
round, and Z3 then read a freed rounding mode (an assertion deep in its float encoding, or a
wrong term). This scanner refuses a raw `Z3_mk_` call beside an argument that calls anything
but `ctx()`.

usage: z3_raw_terms.py ROOT | --self-test
"""
import os
import re
import sys

FOLDERS = ["verify", "compiler", "runtime", "cli", "harness", "import", "lsp", "dds", "report",
           "core", "tests", "bench", "fuzz"]
RAW = re.compile(r"\bZ3_mk_\w+\s*\(")
CALL = re.compile(r"\b(?!ctx\s*\()\w+\s*\(")


def blank_comments_and_strings(text):
    """The text with comments and literals blanked, offsets and newlines kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        two = text[i:i + 2]
        if two == "//":
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif two == "/*":
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif text[i] in "\"'":
            j = i + 1
            while j < n and text[j] != text[i]:
                j += 2 if text[j] == "\\" else 1
            j += 1
        else:
            out.append(text[i])
            i += 1
            continue
        out.append(re.sub(r"[^\n]", " ", text[i:j]))
        i = j
    return "".join(out)


def enclosing_arguments(code, pos):
    """The argument list (start, end) of the innermost call whose parentheses hold pos."""
    depth = 0
    for i in range(pos - 1, -1, -1):
        if code[i] == ")":
            depth += 1
        elif code[i] == "(":
            if depth == 0:
                start = i + 1
                break
            depth -= 1
        elif code[i] in ";{}" and depth == 0:
            return None
    else:
        return None
    depth = 0
    for j in range(start, len(code)):
        if code[j] in "([":
            depth += 1
        elif code[j] in ")]":
            if depth == 0:
                return start, j
            depth -= 1
    return None


def split_arguments(code, start, end):
    """(start, end) of each top-level argument in code[start:end]."""
    spans, depth, begin = [], 0, start
    for j in range(start, end):
        if code[j] in "([{":
            depth += 1
        elif code[j] in ")]}":
            depth -= 1
        elif code[j] == "," and depth == 0:
            spans.append((begin, j))
            begin = j + 1
    return spans + [(begin, end)]


def findings(text):
    code = blank_comments_and_strings(text)
    bad = []
    for m in RAW.finditer(code):
        args = enclosing_arguments(code, m.start())
        if args is None:
            continue
        spans = split_arguments(code, *args)
        others = [code[a:b] for a, b in spans if not a <= m.start() < b]
        if any(CALL.search(o) for o in others):
            bad.append(code.count("\n", 0, m.start()) + 1)
    return bad


def self_test():
    assert findings("f(Z3_mk_fpa_to_fp_float(ctx, Z3_mk_fpa_rne(ctx), x, float_sort(ctx)));\n") == [1]
    assert findings("z3::expr e(ctx, Z3_mk_fpa_round_to_integral(ctx, Z3_mk_fpa_rne(ctx), x));") == []
    assert findings("return wrap(a.ctx(), Z3_mk_fpa_neg(a.ctx(), a.scalar));") == []
    assert findings("Z3_ast r = op ? Z3_mk_fpa_add(ctx, rne(ctx), x, y)\n : Z3_mk_x(ctx);") == []
    assert findings("g(Z3_mk_a(ctx),\n  // h(1)\n  b);") == []
    assert findings("g(h(\"(\"),\n  Z3_mk_a(ctx));") == [2]
    assert findings("z3::expr(ctx, Z3_mk_eq(ctx_, c, m.eval(c, true)));") == []
    print("ok")


def main():
    if sys.argv[1] == "--self-test":
        return self_test()
    root = sys.argv[1]
    bad, raw = [], 0
    for folder in FOLDERS:
        for dirpath, _, files in os.walk(os.path.join(root, folder)):
            for name in sorted(files):
                if not name.endswith((".cc", ".h")):
                    continue
                path = os.path.relpath(os.path.join(dirpath, name), root)
                with open(os.path.join(root, path), encoding="utf-8") as f:
                    text = f.read()
                raw += len(RAW.findall(blank_comments_and_strings(text)))
                bad += [f"{path}:{n}: a raw Z3 term beside an argument that calls; wrap it first"
                        for n in findings(text)]
    print("\n".join(bad + [f"{raw} raw Z3_mk_ calls, {len(bad)} passed beside a call"]))
    return 1 if bad or raw == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
