#!/usr/bin/env python3
"""The DDS figures (issue 15; docs/benchmarks.md#distributed-runs-over-dds-issue-15), one JSON line each.

  dds_direct_latency_us        dds_peer ping -> dds_peer echo -> dds_peer ping: two plain
                               Fast-DDS processes, round trip halved (median of COUNT round
                               trips; the figure is the median of REPS such runs)
  dds_mediated_latency_us      the same with an arbc mediator (latency.spec) in between both
                               ways: every request and every reply crosses a Lua monitor and an
                               arbitrated port (three processes); baseline the direct figure
  dds_mediated_latency_status_off_us
                               the same with the mediator's live status off
                               (--no-status-topics); dds_mediated_latency_us has it on, as a
                               mediator runs by default (issue 42: at most 5% slower with it)
  dds_mediated_throughput_msgs three sources (one dds_peer source process, three writers) into
                               one arbitrated port of an arbc mediator (throughput.spec, by
                               priority), read by dds_peer sink: messages the port decided per
                               second (arrived at the mediator / the sink's first-to-last span);
                               every message must arrive (reliable, keep-all / deep keep-last),
                               the mediator must count no drop, and the sink must receive
                               exactly what the mediator delivered ("delivered_msgs": their rate
                               at the sink); baseline one source writer straight into the sink
                               (no arbc), the same count

usage: dds_figures.py ARBC DDS_PEER   (environment: ARBC_ROOT, ARBC_BENCH_REPETITIONS)
"""
import json
import os
import re
import signal
import statistics
import subprocess
import sys
import tempfile

ROOT = os.environ["ARBC_ROOT"]
sys.path.insert(0, os.path.join(ROOT, "tests", "dds"))
from dds_domain import Domain, environment  # noqa: E402

HERE = os.path.join(ROOT, "bench", "dds")
REPS = int(os.environ.get("ARBC_BENCH_REPETITIONS", "5"))
COUNT, WARMUP = 2000, 200
PER_SOURCE = 5000
ENV = environment(os.path.join(ROOT, "tests", "dds", "loopback_profile.xml"))


def fail(message, *outputs):
    sys.stderr.write("dds_figures.py: " + message + "".join("\n--- output ---\n" + o for o in outputs) + "\n")
    sys.exit(1)


def start(words):
    return subprocess.Popen(words, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=ENV)


def finish(proc, what, timeout=120):
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        fail(what + " did not end", proc.communicate()[0])
    if proc.returncode != 0:
        fail(f"{what} exited {proc.returncode}", out)
    return out


class Bench:
    def __init__(self, arbc, peer):
        self.arbc, self.peer = arbc, peer
        self.domain = str(Domain().id)
        self.dir = tempfile.mkdtemp(prefix="arbc-dds-bench-")
        for spec in ("latency", "throughput"):
            built = subprocess.run([arbc, "build", os.path.join(HERE, spec + ".spec"), "-o", self.dir],
                                   capture_output=True, text=True)
            if built.returncode != 0:
                fail("arbc build " + spec, built.stdout + built.stderr)

    def mediator(self, app, status=True):
        return start([self.arbc, "run", os.path.join(self.dir, app), "--transport", "dds", "--host", "none",
                      "--mediate", "all", "--deploy", os.path.join(HERE, "bench.deploy.json"), "--domain",
                      self.domain, "--duration", "100000s"] + ([] if status else ["--no-status-topics"]))

    def stop(self, mediator):
        mediator.send_signal(signal.SIGTERM)
        out = finish(mediator, "the arbc mediator", 30)
        # Every connection's drop counters (monitor-error, quarantined, queue-full, bad-type,
        # lost-in-transit, errors) must be zero; not-selected is the arbitration's decision,
        # not a loss.
        for line in out.splitlines():
            cells = line.split()
            if len(cells) == 15 and cells[1].isdigit() and any(
                    cells[i] != "0" for i in (8, 9, 10, 11, 12, 14)):
                fail("the mediator dropped messages: " + line, out)
        return out

    def ping(self, out_topic, in_topic):
        echo = start([self.peer, "echo", self.domain, out_topic, in_topic, str(COUNT + WARMUP)])
        ping = start([self.peer, "ping", self.domain, out_topic, in_topic, str(COUNT), str(WARMUP)])
        got = finish(ping, "dds_peer ping")
        finish(echo, "dds_peer echo")
        m = re.search(r"median_one_way_us (\S+)", got)
        return float(m.group(1))

    def direct_latency(self):
        return self.ping("direct/req", "direct/rep")

    def mediated_latency(self, status=True):
        mediator = self.mediator("latency", status)
        # The client writes Client/req and reads Client/rep; the server (the echo) reads
        # Server/req and writes Server/rep; arbc carries each across.
        echo = start([self.peer, "echo", self.domain, "Server/req", "Server/rep", str(COUNT + WARMUP)])
        ping = start([self.peer, "ping", self.domain, "Client/req", "Client/rep", str(COUNT), str(WARMUP)])
        got = finish(ping, "dds_peer ping (mediated)")
        finish(echo, "dds_peer echo (mediated)")
        self.stop(mediator)
        return float(re.search(r"median_one_way_us (\S+)", got).group(1))

    def rate(self, sink_topic, source_topics, mediated, per_source=PER_SOURCE):
        """Messages per second at the sink (first to last), and through the arbitrated port."""
        total = per_source * len(source_topics)
        mediator = self.mediator("throughput") if mediated else None
        sink = start([self.peer, "sink", self.domain, sink_topic, str(total)])
        source = start([self.peer, "source", self.domain, str(per_source)] + source_topics)
        finish(source, "dds_peer source")
        got, _ = sink.communicate(timeout=120)  # exit 3 when fewer than `total` came
        m = re.search(r"received (\d+) of (\d+) in (\S+) s rate (\S+)", got)
        if not m:
            fail("the sink printed no count", got)
        received, span, rate = int(m.group(1)), float(m.group(3)), float(m.group(4))
        if not mediator:
            if received != total:
                fail("the sink did not receive every message", got)
            return rate, rate
        out = self.stop(mediator)
        # Every message arrived at the port and was decided; what was delivered reached the sink.
        rows = [l.split() for l in out.splitlines() if re.match(r"^[abc] +\d", l)]
        arrived = sum(int(r[1]) for r in rows)
        delivered = sum(int(r[2]) for r in rows)
        if arrived != total or delivered != received:
            fail(f"sent {total}, arrived {arrived}, delivered {delivered}, received {received}", out, got)
        return rate, arrived / span

def main():
    bench = Bench(sys.argv[1], sys.argv[2])
    direct, mediated, quiet, through, through_direct = [], [], [], [], []
    for _ in range(REPS):  # interleaved, so that a noisy moment hits both alike
        direct.append(bench.direct_latency())
        mediated.append(bench.mediated_latency())
        quiet.append(bench.mediated_latency(status=False))
        through_direct.append(bench.rate("flat/data", ["flat/data"], False, 3 * PER_SOURCE)[0])
        through.append(bench.rate("Sink/data", ["A/data", "B/data", "C/data"], True))
    d, m, q = statistics.median(direct), statistics.median(mediated), statistics.median(quiet)
    t = statistics.median(r[1] for r in through)
    td = statistics.median(through_direct)
    print(json.dumps({"name": "dds_direct_latency_us", "value": round(d, 1), "unit": "us",
                      "runs": [round(x, 1) for x in direct]}))
    print(json.dumps({"name": "dds_mediated_latency_us", "value": round(m, 1), "unit": "us",
                      "baseline": round(d, 1), "ratio": round(m / d, 2),
                      "runs": [round(x, 1) for x in mediated]}))
    print(json.dumps({"name": "dds_mediated_latency_status_off_us", "value": round(q, 1), "unit": "us",
                      "note": "dds_mediated_latency_us has the live status on; ratio = on / off",
                      "ratio": round(m / q, 3), "runs": [round(x, 1) for x in quiet]}))
    print(json.dumps({"name": "dds_mediated_throughput_msgs", "value": round(t), "unit": "msg/s",
                      "baseline": round(td), "ratio": round(t / td, 2),
                      "delivered_msgs": round(statistics.median(r[0] for r in through)),
                      "runs": [round(x[1]) for x in through]}))


if __name__ == "__main__":
    main()
