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
