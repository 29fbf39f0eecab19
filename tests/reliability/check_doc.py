#!/usr/bin/env python3
"""docs/reliability.md cites the tests that prove each guarantee; this keeps the citations true.

Every `Suite.Name` (or `Suite.*`) in backticks must be a GoogleTest test (TEST, TEST_F, TEST_P)
or a Python unittest method (`class Suite` ... `def test_...`) in the sources, a bare `Name` in the same table cell belongs to the last suite cited there,
every cited ctest name (`lower_case_words`) must be registered with add_test or be a golden
case of tests/check/, and every cited
repository path must exist.
usage: check_doc.py REPO_ROOT
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
doc = (root / "docs/reliability.md").read_text()
skip = {"build", "build-fuzz", "build-bench", "build-asan", "build-tsan", ".git"}
sources = [p for p in root.rglob("*.cc") if p.relative_to(root).parts[0] not in skip]
tests = set()
for p in sources:
    for suite, name in re.findall(r"\bTEST(?:_F|_P)?\((\w+),\s*(\w+)\)", p.read_text()):
        tests.add((suite, name))
# Python unittest cases (tests/lsp/test_protocol.py): `class Suite(...)` with `def test_...`.
for p in root.rglob("*.py"):
    if p.relative_to(root).parts[0] in skip or "node_modules" in p.parts:
        continue
    suite = None
    for line in p.read_text(errors="replace").splitlines():
        m = re.match(r"class (\w+)\(", line)
        if m:
            suite = m.group(1)
        m = re.match(r"    def (test_\w+)\(self", line)
        if m and suite:
            tests.add((suite, m.group(1)))
suites = {s for s, _ in tests}
ctests = set()
for p in root.rglob("CMakeLists.txt"):
    if p.relative_to(root).parts[0] in skip:
        continue
    ctests.update(re.findall(r"add_test\(NAME (\S+)", p.read_text()))
    ctests.update(re.findall(r"arbc_test\(NAME (\S+)", p.read_text()))  # a GoogleTest binary
# A name built in a loop (`check_golden.${case}`) stands for every name it can take.
ctest_patterns = [re.compile(re.escape(t).replace(re.escape("${"), "${").split("${")[0] + ".*"
                             if "${" in t else re.escape(t)) for t in ctests]

# Identifiers the page names that are not tests.
not_tests = {"expect_unaffected_and_accounted", "soak_bench", "on_delivery",
             "lsp_hover_after_edit_ms"}
not_files = {"arbc/status"}  # the language server's own request
errors = []
for line in doc.splitlines():
    if not line.startswith("|"):
        continue
    for cell in line.split("|"):
        suite = None
        for token in re.findall(r"`([^`]+)`", cell):
            m = re.fullmatch(r"([A-Z]\w+)\.(\w+|\*)", token)
            if m and not token.endswith((".md", ".cc", ".h")):
                suite, name = m.groups()
                if name == "*" and suite not in suites:
                    errors.append(f"no test suite {suite}")
                elif name != "*" and (suite, name) not in tests:
                    errors.append(f"no test {token}")
            elif suite and re.fullmatch(r"[A-Z][a-z]\w+", token):
                if (suite, token) not in tests:
                    errors.append(f"no test {suite}.{token}")
            elif re.fullmatch(r"[a-z0-9]+(_[a-z0-9]+)+\.[\w.-]+", token):
                # One case of a per-case ctest family: the family exists and so does the case.
                family, case = token.split(".", 1)
                where = {"check_golden": root / "tests/check" / case,
                         "verify_golden": root / "tests/verify/golden" / case}.get(family)
                if not any(p.fullmatch(token) for p in ctest_patterns):
                    errors.append(f"no ctest {token}")
                elif where is not None and not where.exists():
                    errors.append(f"no case {case} for {family} ({where.relative_to(root)})")
            elif re.fullmatch(r"[a-z0-9]+(_[a-z0-9]+)+(_\*)?", token) and "fuzz" not in token:
                pattern = re.compile(token.replace("*", ".*") + "$")
                golden = (root / "tests/check" / token).is_dir()  # a check_golden case
                # or a name built in a loop (`dds_split_table_clean_${scenario}`)
                looped = any(re.fullmatch(re.escape(t.split("${")[0]) + ".*", token)
                             for t in ctests if "${" in t)
                if not golden and not looped and not any(pattern.match(t) for t in ctests):
                    if token not in not_tests:
                        errors.append(f"no ctest {token}")
            elif "/" in token and re.fullmatch(r"[\w./-]+", token) and token not in not_files:
                if not (root / token).exists():
                    errors.append(f"no file {token}")
for e in errors:
    print("docs/reliability.md:", e)
print(f"{len(errors)} problem(s)")
sys.exit(1 if errors else 0)
