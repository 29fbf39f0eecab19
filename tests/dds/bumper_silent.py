#!/usr/bin/env python3
"""A bumper whose program never starts (issue 39, restarts and unknown events): the planner and
the base are plain Fast-DDS programs (tests/dds/interop/bumper.spec), the bumper's is absent.

1. As written, e_bumped stays unknown since the start: nav's `when not e_bumped` cannot hold, and
   the base receives nothing in RUN_SECONDS, with the mediator saying it never heard the bumper.
2. With `otherwise absent after 1s` on the event (docs/language.md#a-feed-that-may-fail-open),
   the mediator takes e_bumped as absent once the bumper has been silent for 1 s since its start,
   says so, and from then on the base receives the planner's commands; none before.
3. Written as a lock, `event e_bumped = lock Bumper.pressed timeout 500ms;`
   (docs/language.md#locks, issue 42 item 2): a lock whose publisher never starts keeps nav
   closed, past its timeout too, as in 1.

usage: bumper_silent.py ARBC INTEROP_STREAM INTEROP_SUB TESTS_DDS_DIR
"""
import os
import re
import subprocess
import sys
import tempfile
import threading
import time

from dds_domain import Domain, environment

RUN_SECONDS = 3.0
FAIL_OPEN_AFTER = 1.0


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def build(arbc, spec_text, out_dir):
    spec = os.path.join(out_dir, "bumper.spec")
    with open(spec, "w", encoding="utf-8") as f:
        f.write(spec_text)
    built = subprocess.run([arbc, "build", spec, "-o", out_dir], capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    return os.path.join(out_dir, "bumper")


def run(arbc, app, deploy, stream, sub, domain, env):
    """The base and the planner up first, then the mediator for RUN_SECONDS: what the mediator
    said, and the base's commands with the seconds since the mediator started."""
    base = subprocess.Popen([sub, domain, "2", str(RUN_SECONDS + 5)], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, env=env)
    lines = []  # (line, when it was read): the base prints and flushes each command it takes

    def read():
        for line in base.stdout:
            lines.append((line.strip(), time.monotonic()))

    reader = threading.Thread(target=read)
    reader.start()
    planner = subprocess.Popen([stream, domain, "20"], env=env)
    time.sleep(1.0)  # both matched by the time the mediator starts, as on a running robot
    started = time.monotonic()
    mediator = subprocess.Popen(
        [arbc, "run", app, "--transport", "dds", "--host", "none", "--mediate", "all",
         "--deploy", deploy, "--domain", domain, "--duration", f"{RUN_SECONDS}s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    said = mediator.communicate(timeout=60)[0]
    planner.kill()
    planner.wait()
    base.wait(timeout=60)
    reader.join()
    heard = "\n".join(line for line, _ in lines)
    commands = [(float(line), at - started) for line, at in lines[1:] if line]
    return said, heard, commands


def kept_closed(arbc, spec, tmp, deploy, stream, sub, domain, env):
    """1 and 3: with the bumper never heard, nothing reaches the base and the mediator says so."""
    said, heard, commands = run(arbc, build(arbc, spec, tmp), deploy, stream, sub, domain, env)
    if commands:
        fail(f"the base received {len(commands)} commands with the bumper never heard",
             said, heard)
    if "never heard a peer: rt/bumper (Bumper.pressed)" not in said:
        fail("the mediator does not say it never heard the bumper", said)
    # How many arrive depends on when discovery matched under load (25 of 150 on a loaded
    # CI host): some must, and every one that arrived was kept out.
    navs = re.search(r"read  rt/nav/cmd_vel \([^)]*\): (\d+) received", said)
    if not navs or int(navs.group(1)) < 5:
        fail("the mediator did not read the planner's commands (nothing was kept out)", said)
    row = next((ln.split() for ln in said.splitlines() if ln.startswith("nav ")), None)
    if not row or row[5] != row[1]:
        fail("not every command that arrived was kept out (not-selected)", said)


def main():
    arbc, stream, sub, here = sys.argv[1:5]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    interop = os.path.join(here, "interop")
    deploy = os.path.join(interop, "bumper.deploy.json")
    with open(os.path.join(interop, "bumper.spec"), encoding="utf-8") as f:
        closed = f.read()
    event = "event e_bumped = Bumper.pressed : pressed for 500ms;"
    assert event in closed
    opened = closed.replace(event, event[:-1] + f" otherwise absent after {FAIL_OPEN_AFTER:g}s;")
    locked = closed.replace(event, "event e_bumped = lock Bumper.pressed timeout 500ms;")

    with tempfile.TemporaryDirectory(prefix="arbc-dds-bumper-silent-") as tmp:
        for spec in (closed, locked):
            kept_closed(arbc, spec, tmp, deploy, stream, sub, domain, env)
        said, heard, commands = run(arbc, build(arbc, opened, tmp), deploy, stream, sub, domain,
                                    env)
        # Said at the first decision after 1 s (the next command from the planner); when is
        # the runtime's to say, under load too.
        if not re.search(r"event e_bumped taken as absent at [0-9.]+ m?s: nothing from "
                         r"Bumper.pressed since the start", said):
            fail("the mediator does not say it took e_bumped as absent after 1 s", said)
        # How many depends on when discovery matched under load (24 once, the first arriving at
        # 2.6 s with two test suites on the machine): some must, each delivered once it may be,
        # and none before 1 s (below).
        row = next((ln.split() for ln in said.splitlines() if ln.startswith("nav ")), None)
        if len(commands) < 5 or not row or int(row[2]) < 5:
            fail(f"the base received {len(commands)} commands once the bumper could fail open",
                 said, heard)
        # What arrived was delivered or kept out (not-selected: before the bumper's silence
        # counted), nothing else.
        if int(row[2]) + int(row[5]) != int(row[1]):
            fail("nav's commands were neither delivered nor kept out as unknown", said)
        first = min(at for _, at in commands)
        if first < FAIL_OPEN_AFTER:
            fail(f"a command reached the base {first:.3f} s after the mediator started, before "
                 "the bumper's silence could count as absence", said, heard)
    print(f"ok: nothing with the bumper unheard, fail closed and as a lock; {len(commands)} commands "
          f"from {first:.2f} s with `otherwise absent after {FAIL_OPEN_AFTER:g}s`")


if __name__ == "__main__":
    main()
