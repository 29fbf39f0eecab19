#!/usr/bin/env python3
"""The paper's experiment split in two processes over DDS (docs/distributed.md).

W hosts the eight table_clean modules and the simulated world and mediates nothing; M hosts
nothing and mediates every module; both run `--transport dds --time-scale 10`. Each case
starts M, then W, and checks what each prints.

usage: split_run.py ARBC PLUGIN SPEC PROFILE CASE [SEEDS]
  CASE  a scenario (reachable, tool, human, mixed, perturbed): every seed ends with a clean
        table and 0 conflicts, and M ends cleanly on SIGTERM;
        kill-m: M is killed (SIGKILL) in the middle of a `mixed` run and started again; over
        shared memory, the new M must also take ports of its own, not the killed one's (a
        survivor still writes into the killed process's segments: dds/shm_participant_id.h);
        restart-m: the same with M ended by SIGTERM (it deletes its DDS entities first);
        kill-w: W is killed; M keeps running, reports the lapsed events, ends on SIGINT;
        signals: W and M each ended mid-run by SIGINT, then by SIGTERM: each exits, prints
        its counters, writes its trace and report and deletes its DDS entities;
        hosts: W and M on two "hosts", network namespaces joined by a veth pair, with DDS on
        UDP only (hosts_profile.xml: no shared memory, discovery by multicast), a `mixed`
        run per seed; skipped (exit 77) where namespaces cannot be made (needs root).
  SEEDS how many seeds (1..SEEDS) for a scenario (default 5).
Every run gets a DDS domain of its own (a lock file under /tmp holds it), and the profile
keeps DDS traffic on this machine, so parallel ctest runs do not see each other (in the
hosts case the namespaces keep it apart).
"""
import atexit
import json
import os
import re
import signal
import subprocess
import sys
import time

from dds_domain import Domain, environment, scratch_folder

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from proc_signals import wait_until_caught  # noqa: E402

SCALE = os.environ.get("ARBC_SPLIT_SCALE", "10")


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


class Split:
    def __init__(self, arbc, plugin, spec, profile):
        self.arbc, self.plugin, self.profile = arbc, plugin, profile
        self.dir = scratch_folder("arbc-dds-split-")
        built = subprocess.run([arbc, "build", spec, "-o", self.dir], capture_output=True, text=True)
        if built.returncode != 0:
            fail("arbc build: " + built.stdout + built.stderr)
        self.app = os.path.join(self.dir, "table_clean")
        self.state = os.path.join(self.dir, "M.memory.json")
        self.domain = Domain()
        self.env = environment(profile)
        self.prefix = {"W": [], "M": []}  # `ip netns exec NS` in the hosts case
        self.procs = []
        atexit.register(self.kill_leftovers)

    def kill_leftovers(self):
        """A failed check ends this script at once: take every process still running with it."""
        for p in self.procs:
            if p.poll() is None:
                p.kill()

    def start(self, role, extra):
        """Starts M or W; its trace and report go to self.files(role)."""
        trace, report = self.files(role)
        for f in (trace, report):
            if os.path.exists(f):
                os.remove(f)
        common = ["--transport", "dds", "--time-scale", SCALE, "--domain", str(self.domain.id),
                  "--wait-peers", "30", "--trace", trace, "--report", report]
        if role == "M":
            # Warned of, not failed: M outlives W, so LookAround's rate breaks once W has ended
            # (check_m_breaches allows only that).
            # --state: a restarted M goes on from what the last one delivered (a take whose put
            # is still to come; docs/runtime.md#a-mediator-that-restarts).
            words = [self.arbc, "run", self.app, "--host", "none", "--mediate", "all",
                     "--duration", "100000s", "--runtime-checks", "warn",
                     "--state", self.state] + common + extra
        else:
            words = [self.arbc, "run", self.app, "--plugin", self.plugin, "--host", "all",
                     "--mediate", "none", "--no-verify", "--duration", "3000s"] + common + extra
        proc = subprocess.Popen(self.prefix[role] + words, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, env=self.env)
        self.procs.append(proc)
        return proc

    def files(self, role):
        return os.path.join(self.dir, role + ".trace.jsonl"), os.path.join(self.dir, role + ".html")

    def check_files(self, role, what, interrupted, *outputs):
        """The trace of `role` is JSON lines and its report was written (as interrupted)."""
        trace, report = self.files(role)
        expect(os.path.exists(trace) and os.path.exists(report),
               f"{what}: {role} wrote no trace or no report", *outputs)
        lines = open(trace).read().splitlines()
        expect(len(lines) > 1, f"{what}: {role}'s trace is empty", *outputs)
        for line in lines:
            json.loads(line)  # every line is a JSON record (raises on a torn line)
        html = open(report).read()
        expect("</html>" in html, f"{what}: {role}'s report is not complete", *outputs)
        # The page has a row per DDS topic from the transport's status: every one of them
        # heard a peer (W and M publish to each other), and M received messages.
        expect("<h2>Transport</h2>" in html and '<table id="transport-topics">' in html,
               f"{what}: {role}'s report has no table of DDS topics", *outputs)
        rows = re.findall(r"<tr[^>]*><td><code>([^<]*)</code></td><td>([^<]*)</td><td><code>"
                          r"[^<]*</code></td><td>(read|written)</td><td>([^<]*)</td>"
                          r'<td class="n">\d+</td><td class="n">(\d*)</td>', html)
        expect(rows, f"{what}: {role}'s table of DDS topics has no rows", *outputs)
        unheard = [f"{topic} ({port})" for topic, port, _, heard, _ in rows if heard == "never"]
        expect(not unheard, f"{what}: {role}'s report says {unheard} never heard a peer",
               *outputs)
        expect(any(int(received or 0) > 0 for *_, received in rows),
               f"{what}: {role}'s report counts nothing received on any topic", *outputs)
        expect(("interrupted" in html) == interrupted,
               f"{what}: {role}'s report {'does not say' if interrupted else 'says'} it was interrupted",
               *outputs)


def finish(proc, name, timeout):
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, _ = proc.communicate()
        fail(f"{name} did not end within {timeout} s:\n{out}")
    return proc.returncode, out


def stop(proc, name, sig=signal.SIGTERM):
    proc.send_signal(sig)
    return finish(proc, name, 15)


def expect(cond, message, *outputs):
    if not cond:
        fail(message + "".join("\n--- output ---\n" + o for o in outputs))


def alive(proc, message):
    """Fails with `message` and proc's output when proc has ended (its output is read only then)."""
    if proc.poll() is not None:
        fail(message + "\n--- output ---\n" + proc.communicate()[0])


def check_w(rc, out, what):
    expect(rc == 0, f"{what}: W exited {rc}", out)
    expect("conflicts: 0\n" in out, f"{what}: W counted conflicts", out)
    expect("stopped: table clean" in out, f"{what}: the table is not clean", out)


def check_m_stopped(rc, out, what, signame="SIGTERM"):
    expect(rc == 0, f"{what}: M exited {rc} after {signame}", out)
    expect(f"interrupted ({signame})" in out, f"{what}: M did not say it was interrupted", out)
    expect("result: success" in out, f"{what}: M did not end with its counters and result", out)
    expect("dds: domain" in out, f"{what}: M printed no transport summary", out)


def check_m_breaches(out, what):
    """M's runtime checks: every claim and assumption holds but LookAround's rate. That one is
    judged on arrival at M, where it breaks once W has ended (M outlives it), and at time
    scale 10 on a loaded machine its 100 ms of margin are 10 ms of wall time; a restarted M
    says again that the one before it saw it broken."""
    lines = out.split("runtime checks: ", 1)[1].splitlines() if "runtime checks: " in out else []
    expect(lines, f"{what}: M printed no runtime checks", out)
    for line in lines[1:]:
        if not line.startswith("  "):
            break
        # A restarted M reports again what the one before it found broken (its memory).
        expect(re.search(r"assumption given LookAround.gaze every \S+: (nothing from |broken "
                         r"before this mediator started again)", line),
               f"{what}: M broke a runtime check: {line}", out)


def scenario(split, name, seeds):
    for seed in range(1, seeds + 1):
        what = f"{name} seed {seed}"
        m = split.start("M", [])
        w = split.start("W", ["--scenario", name, "--seed", str(seed)])
        rc, out = finish(w, "W", 240)
        mrc, mout = stop(m, "M")
        check_w(rc, out, what)
        check_m_stopped(mrc, mout, what)
        check_m_breaches(mout, what)
        expect(not re.search(r"connection \S+ quarantined:", mout), f"{what}: M quarantined a connection", mout)
        split.check_files("W", what, False, out)
        split.check_files("M", what, True, mout)
        print(f"ok {what}: {out.splitlines()[0] if out else ''}")


def shm_ports(pid):
    """The Fast-DDS shared-memory ports process `pid` has mapped (segments still named)."""
    try:
        with open(f"/proc/{pid}/maps") as f:
            maps = f.read()
    except OSError:
        return set()
    return set(re.findall(r"/fastrtps_port(\d+)$", maps, re.M))


def expect_ports_of_its_own(m2, killed_ports, case):
    """Over shared memory, the restarted M maps a port the killed one did not: its own."""
    if not killed_ports:
        return  # no shared memory in this profile
    deadline = time.time() + 15
    while time.time() < deadline and not shm_ports(m2.pid) - killed_ports:
        time.sleep(0.1)
    new = shm_ports(m2.pid)
    expect(new - killed_ports, f"{case}: the restarted M took the killed M's shared-memory ports "
           f"again ({sorted(new)} of {sorted(killed_ports)}); W may write into the old segments")


def restart_m(split, sig, case):
    """M ended by `sig` in the middle of a `mixed` run and started again; W finishes the run."""
    m = split.start("M", [])
    w = split.start("W", ["--scenario", "mixed", "--seed", "3"])
    time.sleep(2.0)  # about 20 s of the run's time: mid-way through `mixed` (about 45 s)
    alive(w, f"W ended before M was stopped by {sig.name}")
    killed_ports = shm_ports(m.pid) if sig == signal.SIGKILL else set()
    m.send_signal(sig)
    m.wait()
    time.sleep(0.5)
    m2 = split.start("M", [])
    expect_ports_of_its_own(m2, killed_ports, case)
    try:
        # A run takes about 8 s; well within this limit even on a loaded machine.
        out, _ = w.communicate(timeout=120)
        rc = w.returncode
    except subprocess.TimeoutExpired:
        for p in (w, m2):
            p.kill()
        out, mout = w.communicate()[0], m2.communicate()[0]
        fail(f"{case}: W did not end within 120 s of M's restart\n--- W ---\n{out}\n--- M ---\n{mout}")
    mrc, mout = stop(m2, "M (restarted)")
    expect("restored the memory in " + split.state in mout,
           f"{case}: the restarted M did not restore the killed one's memory", mout)
    check_w(rc, out, case)
    check_m_stopped(mrc, mout, case)
    check_m_breaches(mout, case)
    expect("conflicts: 0" in out, f"{case}: conflicts after the restart", out)
    split.check_files("M", f"{case} (restarted M)", True, mout)
    print(f"ok {case}: W survived M's {sig.name}; the restarted M finished the run\n" + out + mout)


def kill_w(split):
    m = split.start("M", [])
    w = split.start("W", ["--scenario", "mixed", "--seed", "2"])
    time.sleep(2.0)
    alive(w, "W ended early")
    w.send_signal(signal.SIGKILL)
    w.wait()
    # Past every lifetime of table_clean's events at time scale 10, and past DDS's lease of a
    # participant that vanished without a word (3 wall seconds, DdsOptions::lease_seconds).
    time.sleep(5.0)
    alive(m, "M ended when W was killed")
    mrc, mout = stop(m, "M", signal.SIGINT)
    check_m_stopped(mrc, mout, "kill-w", "SIGINT")
    check_m_breaches(mout, "kill-w")
    expect(" lapsed at " in mout and "nothing from" in mout, "kill-w: M reported no lapse", mout)
    expect("has no publisher any more" in mout, "kill-w: M did not notice W's topics go", mout)
    # What each silence does here: the rules it fed get nothing, the events it fed lapse.
    for said in ["(PickAndPlace.status) has no publisher any more; e_arm_idle, e_taken are no "
                 "longer refreshed and lapse by their lifetimes",
                 "(ObjectDetector.objects) has no publisher any more; take into "
                 "PickAndPlace.cmd, pull into PullObject.cmd get nothing until one is back; "
                 "e_unreachable is no longer refreshed"]:
        expect(said in mout, "kill-w: M did not say what a silent topic does: " + said, mout)
    split.check_files("M", "kill-w", True, mout)
    print("ok kill-w: M kept running and reported the lapsed events\n" + mout)


def signals(split):
    """Each process ends cleanly on each signal: W by SIGINT and M by SIGTERM, then the reverse."""
    for wsig, msig in ((signal.SIGINT, signal.SIGTERM), (signal.SIGTERM, signal.SIGINT)):
        what = f"W {wsig.name}, M {msig.name}"
        m = split.start("M", [])
        w = split.start("W", ["--scenario", "mixed", "--seed", "1"])
        wait_until_caught(w, wsig)
        wait_until_caught(m, msig)
        time.sleep(2.0)  # mid-run
        alive(w, f"{what}: W ended early")
        wrc, wout = stop(w, "W", wsig)
        # 3: the run ends before the table is clean, which the world reports as a failure.
        expect(wrc == 3, f"{what}: W exited {wrc} (expected 3: the table is not clean yet)", wout)
        expect(f"interrupted ({wsig.name})" in wout and "stopped: interrupted" in wout,
               f"{what}: W did not say it was interrupted", wout)
        expect("conflicts: 0" in wout, f"{what}: W counted conflicts", wout)
        expect("dds: domain" in wout and "input (mediated elsewhere)" in wout,
               f"{what}: W printed no counters or transport summary", wout)
        split.check_files("W", what, True, wout)
        mrc, mout = stop(m, "M", msig)
        check_m_stopped(mrc, mout, what, msig.name)
        check_m_breaches(mout, what)
        split.check_files("M", what, True, mout)
        print(f"ok {what}: both ended cleanly")


class Hosts:
    """Two network namespaces, W's and M's, joined by a veth pair (10.231.0.1 and .2/24), each
    with a multicast route on its end so that DDS discovers the other side by itself."""

    def __init__(self):
        tag = str(os.getpid())
        self.ns = {"W": "arbc-w-" + tag, "M": "arbc-m-" + tag}
        self.dev = {"W": "aw" + tag, "M": "am" + tag}  # interface names: 15 characters at most
        made = subprocess.run(["ip", "netns", "add", self.ns["W"]], capture_output=True, text=True)
        if made.returncode != 0:
            print("SKIP: cannot create a network namespace (root is needed): " + made.stderr.strip())
            sys.exit(77)
        atexit.register(self.remove)
        self.ip("netns", "add", self.ns["M"])
        self.ip("link", "add", self.dev["W"], "type", "veth", "peer", "name", self.dev["M"])
        for role, address in (("W", "10.231.0.1/24"), ("M", "10.231.0.2/24")):
            ns, dev = self.ns[role], self.dev[role]
            self.ip("link", "set", dev, "netns", ns)
            self.ip("-n", ns, "addr", "add", address, "dev", dev)
            self.ip("-n", ns, "link", "set", "lo", "up")
            self.ip("-n", ns, "link", "set", dev, "up")
            self.ip("-n", ns, "route", "add", "224.0.0.0/4", "dev", dev)

    def ip(self, *words):
        done = subprocess.run(["ip"] + list(words), capture_output=True, text=True)
        expect(done.returncode == 0, "ip " + " ".join(words) + ": " + done.stderr.strip())

    def remove(self):
        for ns in self.ns.values():  # the veth pair goes with its namespaces
            subprocess.run(["ip", "netns", "del", ns], capture_output=True)

    def packets(self, role):
        """(received, sent) packets on role's end of the veth pair."""
        shown = subprocess.run(["ip", "-n", self.ns[role], "-j", "-s", "link", "show", self.dev[role]],
                               capture_output=True, text=True)
        stats = json.loads(shown.stdout)[0]["stats64"]
        return stats["rx"]["packets"], stats["tx"]["packets"]


def hosts(split, hosts_profile, seeds):
    """`mixed` with W and M on two hosts: nothing but the veth pair carries their DDS traffic
    (no shared memory in the profile, and neither sees the other's loopback)."""
    net = Hosts()
    split.env = environment(hosts_profile)
    split.prefix = {role: ["ip", "netns", "exec", ns] for role, ns in net.ns.items()}
    scenario(split, "mixed", seeds)
    received, sent = net.packets("W")
    # A mixed run is hundreds of samples each way, besides discovery.
    expect(received > 200 and sent > 200, f"hosts: W's veth carried {received} in, {sent} out")
    print(f"ok hosts: W's end of the veth pair received {received} and sent {sent} packets")


def main():
    if len(sys.argv) < 6:
        print(__doc__)
        sys.exit(2)
    arbc, plugin, spec, profile, case = sys.argv[1:6]
    seeds = int(sys.argv[6]) if len(sys.argv) > 6 else 5
    split = Split(arbc, plugin, spec, profile)
    if case == "kill-m":
        restart_m(split, signal.SIGKILL, case)
    elif case == "restart-m":
        restart_m(split, signal.SIGTERM, case)
    elif case == "kill-w":
        kill_w(split)
    elif case == "signals":
        signals(split)
    elif case == "hosts":
        hosts(split, os.path.join(os.path.dirname(os.path.abspath(__file__)), "hosts_profile.xml"), seeds)
    else:
        scenario(split, case, seeds)


if __name__ == "__main__":
    main()
