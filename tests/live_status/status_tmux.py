#!/usr/bin/env python3
"""`arbc run --status` in a real terminal (tmux, capture-pane), on the wall clock.

mux.spec puts a joystick over a planner by priority (a 2 s hold). The stand-ins publish
mux.inputs.jsonl: the planner every 100 ms, the joystick from 2 s to 2.4 s. The terminal must
show Base.cmd_vel's line with nav selected and the joystick not heard yet, then, on the same
screen row (redrawn in place, not scrolled), joy selected and nav held by joy's hold.

usage: status_tmux.py ARBC HERE       (exit 77: skipped)
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time

WIDTH, HEIGHT = 160, 20


def capture(tmux):
    out = subprocess.run(tmux + ["capture-pane", "-p"], capture_output=True, text=True,
                         timeout=30).stdout
    return [line.rstrip() for line in out.split("\n")]


def wait_for(tmux, text, seconds):
    """The screen's lines once some line holds `text`; None after `seconds`."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        screen = capture(tmux)
        if any(text in line for line in screen):
            return screen
        time.sleep(0.05)
    return None


def port_rows(screen):
    return [i for i, line in enumerate(screen) if line.startswith("Base.cmd_vel  ")]


def main():
    arbc, here = os.path.abspath(sys.argv[1]), sys.argv[2]
    if not shutil.which("tmux"):
        print("SKIPPED: tmux is not installed (scripts/install-deps.sh --test installs it)")
        return 77
    work = tempfile.mkdtemp(prefix="arbc-status-")
    built = subprocess.run([arbc, "build", os.path.join(here, "mux.spec"), "-o", work],
                           capture_output=True, text=True, timeout=120)
    if built.returncode != 0:
        print("FAIL: arbc build\n" + built.stdout + built.stderr)
        return 1
    inputs = os.path.join(here, "mux.inputs.jsonl")
    socket = "arbc-status-" + str(os.getpid())
    tmux = ["tmux", "-L", socket, "-f", "/dev/null"]
    command = (f"{arbc} run {os.path.join(work, 'mux')} --inputs {inputs} --realtime "
               f"--duration 6s --status; sleep 30")
    subprocess.run(tmux + ["new-session", "-d", "-x", str(WIDTH), "-y", str(HEIGHT), command],
                   env=dict(os.environ, TERM="xterm-256color"), check=True, timeout=30)
    try:
        first = wait_for(tmux, "nav selected", 30)
        second = wait_for(tmux, "joy selected", 10)
        end = wait_for(tmux, "result:", 15)
    finally:
        subprocess.run(tmux + ["kill-server"], capture_output=True, timeout=30)
        shutil.rmtree(work, ignore_errors=True)
    failures = []
    if not first or not second or not end:
        print("FAIL: the terminal did not show nav selected, then joy selected, then the end")
        print("\n".join(first or second or end or ["(no screen)"]))
        return 1
    nav_line = "Base.cmd_vel  OK  nav selected | joy: may deliver; nothing from Joy.cmd_vel yet"
    joy_line = "Base.cmd_vel  OK  joy selected | nav: held by joy's hold"
    for screen, line in ((first, nav_line), (second, joy_line)):
        rows = port_rows(screen)
        if len(rows) != 1:
            failures.append(f"the port's line is on {len(rows)} rows (drawn in place: one)")
        elif not screen[rows[0]].startswith(line):
            failures.append(f"row {rows[0]} reads\n  {screen[rows[0]]}\nnot\n  {line} ...")
    if port_rows(first) != port_rows(second):
        failures.append(f"the line moved from row {port_rows(first)} to {port_rows(second)}")
    for f in failures:
        print("FAIL: " + f)
    if failures:
        print("--- first screen ---\n" + "\n".join(first))
        print("--- second screen ---\n" + "\n".join(second))
        return 1
    print("ok: the line changed in place:\n  " + first[port_rows(first)[0]] + "\n  " +
          second[port_rows(second)[0]])
    return 0


if __name__ == "__main__":
    sys.exit(main())
