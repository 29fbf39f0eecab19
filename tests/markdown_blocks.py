"""Fenced code blocks of a Markdown page, for the documentation tests (tests/docs_snippets/,
tests/docs_tutorial/), which both read blocks together with the HTML comment that annotates
them (`<!-- snippet: verify -->`, `<!-- exit: 1 -->`, ...)."""
import re

FENCE = re.compile(r"^```(\S*)\s*$")
COMMENT = re.compile(r"^<!--\s*(.*?)\s*-->\s*$")


def fenced_blocks(text):
    """Yields (line of the opening fence, tag, body, text of the comment on the last non-blank
    line before the block or None, line of the closing fence), line numbers counted from 1."""
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start, tag = i, m.group(1)
        j = i + 1
        while j < len(lines) and lines[j].rstrip() != "```":
            j += 1
        if j == len(lines):
            raise SystemExit(f"line {start + 1}: fenced block never closed")
        k = start - 1
        while k >= 0 and not lines[k].strip():
            k -= 1
        note = COMMENT.match(lines[k]) if k >= 0 else None
        body = "\n".join(lines[start + 1:j]) + "\n" if j > start + 1 else ""
        yield start + 1, tag, body, note.group(1) if note else None, j + 1
        i = j + 1
