#!/usr/bin/env python3
"""Every citation of a document in the repository points at something that exists.

usage: check_links.py ROOT          check every tracked file under ROOT (git ls-files)
       check_links.py --self-test   check that each kind of bad citation is caught

A tracked file fails when it
  - cites the original design document that is not in the repository (its name is the
    upper-case DESIGN plus .md), or cites a section by number ("section 4") without naming
    the outside document it belongs to ("the Lua 5.4 manual, section 3.1" is fine);
  - names a Markdown page (`docs/runtime.md`, a link `[x](checks.md)`) that does not exist;
  - names an anchor (`docs/design.md#effective-guards`, `[x](#run-report)`) that is not the
    GitHub slug of a heading of that page.
Paths with a folder are read from the repository root, then from the citing file's folder;
Markdown link targets from the citing file's folder, as a Markdown viewer reads them. A bare
page name (`checks.md`) is looked up beside the citing file, at the root, and in docs/.
docs/design.md is the page these citations should use. This file is not checked: its
self-test fixtures are bad citations on purpose.
"""
import os
import re
import subprocess
import sys
import tempfile

# Built from parts so that this file does not cite the document itself.
ORIGINAL_DESIGN = re.compile(r"\b" + "DES" + r"IGN\.md\b")
SECTION_NUMBER = re.compile(r"\b[Ss]ections?\s+\d+(?:\.\d+)*\b")
# A section number is fine where the line names the outside document it belongs to.
OTHER_DOCUMENT = re.compile(r"(?i)\b(manual|paper|rfc|standard|specification|fips|iso)\b")
# A path or bare name ending in .md, not part of a longer path or URL, with an optional anchor.
PAGE = re.compile(r"(?<![\w./:@-])((?:\.{1,2}/|[\w-][\w.-]*/)*[\w.-]+\.md)(?!\w)(?:#([\w-]*\w)?)?")
# A Markdown link target: [text](target) or [text](target "title").
LINK = re.compile(r"\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"<a\s+(?:name|id)=\"([^\"]+)\"")
MAX_BYTES = 2_000_000


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links keep their text
    text = text.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors_of(path, cache={}):
    """The anchors a Markdown page defines: its headings' slugs (numbered when repeated, as
    GitHub does) and explicit <a name/id> anchors. Headings inside fenced blocks do not count."""
    if path in cache:
        return cache[path]
    found, seen, fenced = set(), {}, False
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if FENCE.match(line):
                fenced = not fenced
                continue
            if fenced:
                continue
            m = HEADING.match(line)
            if m:
                s = slug(m.group(2))
                n = seen.get(s, 0)
                seen[s] = n + 1
                found.add(s if n == 0 else f"{s}-{n}")
            found.update(HTML_ANCHOR.findall(line))
    cache[path] = found
    return found


def tracked_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True,
                             check=True).stdout.decode()
        return sorted(p for p in out.split("\0") if p)
    except (OSError, subprocess.CalledProcessError):
        files = []
        for folder, dirs, names in os.walk(root):
            # Not ours (a copy without .git, as scripts/mutate.sh makes): hidden folders, build
            # trees, and the editor extension's npm packages.
            dirs[:] = [d for d in dirs if not d.startswith((".", "build"))
                       and d not in ("node_modules", "out")]
            files += [os.path.relpath(os.path.join(folder, n), root) for n in names]
        return sorted(files)


class Checker:
    def __init__(self, root, files):
        self.root = root
        self.errors = []
        # The repository's folders are those that hold tracked files: a folder a command wrote
        # into the checkout (scripts/demo.sh's out/, a build tree) is an output, not a folder
        # of the repository, even though it exists on disk.
        self.folders = {""}
        for rel in files:
            parts = rel.split("/")[:-1]
            for n in range(1, len(parts) + 1):
                self.folders.add("/".join(parts[:n]))

    def fail(self, where, line, what):
        self.errors.append(f"{where}:{line}: {what}")

    def resolve(self, citing, page, link):
        """The file `page` names when cited from `citing` (a path relative to the root), or
        None when no candidate exists."""
        here = os.path.dirname(citing)
        if link:
            candidates = [os.path.join(here, page)]
        elif "/" in page:
            candidates = [page, os.path.join(here, page)]
        else:
            candidates = [os.path.join(here, page), page, os.path.join("docs", page)]
        for c in candidates:
            path = os.path.normpath(os.path.join(self.root, c))
            if os.path.isfile(path):
                return path
        return None

    def outside(self, citing, page, link):
        """Does `page` leave the repository? Such a file (a shared folder beside the checkout)
        is not this test's business. A link is read from the citing file's folder only; a path
        in prose may be meant from either, so it is left alone if either reading leaves."""
        here = os.path.dirname(citing)
        root = os.path.normpath(self.root)
        bases = (here,) if link else ("", here)
        return any(not os.path.normpath(os.path.join(root, base, page)).startswith(root + os.sep)
                   for base in bases)

    def cites_a_page(self, rel, page, anchor):
        """Is a mention of `page` in prose or code a citation? A path whose first folder is a
        folder of the repository is (`docs/x.md`, `../examples/y/README.md`); a path into a
        folder the repository does not have names an output (`out/app/index.md`). A bare name
        is a citation only with an anchor (`checks.md#dead`): without one it may name a file
        that a command writes (`index.md`)."""
        if "/" not in page:
            return anchor is not None
        first = page.split("/")[0]
        if first in (".", ".."):
            return True
        here = os.path.dirname(rel)
        return any(os.path.normpath(os.path.join(d, first)) in self.folders for d in ("", here))

    def check_target(self, rel, number, page, anchor, link):
        if page and self.outside(rel, page, link):
            return
        if page:
            path = self.resolve(rel, page, link)
            if path is None:
                self.fail(rel, number, f"cites {page}, which does not exist")
                return
        else:
            path = os.path.join(self.root, rel)
        if anchor and anchor not in anchors_of(path):
            shown = os.path.relpath(path, self.root)
            self.fail(rel, number, f"cites {page}#{anchor}, but {shown} has no heading "
                                   f"with the anchor '{anchor}'")

    def check_file(self, rel):
        path = os.path.join(self.root, rel)
        if not os.path.isfile(path) or os.path.getsize(path) > MAX_BYTES:
            return
        try:
            text = open(path, encoding="utf-8").read()
        except UnicodeDecodeError:
            return  # binary
        markdown = rel.endswith(".md")
        for number, line in enumerate(text.split("\n"), start=1):
            if ORIGINAL_DESIGN.search(line):
                self.fail(rel, number, "cites the original design document, which is not in the "
                                       "repository: cite docs/design.md#<anchor> instead")
            if SECTION_NUMBER.search(line) and not OTHER_DOCUMENT.search(line):
                self.fail(rel, number, "cites a section by number: cite docs/design.md#<anchor> "
                                       "or the page that owns the topic")
            links = []
            if markdown:
                for m in LINK.finditer(line):
                    target = m.group(1)
                    links.append(m.span(1))
                    if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                        continue  # a URL
                    page, _, anchor = target.partition("#")
                    if page and not page.endswith(".md"):
                        continue  # an image, a source file: not a page
                    self.check_target(rel, number, page, anchor, link=True)
            for m in PAGE.finditer(line):
                if any(a <= m.start(1) < b for a, b in links):
                    continue  # already checked as a link
                page, anchor = m.group(1), m.group(2)
                if not self.cites_a_page(rel, page, anchor):
                    continue
                self.check_target(rel, number, page, anchor, link=False)

    def run(self, files):
        me = os.path.realpath(__file__)
        for rel in files:
            if os.path.realpath(os.path.join(self.root, rel)) != me:  # its fixtures are bad on purpose
                self.check_file(rel)
        return self.errors


def self_test():
    """Each kind of bad citation is reported, and good ones are not."""
    with tempfile.TemporaryDirectory() as root:
        def write(rel, text):
            os.makedirs(os.path.dirname(os.path.join(root, rel)) or root, exist_ok=True)
            with open(os.path.join(root, rel), "w", encoding="utf-8") as f:
                f.write(text)
        write("docs/design.md", "# Design\n\n## Effective guards\n\n```\n## Not a heading\n```\n"
                                "## Priorities and holds\n## Priorities and holds\n")
        write("docs/other.md", "See [guards](design.md#effective-guards) and [top](#top-part).\n"
                               "## Top part\n")
        write("good.cc", "// docs/design.md#priorities-and-holds-1, docs/other.md\n"
                         "// ends a sentence: docs/design.md#effective-guards.\n"
                         "// the Lua 5.4 manual, section 3.1; ../../elsewhere/README.md\n"
                         "// https://example.org/x/missing.md is a URL\n")
        write("bad1.cc", "// the effective guard of " + "DES" + "IGN.md\n")
        write("bad2.cc", "// see docs/design.md, section 5\n")
        write("bad3.cc", "// docs/missing.md\n")
        write("bad4.cc", "// docs/design.md#not-a-heading\n")
        write("output.cc", "// writes out/app/index.md and %s/index.md, then index.md\n")
        write("docs/bad5.md", "[x](design.md#nope) and [y](#nowhere) and [z](gone.md)\n")
        # An output folder in the checkout (scripts/demo.sh writes out/), holding files but none
        # tracked: a path into it names an output, not a page (docs/tutorial.md cites
        # out/step3-docs/index.md before or after the demo has run).
        write("out/app/app.json", "{}\n")
        write("docs/outputs.md", "`arbc docs` writes out/step3-docs/index.md and out/app/index.md\n")
        files = ["good.cc", "output.cc", "docs/design.md", "docs/other.md", "docs/outputs.md",
                 "bad1.cc", "bad2.cc", "bad3.cc", "bad4.cc", "docs/bad5.md"]
        errors = Checker(root, files).run(files)
        expected = {"bad1.cc:1": "original design", "bad2.cc:1": "section by number",
                    "bad3.cc:1": "docs/missing.md, which does not exist",
                    "bad4.cc:1": "no heading with the anchor 'not-a-heading'"}
        problems = []
        for where, what in expected.items():
            if not any(e.startswith(where + ":") and what in e for e in errors):
                problems.append(f"not reported: {where} {what}")
        bad5 = [e for e in errors if e.startswith("docs/bad5.md:")]
        if len(bad5) != 3:
            problems.append(f"docs/bad5.md: expected 3 errors, got {bad5}")
        for e in errors:
            if e.startswith(("good.cc", "output.cc", "docs/design.md", "docs/other.md",
                             "docs/outputs.md")):
                problems.append(f"false alarm: {e}")
        for p in problems:
            print("FAIL", p)
        print(f"self-test: {len(errors)} errors reported, {len(problems)} problems")
        return 1 if problems else 0


def main():
    args = sys.argv[1:]
    if args == ["--self-test"]:
        sys.exit(self_test())
    if len(args) != 1:
        sys.exit(__doc__)
    root = os.path.abspath(args[0])
    files = tracked_files(root)
    errors = Checker(root, files).run(files)
    for e in errors:
        print(e)
    print(f"{len(files)} files, {len(errors)} bad citations")
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
