#!/usr/bin/env python3
"""Neovim (Debian's 0.7) with its built-in LSP client attached to `arbc lsp`, in a real
terminal (tmux), set up by the very init.lua docs/editors.md gives (with `arbc` on the PATH and
filetype detection turned on first, as plugin managers do): nvim_lsp.lua does the editing and
checks; this script starts it, reads the checks, takes the screenshot (tmux capture-pane) that
docs/editors.md shows, then quits nvim and checks that it and the server are gone.

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
    other = os.path.join(work, "face_filter.spec")
    shutil.copy(os.path.join(ROOT, "specs", "face_filter.spec"), other)
    init = os.path.join(work, "init.lua")
    with open(init, "w", encoding="utf-8") as f:
        f.write(doc_init_lua())
    bin_dir = os.path.join(work, "bin")  # `arbc` on the PATH, as the doc asks
    os.mkdir(bin_dir)
    os.symlink(arbc, os.path.join(bin_dir, "arbc"))
    result, ready = os.path.join(work, "result.json"), os.path.join(work, "ready")
    socket = f"arbc-nvim-{os.getpid()}"
    env = dict(os.environ, SPEC=spec, OTHER=other, RESULT=result, READY=ready,
               TERM="xterm-256color", PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""))
    script = os.path.join(ROOT, "tests", "lsp", "nvim_lsp.lua")
    tmux = ["tmux", "-L", socket, "-f", "/dev/null"]
    subprocess.run(tmux + ["new-session", "-d", "-x", str(WIDTH), "-y", str(HEIGHT), "-c", work,
                           f"nvim -u {init} --noplugin -n -i NONE "
                           f"--cmd 'filetype plugin indent on' "
                           f"-c 'set noruler noshowcmd laststatus=0' -c 'luafile {script}'"],
                   env=env, check=True, timeout=30)
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
        quit_checks = quit_nvim(tmux, result + ".pid")
    finally:
        subprocess.run(tmux + ["kill-server"], capture_output=True, timeout=30)
    with open(screen_out, "w", encoding="utf-8") as f:
        f.write(screen)
    failed = 0
    results = json.load(open(result)) + quit_checks
    for r in results:
        print(("ok   " if r["ok"] else "FAIL ") + r["name"])
        if not r["ok"]:
            print("     " + r["detail"].replace("\n", "\n     "))
            failed += 1
    failed += not check_doc(screen)
    print(f"{len(results) + 1 - failed} passed, {failed} failed")
    return 1 if failed else 0


def doc_init_lua():
    """The first Lua block of docs/editors.md's Neovim section: what a user puts in init.lua."""
    text = open(DOC, encoding="utf-8").read()
    section = text.split("## Neovim\n", 1)[1]
    return section.split("```lua\n", 1)[1].split("```", 1)[0]


def quit_nvim(tmux, pid_file):
    """`:qa!` as a person types it: nvim must exit promptly and take the server with it."""
    subprocess.run(tmux + ["send-keys", "Escape", ":qa!", "Enter"], timeout=30)
    deadline = time.monotonic() + 10
    while subprocess.run(tmux + ["has-session"], capture_output=True, timeout=30).returncode == 0:
        if time.monotonic() > deadline:
            return [{"name": "nvim exits on :qa!", "ok": False, "detail": capture(tmux)}]
        time.sleep(0.1)
    checks = [{"name": "nvim exits on :qa!", "ok": True, "detail": ""}]
    pid = int(open(pid_file).read()) if os.path.exists(pid_file) else None
    deadline = time.monotonic() + 10
    while pid and os.path.exists(f"/proc/{pid}") and time.monotonic() < deadline:
        time.sleep(0.1)
    gone = pid is not None and not os.path.exists(f"/proc/{pid}")
    checks.append({"name": "and the server is gone", "ok": gone, "detail": f"pid {pid}"})
    return checks


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
