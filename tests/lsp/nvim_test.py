#!/usr/bin/env python3
"""Neovim (Debian's 0.7) with its built-in LSP client attached to `arbc lsp`, in a real
terminal (tmux): nvim_lsp.lua does the editing and checks; this script starts it, reads the
checks, and takes the screenshot (tmux capture-pane) that docs/editors.md shows.

usage: nvim_test.py ARBC SCREEN_OUT       (from the repository root; exit 77: skipped)
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.getcwd()
WIDTH, HEIGHT = 100, 34
DOC = os.path.join(ROOT, "docs", "editors.md")
BEGIN, END = "<!-- neovim screenshot: begin -->", "<!-- neovim screenshot: end -->"


def main():
    arbc, screen_out = os.path.abspath(sys.argv[1]), sys.argv[2]
    for tool in ("nvim", "tmux"):
        if not shutil.which(tool):
            print(f"SKIPPED: {tool} is not installed (scripts/install-deps.sh --test installs it)")
            return 77
    work = tempfile.mkdtemp(prefix="arbc-nvim-")
    spec = os.path.join(work, "table_clean.spec")
    shutil.copy(os.path.join(ROOT, "specs", "table_clean.spec"), spec)
    result, ready = os.path.join(work, "result.json"), os.path.join(work, "ready")
    socket = f"arbc-nvim-{os.getpid()}"
    env = dict(os.environ, ARBC=arbc, SPEC=spec, RESULT=result, READY=ready, TERM="xterm-256color")
    script = os.path.join(ROOT, "tests", "lsp", "nvim_lsp.lua")
    tmux = ["tmux", "-L", socket, "-f", "/dev/null"]
    subprocess.run(tmux + ["new-session", "-d", "-x", str(WIDTH), "-y", str(HEIGHT),
                           f"nvim --clean -n -i NONE -c 'set noruler noshowcmd laststatus=0' "
                           f"-c 'luafile {script}'"], env=env, check=True, timeout=30)
    try:
        deadline = time.monotonic() + 120
        while not os.path.exists(ready):
            if time.monotonic() > deadline:
                print("FAIL: nvim did not finish within 120 s; the screen:")
                print(capture(tmux))
                return 1
            time.sleep(0.2)
        time.sleep(0.5)  # the last redraw reaches the terminal
        screen = capture(tmux)
    finally:
        subprocess.run(tmux + ["kill-server"], timeout=30)
    with open(screen_out, "w", encoding="utf-8") as f:
        f.write(screen)
    failed = 0
    for r in json.load(open(result)):
        print(("ok   " if r["ok"] else "FAIL ") + r["name"])
        if not r["ok"]:
            print("     " + r["detail"].replace("\n", "\n     "))
            failed += 1
    failed += not check_doc(screen)
    print(f"{len(json.load(open(result))) + 1 - failed} passed, {failed} failed")
    return 1 if failed else 0


def capture(tmux):
    lines = subprocess.run(tmux + ["capture-pane", "-p"], capture_output=True, text=True,
                           timeout=30).stdout.split("\n")
    return "\n".join(l.rstrip() for l in lines).rstrip("\n") + "\n"


def check_doc(screen):
    """docs/editors.md shows this very screen between its markers."""
    text = open(DOC, encoding="utf-8").read()
    if BEGIN not in text or END not in text:
        print(f"FAIL docs/editors.md has no {BEGIN} ... {END} block")
        return False
    block = text.split(BEGIN, 1)[1].split(END, 1)[0]
    shown = block.strip("\n").removeprefix("```text\n").removesuffix("```").rstrip("\n") + "\n"
    if shown != screen:
        print("FAIL docs/editors.md's screenshot differs from the screen; the screen now:")
        print(screen)
        return False
    print("ok   docs/editors.md shows the screen")
    return True


if __name__ == "__main__":
    sys.exit(main())
