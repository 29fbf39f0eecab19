#!/usr/bin/env python3
"""docs/cli.md and `arbc --help` / `arbc CMD --help` must agree (issue 9).

usage: check_cli_doc.py ARBC [PAGE]          (PAGE: docs/cli.md by default)

What is compared:
- The page's first ```text block is `arbc --help`, byte for byte.
- The page has one section `## `arbc CMD`` per command that `arbc --help` lists, and no other.
- A command's section opens with a ```text block: its `--help` up to and including the
  `Usage:` line (the description and the usage), byte for byte.
- The section's table (columns: argument or option | value | meaning) has one row per argument
  and option of the command's `--help`, except `-h,--help` (described once for all commands),
  and no other rows. A row names the same flags (`-o`, `--output`), its meaning is the help's
  description exactly (after undoing Markdown escapes: `\\*`, `&lt;`, `&gt;`), and when the help
  shows a default (`=60`), the value column mentions it.
- Every `--help` offers `-h,--help`, and the page's "Exit codes" table gives, for each code of
  the `exit codes:` line of `arbc --help`, a meaning that starts with the help's words.
"""
import re
import subprocess
import sys


def run_help(arbc, *command):
    proc = subprocess.run([arbc, *command, "--help"], capture_output=True, text=True, timeout=60)
    if proc.returncode != 0:
        raise SystemExit(f"arbc {' '.join(command)} --help exited {proc.returncode}")
    return proc.stdout


def parse_help_entries(text):
    """The entries of a CLI11 help's Positionals and Options lists: {name set: (description,
    default or None)}. CLI11 pads `  NAMES [TYPE][=DEFAULT]` to 30 columns and starts the
    description at column 30, or, when the names are longer, on the next line, indented by 30."""
    entries, section = {}, None
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        line = lines[i]
        i += 1
        if line in ("Positionals:", "Options:"):
            section = line
            continue
        if section is None or not line.strip():
            continue
        following = lines[i] if i < len(lines) else ""
        if re.match(r"^ {30}\S", following):
            spec, description = line.strip(), following.strip()
            i += 1
        else:
            spec, description = line[:30].strip(), line[30:].strip()
        names = frozenset(spec.split(" ", 1)[0].split(","))
        d = re.search(r"=([^\s=]+)$", spec)
        entries[names] = (description, d.group(1) if d else None)
    return entries


def unescape(cell):
    return cell.replace("\\*", "*").replace("&lt;", "<").replace("&gt;", ">")


def sections(page):
    """{command: section text} for each `## `arbc CMD`` heading, and the text before them."""
    parts = re.split(r"^## `arbc (\w+)`\s*$", page, flags=re.M)
    return parts[0], {parts[i]: parts[i + 1] for i in range(1, len(parts), 2)}


def first_text_block(text):
    m = re.search(r"^```text\n(.*?)^```$", text, re.S | re.M)
    return m.group(1) if m else None


def table_rows(text):
    """Rows of the section's option table as (names, value, meaning)."""
    rows = []
    for line in text.split("\n"):
        if not line.startswith("| `"):
            continue
        cells = [c.strip() for c in line.strip()[1:-1].split("|")]
        if len(cells) != 3:
            raise SystemExit(f"a table row without 3 cells: {line!r}")
        names = frozenset(re.findall(r"`([^`]+)`", cells[0]))
        rows.append((names, cells[1], unescape(cells[2])))
    return rows


def check_command(arbc, command, section):
    problems = []
    help_text = run_help(arbc, command)
    lines = help_text.split("\n")
    usage = next(i for i, line in enumerate(lines) if line.startswith("Usage:"))
    head = "\n".join(lines[:usage + 1]) + "\n"
    if first_text_block(section) != head:
        problems.append(f"arbc {command}: the first text block is not the help's head:\n{head}")
    entries = parse_help_entries(help_text)
    if frozenset(["-h", "--help"]) not in entries:
        problems.append(f"arbc {command} --help does not offer -h,--help")
    entries.pop(frozenset(["-h", "--help"]), None)
    rows = {names: (value, meaning) for names, value, meaning in table_rows(section)}
    for names, (description, default) in entries.items():
        shown = ", ".join(sorted(names))
        if names not in rows:
            problems.append(f"arbc {command}: {shown} is in --help but not in docs/cli.md")
            continue
        value, meaning = rows[names]
        if meaning != description:
            problems.append(f"arbc {command}: {shown}: docs/cli.md says {meaning!r}, "
                            f"--help says {description!r}")
        if default is not None and default not in value:
            problems.append(f"arbc {command}: {shown}: the value column does not mention the "
                            f"default {default!r}")
    for names in rows:
        if names not in entries:
            problems.append(f"arbc {command}: {', '.join(sorted(names))} is in docs/cli.md but "
                            "not in --help")
    return problems


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    arbc = sys.argv[1]
    page_path = sys.argv[2] if len(sys.argv) > 2 else "docs/cli.md"
    page = open(page_path, encoding="utf-8").read()
    problems = []
    top = run_help(arbc)
    preamble, by_command = sections(page)
    if first_text_block(preamble) != top:
        problems.append(f"the page's first text block is not `arbc --help`:\n{top}")
    listed = re.findall(r"^  (\w+)\s", top.split("commands:\n", 1)[1].split("\n\n", 1)[0], re.M)
    if sorted(listed) != sorted(by_command):
        problems.append(f"commands in --help {sorted(listed)}, sections {sorted(by_command)}")
    codes = re.search(r"^exit codes: (.*)$", top, re.M).group(1)
    exit_rows = dict(re.findall(r"^\| (\d) \| (.*) \|$", page, re.M))
    for item in codes.split(", "):
        code, meaning = item.split(" ", 1)
        if not exit_rows.get(code, "").startswith(meaning):
            problems.append(f"exit code {code}: the table does not start with {meaning!r}")
    for command in listed:
        if command in by_command:
            problems += check_command(arbc, command, by_command[command])
    for p in problems:
        print(f"FAIL {p}")
    print(f"{page_path}: {len(listed)} commands, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
