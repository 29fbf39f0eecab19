#!/usr/bin/env python3
"""SIGINT and SIGTERM end `arbc run` within a second in every state (docs/reliability.md,
"A stuck monitor"), printing the counters so far and writing the trace and the report of an
interrupted run.

usage: check_interrupt.py ARBC TEST_PLUGIN CASE       (run from the repository root)

cases:
  pattern_sigterm   a monitor inside Lua's string.find (the pattern of issue 13) when SIGTERM
                    comes: the sandbox stops the match, the run ends normally as interrupted
  pattern_sigint    the same with SIGINT (Ctrl-C)
  stuck_plugin      plugin code that never returns (the test plugin's scenario "stuck"): the
                    watchdog names it, writes what there is and ends the process (exit 3)
"""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from proc_signals import wait_until_caught  # noqa: E402

LIMIT = 1.0  # seconds from the signal to the end of the process


def fail(what, out="", err=""):
    sys.exit(f"FAIL: {what}\n--- stdout\n{out}\n--- stderr\n{err}")


def interrupt(cmd, sig, after):
    """Starts cmd, sends sig `after` seconds after the run started (arbc handles the signal
    from then on: before, while it builds and proves the app, a signal ends the process as
    usual, and a slow start, under a sanitizer or a loaded machine, must not look like that);
    returns (exit code, seconds to exit, out, err)."""
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wait_until_caught(proc, sig)
    time.sleep(after)
    if proc.poll() is not None:
        out, err = proc.communicate()
        fail(f"arbc run ended before the signal (exit {proc.returncode})", out, err)
    sent = time.monotonic()
    proc.send_signal(sig)
    try:
        out, err = proc.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, err = proc.communicate()
        fail("arbc run ignored the signal for 30 s", out, err)
    return proc.returncode, time.monotonic() - sent, out, err


def check_outputs(out, err, trace, report, stop_words):
    if "connection" not in out or "arrived" not in out:
        fail("no counters on stdout", out, err)
    with open(trace) as f:
        text = f.read()
    if '"stop: interrupted' not in text or stop_words not in text:
        fail(f"the trace does not end as an interrupted run ({stop_words!r})", text[-2000:], err)
    with open(report) as f:
        html = f.read()
    if "interrupted" not in html:
        fail("the report does not say the run was interrupted", out, err)


def pattern_case(arbc, plugin, sig, name):
    with tempfile.TemporaryDirectory() as d:
        build = subprocess.run([arbc, "build", "tests/interrupt/stuck_pattern.spec", "-o", d],
                               capture_output=True, text=True, timeout=120)
        if build.returncode != 0:
            fail("arbc build failed", build.stdout, build.stderr)
        trace, report = os.path.join(d, "trace.jsonl"), os.path.join(d, "report.html")
        code, seconds, out, err = interrupt(
            [arbc, "run", os.path.join(d, "stuck_pattern"), "--plugin", plugin, "--duration",
             "10min", "--trace", trace, "--report", report], sig, 1.5)
        if seconds > LIMIT:
            fail(f"arbc run took {seconds:.2f} s to end after {name}", out, err)
        if f"arbc run: interrupted ({name})" not in err:
            fail("stderr does not say the run was interrupted", out, err)
        if f"stopped: interrupted by {name}" not in out:
            fail(f"the run line does not say it was interrupted by {name}", out, err)
        if "string.find: work budget" not in err and ": interrupted" not in err:
            fail("no monitor error from the pattern", out, err)
        check_outputs(out, err, trace, report, '"stop: interrupted"')
        with open(report) as f:
            if f"interrupted by {name}" not in f.read():
                fail(f"the report does not name {name}", out, err)
        print(f"ok: ended {seconds:.3f} s after {name}, exit {code}")


def stuck_plugin_case(arbc, plugin):
    with tempfile.TemporaryDirectory() as d:
        trace, report = os.path.join(d, "trace.jsonl"), os.path.join(d, "report.html")
        code, seconds, out, err = interrupt(
            [arbc, "run", "runtime/testdata/pingpong", "--plugin", plugin, "--scenario", "stuck",
             "--trace", trace, "--report", report], signal.SIGINT, 1.0)
        if seconds > LIMIT:
            fail(f"arbc run took {seconds:.2f} s to end after SIGINT", out, err)
        if code != 3:
            fail(f"exit {code}, expected 3", out, err)
        words = "module 'Arm', in on_delivery is still running"
        if words not in err or "plugin code cannot be stopped" not in err:
            fail("stderr does not name the stuck callback", out, err)
        # The wait as the spec writes times (600ms), as the monitor's budget beside it is.
        if not re.search(r"is still running \d+(\.\d+)?m?s after the interrupt", err):
            fail("the wait is not written as a duration (600ms)", out, err)
        if "result: interrupted (the run did not finish)" not in out:
            fail("no verdict for the unfinished run", out, err)
        check_outputs(out, err, trace, report, words)
        print(f"ok: ended {seconds:.3f} s after SIGINT, exit {code}")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    arbc, plugin, case = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
    if case == "pattern_sigterm":
        pattern_case(arbc, plugin, signal.SIGTERM, "SIGTERM")
    elif case == "pattern_sigint":
        pattern_case(arbc, plugin, signal.SIGINT, "SIGINT")
    elif case == "stuck_plugin":
        stuck_plugin_case(arbc, plugin)
    else:
        sys.exit(__doc__)
