#!/usr/bin/env python3
"""Runs the commands shown in docs/tutorial.md and compares their output with the page (issue 9).

usage: run_tutorial.py BUILD_DIR [PAGE] [--keep]        (run from the repository root)

The page is read top to bottom:

- A ```sh block is a command block. Its text is run as one bash script (`bash -c`), in a
  scratch folder that stands for a fresh clone after `scripts/build.sh`: it holds `specs/` and
  `docs/` (copies from the repository) and `build` (a link to BUILD_DIR). Blocks run in page
  order in the same folder, so `out/` written by one block is there for the next.
- The fenced block right after a command block must be a ```text block: the expected output,
  stdout and stderr together (stderr is redirected into the same pipe as stdout).
- The script's exit status must be 0, or N when the command block is preceded by the HTML
  comment `<!-- exit: N -->`.
- `<!-- not run: REASON -->` before a command block skips it and needs no output block (only for
  the set-up steps that make BUILD_DIR itself: clone, build).
- A ```spec block preceded by `<!-- file: PATH -->` must be the file PATH, byte for byte, and
  with `<!-- file: PATH lines A-B -->` lines A to B of it (the page shows the real spec).

Normalisation, two narrow rules and nothing else:
- `arbc run SPEC` builds into a fresh temporary folder made by mkdtemp and prints its name; the
  test runs with TMPDIR=/tmp and writes the random part as on the page:
  `/tmp/arbc-run-XXXXXX/`.
- The scratch folder's absolute path, should an output show it, becomes `<scratch>`.
Timings are not normalised: the page shows only outputs without them (`arbc verify` without
--stats; `arbc run` in simulated time, which is deterministic for a seed).

Output order: the commands run on a pseudo-terminal, as in a user's shell (stdout is then
line-buffered), so lines written to stdout and stderr appear in the order a user sees them;
the terminal is 80x24, and its CR LF line ends are read as LF.

--keep leaves the scratch folder in place and prints its path. --update writes the actual
outputs into the page's ```text blocks, and the named files into its `file:` blocks, instead of
comparing (review the diff by eye).
"""
import difflib
import fcntl
import os
import re
import select
import shutil
import struct
import subprocess
import sys
import tempfile
import termios
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from markdown_blocks import fenced_blocks  # noqa: E402


def run_on_terminal(script, cwd, timeout=600):
    """Runs `bash -c script` with stdout and stderr on one pseudo-terminal; returns the exit
    status and what it printed."""
    master, slave = os.openpty()
    # A fixed 80x24 window, so that nothing depends on the size of the caller's terminal.
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 80, 0, 0))
    proc = subprocess.Popen(["bash", "-c", script], cwd=cwd, stdin=subprocess.DEVNULL,
                            stdout=slave, stderr=slave, env=dict(os.environ, TMPDIR="/tmp"))
    os.close(slave)
    chunks, deadline = [], time.monotonic() + timeout
    try:
        while time.monotonic() < deadline:
            ready, _, _ = select.select([master], [], [], 1.0)
            if not ready:
                if proc.poll() is not None:
                    break
                continue
            try:
                data = os.read(master, 65536)
            except OSError:  # EIO: the child side is closed
                break
            if not data:
                break
            chunks.append(data)
    finally:
        os.close(master)
    try:
        returncode = proc.wait(timeout=max(1.0, deadline - time.monotonic()))
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
        return -1, b"".join(chunks).decode("utf-8", "replace") + "\n[timed out]\n"
    return returncode, b"".join(chunks).decode("utf-8", "replace").replace("\r\n", "\n")


def normalise(output, scratch):
    output = re.sub(r"/tmp/arbc-run-[A-Za-z0-9]{6}/", "/tmp/arbc-run-XXXXXX/", output)
    return output.replace(scratch, "<scratch>")


def make_scratch(build_dir):
    scratch = tempfile.mkdtemp(prefix="arbc-tutorial-")
    for folder in ("specs", "docs"):
        shutil.copytree(folder, os.path.join(scratch, folder))
    os.symlink(os.path.abspath(build_dir), os.path.join(scratch, "build"))
    return scratch


def file_excerpt(note):
    """The text a `file: PATH [lines A-B]` annotation names, or None if it cannot be read."""
    m = re.fullmatch(r"file:\s*(\S+)(?:\s+lines\s+(\d+)-(\d+))?", note)
    if not m or not os.path.exists(m.group(1)):
        return None
    text = open(m.group(1), encoding="utf-8").read()
    if m.group(2):
        lines = text.split("\n")
        text = "\n".join(lines[int(m.group(2)) - 1:int(m.group(3))]) + "\n"
    return text


def check_file_block(where, note, body):
    text = file_excerpt(note)
    if text is None:
        return [f"{where}: cannot read the annotation '{note}' (or the file does not exist)"]
    if body != text:
        return [f"{where}: the block is not {note[len('file:'):].strip()}\n--- page\n{body}"
                f"--- file\n{text}"]
    return []


def main():
    args = [a for a in sys.argv[1:] if a not in ("--keep", "--update")]
    keep = "--keep" in sys.argv
    update = "--update" in sys.argv or bool(os.environ.get("ARBC_UPDATE_GOLDEN"))  # golden.py --bless
    if not args:
        sys.exit(__doc__)
    build_dir = args[0]
    page = args[1] if len(args) > 1 else "docs/tutorial.md"
    page_text = open(page, encoding="utf-8").read()
    items = list(fenced_blocks(page_text))
    updates = []  # (first line, last line) of a text block's body, and its new text
    scratch = make_scratch(build_dir)
    failures, commands = [], 0
    try:
        i = 0
        while i < len(items):
            line, tag, body, note, end = items[i]
            where = f"{page}:{line}"
            i += 1
            if tag == "spec" and note and note.startswith("file:"):
                if update and file_excerpt(note) is not None:
                    updates.append((line, end, file_excerpt(note)))
                else:
                    failures += check_file_block(where, note, body)
                continue
            if tag != "sh":
                continue
            if note and note.startswith("not run:"):
                continue
            want_exit = 0
            if note:
                m = re.fullmatch(r"exit:\s*(\d+)", note)
                if not m:
                    failures.append(f"{where}: cannot read the annotation '{note}'")
                    continue
                want_exit = int(m.group(1))
            if i >= len(items) or items[i][1] != "text":
                failures.append(f"{where}: a command block must be followed by a ```text block")
                continue
            expected, text_start, text_end = items[i][2], items[i][0], items[i][4]
            i += 1
            commands += 1
            returncode, raw = run_on_terminal(body, scratch)
            output = normalise(raw, scratch)
            if update:
                updates.append((text_start, text_end, output))
            elif output != expected:
                diff = difflib.unified_diff(expected.splitlines(True), output.splitlines(True),
                                            "page", "actual")
                failures.append(f"{where}: output differs from the page\n$ {body}"
                                + "".join(diff))
            if returncode != want_exit:
                failures.append(f"{where}: exit status {returncode}, the page says "
                                f"{want_exit}\n$ {body}{output}")
    finally:
        if keep:
            print(f"scratch folder: {scratch}")
        else:
            shutil.rmtree(scratch, ignore_errors=True)
    if update:
        lines = page_text.split("\n")
        for start, end, output in sorted(updates, reverse=True):
            lines[start:end - 1] = output.split("\n")[:-1] if output else []
        with open(page, "w", encoding="utf-8") as f:
            f.write("\n".join(lines))
        print(f"{page}: {len(updates)} output blocks written")
    for f in failures:
        print(f"FAIL {f}")
    print(f"{page}: {commands} command blocks, {len(failures)} failures")
    return 1 if failures or commands == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
