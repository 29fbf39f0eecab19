"""A campaign of the random differential test (docs/reliability.md#random-differential-testing):
random specs from a seed, each verified and run on random inputs until the time is up; every
disagreement shrunk and written as a case folder. The last line is exactly
`drt: N specs, M steps, K disagreements`.

usage: python3 -m drt.campaign ARBC [SECONDS] [SEED] [--out DIR] [--runs N] [--no-shrink]
"""
import argparse
import os
import random
import shutil
import sys
import tempfile
import time

from .gen_spec import SpecGen
from .oracle import Arbc, Oracle
from .shrink import shrink
from .cases import save_case


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("arbc")
    ap.add_argument("seconds", nargs="?", type=float, default=60)
    ap.add_argument("seed", nargs="?", type=int, default=38)
    ap.add_argument("--out", default=None, help="where to write the cases of disagreements found")
    ap.add_argument("--runs", type=int, default=4, help="runs (random inputs) per spec")
    ap.add_argument("--no-shrink", action="store_true")
    ap.add_argument("--shrink-seconds", type=float, default=180)
    ap.add_argument("--keep", action="store_true", help="keep the work folder")
    ap.add_argument("--specs", type=int, default=0, help="stop after this many specs (0: none)")
    ap.add_argument("--only", type=int, default=0, help="judge only spec number N of the seed")
    ap.add_argument("--avoid", default="", help="generator features to leave out (comma list)")
    ap.add_argument("--avoid-open", action="store_true",
                    help="leave out the features tests/drt/open/AVOID names (open bugs)")
    args = ap.parse_args(argv)
    avoid = set(filter(None, args.avoid.split(",")))
    if args.avoid_open:
        avoid |= open_features()
    oracle = Oracle(Arbc(os.path.abspath(args.arbc)), avoid=avoid)
    work = tempfile.mkdtemp(prefix="arbc-drt.")
    out_dir = args.out or os.path.join(work, "found")
    started = time.monotonic()
    deadline = started + args.seconds
    totals = {"specs": 0, "steps": 0, "rejected": 0, "timeouts": 0, "outside": 0, "unjudged": 0, "beyond_bound": 0,
              "skipped": 0, "disagreements": 0, "runs": 0}
    verdicts, rejected_ids, kinds = {}, {}, {}
    index = 0
    while time.monotonic() < deadline and not (args.specs and index >= args.specs):
        index += 1
        if args.only and index != args.only:
            if index > args.only:
                break
            continue
        rng = random.Random(f"{args.seed}/{index}")
        spec = SpecGen(rng, index, avoid).make()
        spec_work = os.path.join(work, f"spec{index}")
        res = oracle.judge(spec, spec_work, rng, args.runs)
        totals["specs"] += 1
        totals["steps"] += res.steps
        totals["runs"] += res.runs
        totals["timeouts"] += res.timeouts
        totals["outside"] += res.outside
        totals["unjudged"] += res.unjudged
        totals["beyond_bound"] += res.beyond_bound
        totals["skipped"] += res.skipped_values
        if res.rejected:
            totals["rejected"] += 1
            for i in res.rejected:
                rejected_ids[i] = rejected_ids.get(i, 0) + 1
            print(f"drt: spec {index} rejected by arbc check: {', '.join(res.rejected)} "
                  f"({spec_work}/app.spec)", flush=True)
        verdicts[res.verdict or "-"] = verdicts.get(res.verdict or "-", 0) + 1
        if res.breaches:
            totals["disagreements"] += 1
            report_found(args, oracle, spec, spec_work, res, out_dir, index, kinds)
    print(f"drt: seed {args.seed}, {time.monotonic() - started:.0f} s, {totals['runs']} runs"
          + (f", leaving out {', '.join(sorted(avoid))}" if avoid else "") + "; verdicts "
          + ", ".join(f"{k} {v}" for k, v in sorted(verdicts.items())))
    print(f"drt: rejected by arbc check: {totals['rejected']}"
          + (f" ({', '.join(f'{k} {v}' for k, v in sorted(rejected_ids.items()))})" if rejected_ids else ""))
    print(f"drt: timeouts: {totals['timeouts']}; decisions outside the claims' premises: "
          f"{totals['outside']}; breaches by lists longer than a bounded verdict claims: "
          f"{totals['beyond_bound']}; deliveries not judged (NaN or infinity in the trace): "
          f"{totals['unjudged']}; input values left out: "
          f"{totals['skipped']}")
    if kinds:
        print("drt: disagreements by claim: " + ", ".join(f"{k} {v}" for k, v in sorted(kinds.items())))
    if totals["disagreements"] or args.keep:
        print(f"drt: work folder kept: {work}")
    else:
        shutil.rmtree(work, ignore_errors=True)
    print(f"drt: {totals['specs']} specs, {totals['steps']} steps, "
          f"{totals['disagreements']} disagreements")
    return 1 if totals["disagreements"] else 0


def open_features():
    """The generator features tests/drt/open/AVOID names: `FEATURE CASE-FOLDER why` per line."""
    path = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "open", "AVOID")
    out = set()
    if os.path.exists(path):
        for line in open(path):
            line = line.split("#")[0].strip()
            if line:
                out.add(line.split()[0])
    return out


def report_found(args, oracle, spec, spec_work, res, out_dir, index, kinds):
    breach, inputs = res.breaches[0]
    for b, _ in res.breaches:
        kinds[b.claim] = kinds.get(b.claim, 0) + 1
    print(f"drt: DISAGREEMENT in spec {index} ({spec_work}): [{breach.claim}] {breach.what}: "
          f"{breach.detail}" + (f" [needs {breach.needs}]" if breach.needs else ""), flush=True)
    if args.no_shrink:
        return
    small, small_inputs, small_breach = shrink(oracle, spec, inputs, breach, spec_work,
                                               args.shrink_seconds)
    folder = save_case(out_dir, small, small_inputs, small_breach, index)
    print(f"drt: shrunk to {folder}: [{small_breach.claim}] {small_breach.detail}", flush=True)


if __name__ == "__main__":
    sys.exit(main())
