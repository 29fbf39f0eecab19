"""Shrinking a disagreement: smaller specs and inputs that still disagree the same way (the same
claim breached), one step at a time, until no step keeps it or the time is up. Steps: drop a
declaration, a rule, a statement, a message; replace an `if` by a branch, an expression by a
sub-expression or a literal of its type; drop a `when`, a hold, `by priority`. A step whose
spec `arbc check` refuses is simply not taken."""
import copy
import os
import random
import time

from .spec import Expr, Arbitrate, Connect, Decl, lit, BOOL, INT, FLOAT, STRING, SIZED, F32, is_fixed

LEAVES = {BOOL: ["true", "false"], INT: ["0", "1"], FLOAT: ["0.0", "1.0"], STRING: ['""'],
          **{t: (["0.0", "1.0"] if t == F32 else ["0", "1"]) for t in SIZED}}


def fit_inputs(spec, inputs):
    """The messages whose port the spec still has, with the same type."""
    if not inputs:
        return None
    msgs, end = inputs
    return [m for m in msgs if spec.port_type(m["port"]) is not None], end


def shrink(oracle, spec, inputs_file, breach, work, seconds):
    """(smaller spec, its inputs (messages, end) or None, the breach it still shows)."""
    inputs = read_inputs(inputs_file) if inputs_file else None
    deadline = time.monotonic() + seconds
    tries = [0]

    def still(cand_spec, cand_inputs):
        tries[0] += 1
        sub = os.path.join(work, f"shrink{tries[0]}")
        res = oracle.judge(cand_spec, sub, random.Random(0), 0, cand_inputs)
        hit = [b for b, _ in res.breaches if b.signature() == breach.signature()]
        return hit[0] if hit else None

    best = breach
    changed = True
    while changed and time.monotonic() < deadline:
        changed = False
        for cand_spec, cand_inputs in candidates(spec, inputs):
            if time.monotonic() > deadline:
                break
            if cand_inputs is not None and not cand_inputs[0]:
                continue
            b = still(cand_spec, fit_inputs(cand_spec, cand_inputs))
            if b:
                spec, inputs, best, changed = cand_spec, fit_inputs(cand_spec, cand_inputs), b, True
                break
    return spec, inputs, best


def read_inputs(path):
    """The messages and end of a run's inputs file (the end is in the file beside it)."""
    import json
    from decimal import Decimal
    from .inputs import exact_time
    msgs = []
    with open(path) as f:
        for line in f:
            m = json.loads(line)
            m["t"] = exact_time(Decimal(repr(m["t"])))
            msgs.append(m)
    end_path = path.replace(".jsonl", ".end")
    end = Decimal(open(end_path).read().strip()) if os.path.exists(end_path) else \
        (max((m["t"] for m in msgs), default=Decimal(0)) + 2)
    return msgs, end


def candidates(spec, inputs):
    """Smaller variants, biggest cuts first."""
    if inputs:
        msgs, end = inputs
        n = len(msgs)
        for size in (n // 2, n // 4, 1):
            if size < 1:
                continue
            for i in range(0, n, size):
                yield spec, (msgs[:i] + msgs[i + size:], end)
    for i in range(len(spec.decls)):
        s = copy.deepcopy(spec)
        del s.decls[i]
        yield s, inputs
    for i in range(len(spec.modules)):
        s = copy.deepcopy(spec)
        del s.modules[i]
        yield s, inputs
    for i, _ in enumerate(spec.consts):
        s = copy.deepcopy(spec)
        del s.consts[i]
        yield s, inputs
    yield from rule_steps(spec, inputs)
    yield from body_steps(spec, inputs)
    yield from expr_steps(spec, inputs)
    if inputs:
        yield from value_steps(spec, inputs)


def rule_steps(spec, inputs):
    for i, d in enumerate(spec.decls):
        if not isinstance(d, Arbitrate):
            continue
        for j, r in enumerate(d.rules):
            s = copy.deepcopy(spec)
            del s.decls[i].rules[j]
            yield s, inputs
            for attr, val in (("when", None), ("hold", ""), ("body", None)):
                if getattr(r, attr):
                    s = copy.deepcopy(spec)
                    setattr(s.decls[i].rules[j], attr, val)
                    yield s, inputs
        for flag in ("by_priority", "complete"):
            if getattr(d, flag):
                s = copy.deepcopy(spec)
                setattr(s.decls[i], flag, False)
                if flag == "by_priority":
                    for r in s.decls[i].rules:
                        r.hold = ""
                yield s, inputs


def bodies(spec):
    """(path to a statement list) for every body of the spec."""
    for i, d in enumerate(spec.decls):
        if isinstance(d, Arbitrate):
            for j, r in enumerate(d.rules):
                if r.body:
                    yield lambda s, i=i, j=j: s.decls[i].rules[j].body
        elif isinstance(d, Connect) and d.body:
            yield lambda s, i=i: s.decls[i].body


def stmt_lists(stmts):
    yield stmts
    for st in stmts:
        for _, block in st.branches:
            yield from stmt_lists(block)


def body_steps(spec, inputs):
    for get in bodies(spec):
        lists = list(stmt_lists(get(spec)))
        for li, stmts in enumerate(lists):
            for k, st in enumerate(stmts):
                s = copy.deepcopy(spec)
                target = list(stmt_lists(get(s)))[li]
                del target[k]
                yield s, inputs
                if st.kind == "if":
                    for b, (_, block) in enumerate(st.branches):
                        s = copy.deepcopy(spec)
                        target = list(stmt_lists(get(s)))[li]
                        target[k:k + 1] = target[k].branches[b][1]
                        yield s, inputs


def expr_slots(spec):
    """Setters and values of every expression slot (statements, `if` conditions, predicates)."""
    out = []
    for get in bodies(spec):
        for stmts in stmt_lists(get(spec)):
            for st in stmts:
                if st.expr is not None:
                    out.append(st.expr)
                out += [c for c, _ in st.branches if c is not None]
    for d in spec.decls:
        if isinstance(d, Decl):
            for key in ("pred", "when"):
                if isinstance(d.info.get(key), Expr):
                    out.append(d.info[key])
    return out


def subexprs(e):
    yield e
    for a in e.args:
        yield from subexprs(a)


def expr_steps(spec, inputs):
    n_slots = len(expr_slots(spec))
    for si in range(n_slots):
        nodes = list(subexprs(expr_slots(spec)[si]))
        for ni, node in enumerate(nodes):
            repls = [a for a in node.args if a.ty == node.ty and a.kind != "lambda"]
            repls += [lit(node.ty, t) for t in LEAVES.get(node.ty, []) if node.kind != "lit"]
            for rep in repls:
                s = copy.deepcopy(spec)
                target = list(subexprs(expr_slots(s)[si]))[ni]
                new = copy.deepcopy(rep)
                target.kind, target.ty, target.args, target.val = new.kind, new.ty, new.args, new.val
                if refresh_decls(s):
                    yield s, inputs


def refresh_decls(spec):
    """Reprints the declarations whose text holds an expression; False when an assert over data
    no longer reads `emitted` (it would be an assert over events: another claim)."""
    for d in spec.decls:
        if not isinstance(d, Decl):
            continue
        if d.kind == "derived":
            d.text = f"event {d.info['event']} = {d.info['source']} : {d.info['pred'].text()}" + \
                (f" for {d.info['for']}" if d.info["for"] else "") + ";"
        elif d.kind == "assert_data":
            if "emitted" not in d.info["pred"].text():
                return False
            d.text = f"assert {d.info['port']}: {d.info['rule']} -> {d.info['pred'].text()};"
        elif d.kind == "resource":
            w = d.info.get("when")
            d.text = f"resource {d.info['name']} {{ {', '.join(d.info['ports'])} }}" + \
                (f" when {w.text()}" if w is not None else "") + ";"
    return True


def value_steps(spec, inputs):
    msgs, end = inputs
    for i, m in enumerate(msgs):
        v = m["value"]
        simpler = []
        if isinstance(v, list) and v and not is_fixed(spec.port_type(m["port"]) or ("",)):
            simpler = [v[:len(v) // 2], v[1:]]  # a T[N]'s value keeps its N elements
        elif isinstance(v, (int, float)) and not isinstance(v, bool) and v not in (0, 1):
            simpler = [type(v)(0), type(v)(1)]
        elif isinstance(v, str) and v:
            simpler = [""]
        for new in simpler:
            c = copy.deepcopy(msgs)
            c[i]["value"] = new
            yield spec, (c, end)
