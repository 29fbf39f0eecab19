#!/usr/bin/env python3
"""Latency figures of `arbc lsp` on one spec, each a median over N edits (docs/benchmarks.md).

usage: lsp_latency.py ARBC SPEC N

Prints one JSON line per figure:
  lsp_diagnostics_latency_ms  a didChange that misspells (or restores) an event, until the
                              publishDiagnostics of that version arrives; baseline: a whole
                              `arbc check SPEC` process, timed N times in the same run.
  lsp_hover_after_edit_ms     a hover sent right after a didChange, until its answer: the
                              longest a request waits on a keystroke (the server answers from
                              the analysis of the text just typed); baseline: the same hover
                              with no edit pending.
The server runs with --no-verify: the proof runs on its own thread on save and is not what a
keystroke waits for.
"""
import json
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "lsp"))
from lsp_client import LspClient, file_uri, position_of  # noqa: E402

WORD, TYPO = "e_arm_idle and e_pull_idle hold 1s {", "e_arm_idel and e_pull_idle hold 1s {"


def ms(seconds):
    return round(seconds * 1000, 2)


def figure(name, values, baseline):
    value, base = statistics.median(values), statistics.median(baseline)
    print(json.dumps({"name": name, "value": ms(value), "unit": "ms", "baseline": ms(base),
                      "ratio": round(value / base, 2), "max": ms(max(values))}))


def check_times(arbc, spec, n):
    times = []
    for _ in range(n):
        start = time.perf_counter()
        subprocess.run([arbc, "check", spec], stdout=subprocess.DEVNULL, check=True)
        times.append(time.perf_counter() - start)
    return times


def edit(client, uri, text, version):
    """Misspells the event on odd versions, restores it on even ones; the diagnostics expected."""
    start = position_of(text, WORD)
    end = dict(start, character=start["character"] + len("e_arm_idle"))
    client.change(uri, version, [{"range": {"start": start, "end": end},
                                  "text": "e_arm_idel" if version % 2 else "e_arm_idle"}])
    return 1 if version % 2 else 0


def main():
    arbc, spec, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
    text = open(spec, encoding="utf-8").read()
    uri = file_uri(spec)
    baseline_check = check_times(arbc, spec, n)
    diagnostics, hover_after_edit, hover_idle = [], [], []
    with LspClient([arbc, "lsp", "--no-verify"], stderr=subprocess.DEVNULL) as c:
        c.initialize(os.path.dirname(spec))
        c.open(uri, text)
        if c.wait_diagnostics(uri, version=1) != []:
            sys.exit(f"lsp_latency.py: {spec} is not clean")
        hover = {"textDocument": {"uri": uri}, "position": position_of(text, "take: from")}
        version = 1
        for _ in range(n):
            version += 1
            expected = edit(c, uri, text, version)
            start = time.perf_counter()
            got = c.wait_diagnostics(uri, version=version)
            diagnostics.append(time.perf_counter() - start)
            if len(got) != expected:  # the figure must time the real answer
                sys.exit(f"lsp_latency.py: version {version} got {len(got)} diagnostics")
            version += 1
            edit(c, uri, text, version)
            start = time.perf_counter()
            answer = c.request("textDocument/hover", hover)
            hover_after_edit.append(time.perf_counter() - start)
            if "**rule** `take`" not in answer["contents"]["value"]:
                sys.exit("lsp_latency.py: the hover after an edit is not take's")
            c.wait_diagnostics(uri, version=version)
            start = time.perf_counter()
            c.request("textDocument/hover", hover)
            hover_idle.append(time.perf_counter() - start)
        c.shutdown_and_exit()
    figure("lsp_diagnostics_latency_ms", diagnostics, baseline_check)
    figure("lsp_hover_after_edit_ms", hover_after_edit, hover_idle)


if __name__ == "__main__":
    main()
