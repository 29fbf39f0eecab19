"""Regression cases (tests/drt/cases/NAME/, tests/drt/open/NAME/): a shrunk spec (`app.spec`,
and `spec.json`, the structure the claims read), its hand-written scripts, the inputs of the run
that disagreed (`inputs.jsonl`, with `end`, the instant the run was observed to), and a
one-line README saying what disagreed. `run_case` judges the spec on those inputs again."""
import dataclasses
import json
import os
import random
from decimal import Decimal

from . import spec as S
from .inputs import write_inputs, exact_time

CLASSES = {c.__name__: c for c in (S.Expr, S.Stmt, S.Rule, S.Arbitrate, S.Connect, S.Module,
                                     S.Decl, S.Spec)}


def to_obj(x):
    if dataclasses.is_dataclass(x):
        d = {"_": type(x).__name__}
        for f in dataclasses.fields(x):
            d[f.name] = to_obj(getattr(x, f.name))
        return d
    if isinstance(x, tuple):
        return {"_t": [to_obj(v) for v in x]}
    if isinstance(x, list):
        return [to_obj(v) for v in x]
    if isinstance(x, dict):
        return {k: to_obj(v) for k, v in x.items()}
    return x


def from_obj(x):
    if isinstance(x, list):
        return [from_obj(v) for v in x]
    if isinstance(x, dict):
        if "_t" in x:
            return tuple(from_obj(v) for v in x["_t"])
        if "_" in x:
            cls = CLASSES[x["_"]]
            return cls(**{k: from_obj(v) for k, v in x.items() if k != "_"})
        return {k: from_obj(v) for k, v in x.items()}
    return x


def save_case(root, spec, inputs, breach, index):
    """Writes the case under root/<claim>-<index>/ and returns the folder."""
    folder = os.path.join(root, f"{breach.claim}-{index}")
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "app.spec"), "w") as f:
        f.write(spec.text())
    for name, text in spec.scripts.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
    with open(os.path.join(folder, "spec.json"), "w") as f:
        json.dump(to_obj(spec), f, indent=1, ensure_ascii=False)
    if inputs:
        msgs, end = inputs
        write_inputs(os.path.join(folder, "inputs.jsonl"), msgs)
        with open(os.path.join(folder, "end"), "w") as f:
            f.write(f"{end}\n")
    with open(os.path.join(folder, "README"), "w") as f:
        f.write(f"[{breach.claim}] {breach.what}: {breach.detail}".replace("\n", " ")[:900] +
                (f" [needs {breach.needs}]" if breach.needs else "") + "\n")
    return folder


def load_case(folder):
    with open(os.path.join(folder, "spec.json")) as f:
        spec = from_obj(json.load(f))
    inputs = None
    path = os.path.join(folder, "inputs.jsonl")
    if os.path.exists(path):
        msgs = []
        with open(path) as f:
            for line in f:
                m = json.loads(line)
                m["t"] = exact_time(Decimal(repr(m["t"])))
                msgs.append(m)
        with open(os.path.join(folder, "end")) as f:
            end = Decimal(f.read().strip())
        inputs = (msgs, end)
    return spec, inputs


def run_case(oracle, folder, work):
    """The breaches of the case on today's arbc (none: it agrees)."""
    spec, inputs = load_case(folder)
    res = oracle.judge(spec, work, random.Random(0), 0 if inputs else 1, inputs)
    return res
