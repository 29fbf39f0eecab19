"""One spec through arbc: `check`, `verify --format json --counterexamples DIR`, `build
--no-verify`, then runs on the embedded runtime in simulated time (`run --inputs --trace`) and
`test --no-verify` of the written counterexamples; what the report claims (report_claims.py)
judged on each run by claims.py. The result lists the breaches: disagreements."""
import json
import os
import re
import shutil
import subprocess

from . import claims as C
from .inputs import InputGen, write_inputs, spec_durations
from .model import Model
from .report_claims import Claims
from .trace import Run

SANITIZER = re.compile(r"AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|runtime error:")


class Arbc:
    def __init__(self, path, timeout=60):
        self.path = path
        self.timeout = timeout

    def __call__(self, args, cwd=None, timeout=None):
        """(exit code, stdout, stderr); exit code None on a timeout."""
        try:
            p = subprocess.run([self.path] + args, cwd=cwd, capture_output=True, text=True,
                               timeout=timeout or self.timeout, errors="replace")
            return p.returncode, p.stdout, p.stderr
        except subprocess.TimeoutExpired:
            return None, "", ""


class Result:
    def __init__(self):
        self.rejected = None     # the check's error ids, when `arbc check` refused the spec
        self.breaches = []       # (Breach, inputs file or None)
        self.steps = 0           # messages published in runs
        self.runs = 0
        self.outside = 0         # decisions not judged: outside the claims' premises
        self.unjudged = 0        # deliveries whose value the trace cannot write
        self.beyond_bound = 0    # breaches by lists longer than a bounded verdict claims
        self.skipped_values = 0  # values the inputs file cannot carry
        self.timeouts = 0
        self.verdict = ""


def process_breach(what, rc, out, err, ok=(0, 1)):
    """A crash, a hang, an internal error, a sanitizer report, or an exit code the docs do not
    give (docs/cli.md#exit-codes)."""
    text = out + err
    if rc is None:
        return C.Breach("timeout", what, "no answer within the time limit")
    if rc < 0:
        return C.Breach("crash", what, f"killed by signal {-rc}: {err[-400:]}")
    if SANITIZER.search(err):
        return C.Breach("crash", what, f"sanitizer: {SANITIZER.search(err).group(0)}: {err[-400:]}")
    if "internal error" in text or "please report" in text:
        line = next((ln for ln in text.splitlines() if "internal error" in ln or "please report" in ln), "")
        return C.Breach("internal", what, line[:600])
    if rc not in ok:
        return C.Breach("crash", what, f"exit code {rc}: {(err or out)[-600:]}")
    return None


def write_spec(spec, work):
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "app.spec")
    with open(path, "w") as f:
        f.write(spec.text())
    for name, text in spec.scripts.items():
        with open(os.path.join(work, name), "w") as f:
            f.write(text)
    return path


class Oracle:
    def __init__(self, arbc, list_bound=4, temporal_bound=6, verify_timeout=10, avoid=()):
        self.arbc = arbc
        self.avoid = set(avoid)
        self.list_bound = list_bound
        self.temporal_bound = temporal_bound
        self.verify_timeout = verify_timeout

    def verify(self, spec, work, res):
        """The report, or None (the breach or the rejection is in res)."""
        path = write_spec(spec, work)
        rc, out, err = self.arbc(["check", path])
        if rc != 0:
            # The errors' ids: a warning printed beside them (lapsing-permission) rejected nothing.
            res.rejected = sorted(set(re.findall(r": error: .*\[([a-z][a-z0-9-]*)\]$", out + err,
                                                 re.M))) or [f"exit {rc}"]
            b = process_breach("arbc check", rc, out, err, ok=(0, 2))
            if b:
                res.breaches.append((b, None))
            return None
        cex = os.path.join(work, "cex")
        shutil.rmtree(cex, ignore_errors=True)
        rc, out, err = self.arbc(["verify", path, "--format", "json", "--counterexamples", cex,
                                  "--temporal-bound", str(self.temporal_bound),
                                  "--list-bound", str(self.list_bound),
                                  "--timeout", str(self.verify_timeout)], cwd=work,
                                 # --timeout bounds the run (the watchdog watches the
                                 # claim tests' context too, and a query that ignores it ends
                                 # the run 5 s later, unknown): 3x + 30 s is a hang.
                                 timeout=self.verify_timeout * 3 + 30)
        b = process_breach("arbc verify", rc, out, err)
        if b:
            res.breaches.append((b, None))
            res.timeouts += b.claim == "timeout"
            if b.claim != "internal":  # an internal error still leaves a report to judge by
                return None
        try:
            report = json.loads(out)
        except json.JSONDecodeError:  # an internal error that left no report: say so, go on
            res.breaches.append((C.Breach("internal", "arbc verify", f"exit {rc}, no JSON report: "
                                          f"{err.strip()[-600:]}"), None))
            return None
        res.verdict = report["verdict"]
        return report

    def build(self, work):
        out_dir = os.path.join(work, "out")
        rc, out, err = self.arbc(["build", os.path.join(work, "app.spec"), "--no-verify", "-o", out_dir])
        b = process_breach("arbc build --no-verify", rc, out, err, ok=(0,))
        if b:
            return None, b
        app = [d for d in os.listdir(out_dir)][0]
        return os.path.join(out_dir, app), None

    def sources(self, spec, model):
        """Every out-port a connection reads: port -> (type, status flags or None)."""
        flags = {d.info["port"]: list(d.info["flags"].values()) for d in spec.decls_of("feed")}
        inputs = {f"{m.name}.{p}" for m in spec.modules for d, p, _ in m.ports if d == "in"}
        out = {}
        for c in model.connections.values():
            if c.source in inputs:
                continue  # a delivery event's feed: the runtime runs it at each delivery
            out[c.source] = (spec.port_type(c.source), flags.get(c.source))
        return out

    def judge(self, spec, work, rng, runs, inputs=None):
        """Verify `spec`, run it `runs` times on random inputs (or once on `inputs`, a list of
        messages with its end), judge every run; a Result."""
        res = Result()
        report = self.verify(spec, work, res)
        if report is None:
            return res
        app_dir, b = self.build(work)
        if b:
            res.breaches.append((b, None))
            return res
        model = Model(os.path.join(app_dir, "app.json"))
        claims = Claims(report, spec, model, self.list_bound)
        gen = InputGen(rng, spec, self.sources(spec, model), self.list_bound, self.avoid)
        durations = spec_durations(spec.text())
        todo = [inputs] if inputs else [gen.make() for _ in range(runs)]
        for k, (msgs, end) in enumerate(todo):
            path = os.path.join(work, f"inputs{k}.jsonl")
            write_inputs(path, msgs)
            with open(path.replace(".jsonl", ".end"), "w") as f:
                f.write(f"{end}\n")
            self.run_one(app_dir, path, end, model, durations, claims, res, spec.port_type)
        res.skipped_values += gen.skipped
        self.replay(work, res)
        return res

    def run_one(self, app_dir, inputs, end, model, durations, claims, res, port_type):
        trace = inputs.replace(".jsonl", ".trace.jsonl")
        rc, out, err = self.arbc(["run", app_dir, "--no-verify", "--inputs", inputs, "--duration",
                                  f"{float(end) * 1000 + 1:.0f}ms", "--trace", trace])
        res.runs += 1
        b = process_breach("arbc run", rc, out, err, ok=(0, 3))
        if b:
            res.breaches.append((b, inputs))
            res.timeouts += b.claim == "timeout"
            return
        with open(trace) as f:
            run = Run(f.readlines(), model, durations, port_type)
        res.steps += sum(len(v) for v in run.publishes.values())
        for b in claims.judge(run, end, res):
            res.breaches.append((b, inputs))
        for b in claims.runtime_checks(out):  # the runtime's own checks: a second oracle
            res.breaches.append((b, inputs))

    def replay(self, work, res):
        """The counterexample tests `verify --counterexamples` wrote, each run as `arbc test` runs
        it. A file that states the claim it breaks (a property over time, a port's exclusivity,
        an assert: "kept as a regression" in its header) must fail on this app, its expectation
        unmet: the violation is real. A file that states what the
        broken app does must pass (docs/checks.md#temporal)."""
        cex = os.path.join(work, "cex")
        if not os.path.isdir(cex):
            return
        files = sorted(os.path.join(cex, f) for f in os.listdir(cex) if f.endswith(".test.spec"))
        for path in files:
            with open(path) as f:
                regression = "kept as a regression" in f.read()
            rc, out, err = self.arbc(["test", "--no-verify", path], cwd=work)
            b = process_breach("arbc test (counterexample)", rc, out, err, ok=(0, 1, 2))
            if not b and rc == 2:
                b = C.Breach("replay", "a counterexample `verify --counterexamples` wrote is "
                             "refused by `arbc test`", (out + err).strip().splitlines()[0][:600])
            elif not b and rc != (1 if regression else 0):
                what = ("passes on the app it came from (the violation did not show again)"
                        if regression else "fails under `arbc test` (it should show the violation)")
                b = C.Breach("replay", "a counterexample `verify --counterexamples` wrote " + what,
                             "\n".join(ln for ln in out.splitlines()
                                       if ln.startswith(("FAIL", "PASS", "  ")))[:800])
            if b:
                res.breaches.append((b, None))
