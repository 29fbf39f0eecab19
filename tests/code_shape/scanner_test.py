#!/usr/bin/env python3
"""Checks scripts/long_functions.py's scanner on scanner_fixture.cc.txt: every function it finds,
with its first and last line, is the one a `// expect NAME FIRST LAST` comment names, and none is
missing (raw strings, comments, character literals, constructor initializer lists, member
functions, operators, trailing return types and lambdas)."""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "scripts"))
import long_functions  # noqa: E402

fixture = os.path.join(here, "scanner_fixture.cc.txt")
with open(fixture, encoding="utf-8") as f:
    expected = [(m.group(1), int(m.group(2)), int(m.group(3)))
                for m in re.finditer(r"// expect (\S+) (\d+) (\d+)", f.read())]
found = long_functions.scan(fixture)
if found != expected:
    print("expected:", expected)
    print("found:   ", found)
    sys.exit(1)
print(f"{len(found)} functions found as expected")

# Which files are test code: production files named test_* (harness/test_runner.cc, the `arbc test`
# engine) are judged as production; tests, test utilities and testing/ folders are not.
for path, test in [("harness/test_runner.cc", False), ("compiler/lower/test_cases.h", False),
                   ("verify/checks_test.cc", True), ("runtime/runtime_test_util.h", True),
                   ("compiler/codegen/testing/lua_monitor_harness.cc", True),
                   ("tests/check/robustness_test.cc", True), ("lsp/server.cc", False)]:
    if long_functions.is_test_file(path) != test:
        print(f"is_test_file({path!r}) is {not test}, expected {test}")
        sys.exit(1)
for folder in ("lsp", "dds", "import"):
    if folder not in long_functions.LIBRARY_DIRS:
        print(f"{folder}/ is not scanned")
        sys.exit(1)
print("test files and scanned folders as expected")
