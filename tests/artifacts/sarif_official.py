#!/usr/bin/env python3
"""Every SARIF log arbc writes follows the official SARIF 2.1.0 JSON schema (OASIS, rtm.5, as
schemastore publishes it), not only the stricter subset written here from the standard's text
(sarif-2.1.0-subset.schema.json). The official schema is not in the repository:
`scripts/install-deps.sh --test` takes it from the npm registry (inside @microsoft/jest-sarif)
and keeps it, checked by its SHA-256, as tests/artifacts/official/sarif-2.1.0-rtm.5.json.

The logs read are the verify goldens' (tests/verify/golden/*.sarif): verify_golden.* compares
arbc's output with each byte for byte, so they are what arbc writes. A golden holds stdout and
stderr; a bad input's diagnostics come before the log, which starts at the first line that is
`{`. First, broken logs must be refused, so that a pass means something.

usage: sarif_official.py ROOT     exit 77 (skipped) when the schema is not installed
"""
import glob
import json
import os
import sys

SCHEMA = os.path.join("tests", "artifacts", "official", "sarif-2.1.0-rtm.5.json")


def log_of(text):
    lines = text.splitlines(keepends=True)
    start = next((i for i, line in enumerate(lines) if line.rstrip("\n") == "{"), None)
    return None if start is None else json.loads("".join(lines[start:]))


def broken_logs():
    """Logs the official schema must refuse: each breaks one rule of the standard."""
    good = {"version": "2.1.0", "runs": [{"tool": {"driver": {"name": "arbc"}}, "results": [
        {"ruleId": "exclusive", "level": "error", "message": {"text": "m"}}]}]}
    level = json.loads(json.dumps(good))
    level["runs"][0]["results"][0]["level"] = "fatal"  # not one of the four levels (3.27.10)
    extra = json.loads(json.dumps(good))
    extra["runs"][0]["results"][0]["confidence"] = 1  # a property results do not have
    no_message = json.loads(json.dumps(good))
    del no_message["runs"][0]["results"][0]["message"]  # required (3.27.11)
    return {"good": (good, True), "level": (level, False), "extra": (extra, False),
            "no message": (no_message, False)}


def main():
    import jsonschema
    root = sys.argv[1]
    path = os.path.join(root, SCHEMA)
    if not os.path.exists(path):
        print(f"skipped: {SCHEMA} is not installed (scripts/install-deps.sh --test fetches it "
              "from the npm registry); the SARIF logs are checked against the subset only")
        return 77
    with open(path, encoding="utf-8") as f:
        schema = json.load(f)
    validator = jsonschema.validators.validator_for(schema)(schema)
    problems = []
    for name, (log, valid) in broken_logs().items():
        if validator.is_valid(log) != valid:
            problems.append(f"self-test: the {name!r} log is {'refused' if valid else 'accepted'}")
    logs = sorted(glob.glob(os.path.join(root, "tests", "verify", "golden", "*.sarif")))
    for log_path in logs:
        with open(log_path, encoding="utf-8") as f:
            log = log_of(f.read())
        rel = os.path.relpath(log_path, root)
        if log is None:
            problems.append(f"{rel}: no SARIF log in it")
            continue
        for e in sorted(validator.iter_errors(log), key=lambda e: list(e.path))[:1]:
            problems.append(f"{rel}: at /{'/'.join(map(str, e.path))}: {e.message}")
    for p in problems:
        print("FAIL", p)
    print(f"{len(logs)} SARIF logs read against the official schema, {len(problems)} problems")
    return 1 if problems or not logs else 0


if __name__ == "__main__":
    sys.exit(main())
