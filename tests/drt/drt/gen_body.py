"""Random monitor bodies (docs/language.md#monitor-bodies): let, var, assignment, accept,
set / unset of the events monitors own, if / else if / else, emit, throttle, every; and
`script` rules with a small hand-written Lua monitor."""
from .spec import (BOOL, INT, FLOAT, STRING, U64, F32, Stmt, Expr, lit, name, fits, int_like,
                   is_numeric, assignable)
from .gen_expr import ExprGen

DURATIONS = ["1ms", "50ms", "100ms", "200ms", "250ms", "300ms", "0.5s", "1s", "1.5s"]


class BodyGen:
    def __init__(self, rng, consts, counter, avoid=()):
        self.rng = rng
        self.avoid = set(avoid)
        self.exprs = ExprGen(rng, consts, avoid)
        self.counter = counter  # shared: let/var names unique in the spec

    def fresh(self, prefix):
        self.counter[prefix] = self.counter.get(prefix, 0) + 1
        return f"{prefix}{self.counter[prefix]}"

    def body(self, msg, src_type, dst_type, events, must_emit, in_rule=True):
        """A body reading message `msg` of `src_type`, delivering `dst_type`; `events` are the
        declared events it may set or unset. Returns (statements, events it sets)."""
        r = self.rng
        env = {msg: src_type}
        stmts, sets = [], set()
        top_vars = {}
        if r.random() < 0.25:
            v = self.fresh("v")
            init = self.sized_init(env) if r.random() < 0.4 else None
            init = init or self.exprs.gen(r.choice([INT, FLOAT, BOOL]), {}, 1, pure=True)
            vt = promoted(init.ty)
            stmts.append(Stmt("var", v, init))
            top_vars[v] = vt
            env[v] = vt
        for _ in range(r.randint(0, 4)):
            stmts += self.statement(env, top_vars, dst_type, events, sets, depth=2, in_rule=in_rule)
        if r.random() < 0.2 and in_rule:
            stmts.insert(r.randint(0, len(stmts)), Stmt("throttle", duration=r.choice(DURATIONS)))
        if r.random() < 0.1 and events:
            e = r.choice(events)
            sets.add(e)
            every = Stmt("every", duration=r.choice(DURATIONS[3:]),
                         branches=[(None, [Stmt("set", e, duration=r.choice(["", "100ms"]))])])
            stmts.insert(0 if "every-late" in self.avoid else len(stmts), every)
        if must_emit or r.random() < 0.5:
            stmts.append(Stmt("emit", expr=self.exprs.gen(dst_type, env, 3)))
        return stmts, sets

    def sized_init(self, env):
        """A sized number of the message as a `var`'s first value: the var holds its promoted
        type (`var n = m.seq;` of an int32 is an int), so later assignments of ints fit."""
        if "sized" in self.avoid:
            return None
        want = (lambda t: is_numeric(t) and t not in (INT, FLOAT))
        msg = next(iter(env))
        if want(env[msg]):
            return name(env[msg], msg)
        return self.exprs.field_of(INT, env, 0, want)

    def statement(self, env, top_vars, dst_type, events, sets, depth, in_rule):
        r = self.rng
        roll = r.random()
        if roll < 0.25:
            n = self.fresh("l")
            t = r.choice([INT, FLOAT, BOOL, STRING] + [t for t in env.values()])
            e = self.exprs.gen(t, env, 3)
            env[n] = e.ty
            return [Stmt("let", n, e)]
        if roll < 0.5:
            return [Stmt("accept", expr=self.exprs.gen(BOOL, env, 3))]
        if roll < 0.6 and top_vars:
            v = r.choice(list(top_vars))
            e = self.exprs.gen(top_vars[v], env, 2)
            if not assignable(e.ty, top_vars[v]):
                # An int constant into a uint64 var is refused (type-mismatch, unlike `emit`):
                # add it to the var instead.
                e = Expr("bin", U64, [name(U64, v), e], "+")
            return [Stmt("assign", v, e)]
        if roll < 0.75 and events:
            e = r.choice(events)
            if e in sets and r.random() < 0.4:
                return [Stmt("unset", e)]
            sets.add(e)
            return [Stmt("set", e, duration=r.choice(["", "", "100ms", "0.5s", "1s"]))]
        if roll < 0.9 and depth > 0:
            branches = []
            for i in range(r.randint(1, 3)):
                cond = self.exprs.gen(BOOL, env, 2) if i == 0 or r.random() < 0.6 else None
                inner = dict(env)
                block = []
                for _ in range(r.randint(1, 2)):
                    block += self.statement(inner, top_vars, dst_type, events, sets, depth - 1,
                                            in_rule)
                branches.append((cond, block))
                if cond is None:
                    break
            return [Stmt("if", branches=branches)]
        if in_rule:
            return [Stmt("emit", expr=self.exprs.gen(dst_type, env, 3))]
        return []


def script_lua(rng, msg_type, events):
    """A hand-written monitor: accept on a condition of the message, set or unset an event
    (the proof treats it as opaque: docs/design.md#effective-guards)."""
    cond = "true"
    if is_numeric(msg_type):
        cond = rng.choice(["msg > 2", "msg <= 0.5", "msg ~= msg", "true"])
    elif msg_type == BOOL:
        cond = rng.choice(["msg", "not msg"])
    elif msg_type[0] == "string":
        cond = rng.choice(['#msg > 0', 'msg == "take"'])
    lines = ["-- A hand-written monitor of the differential test (tests/drt).",
             "PortMonitor.accept = function(msg)"]
    if events:
        e = rng.choice(events)
        lines.append(f'  if {cond} then PortMonitor.setEvent("{e}", 0.2) '
                     f'else PortMonitor.unsetEvent("{e}") end')
    lines.append(f"  return {cond}")
    lines.append("end")
    return "\n".join(lines) + "\n"


def constant_value(rng, ty):
    """A literal of a simple type."""
    if ty == INT:
        return lit(INT, rng.choice(["0", "2", "5"]))
    if ty == FLOAT:
        return lit(FLOAT, rng.choice(["0.5", "0.25", "1.0"]))
    if ty == BOOL:
        return lit(BOOL, "true")
    return lit(STRING, '"s"')


def promoted(t):
    """The type a `var` holds of a value of type t (sema_body.cc: sized numbers promote)."""
    return INT if int_like(t) else FLOAT if t == F32 else t


def guarded_emit(rng, msg, src_type, dst_type):
    """A body that accepts on a comparison of the message and emits it, with the predicate over
    `emitted` that the comparison makes true over the reals (for `assert ... -> P(emitted)`):
    rounding, NaN and wrapping are what can break it."""
    if src_type == U64 and dst_type == U64:
        return guarded_u64(rng, msg)
    if not fits(src_type, dst_type) or not is_numeric(src_type) or U64 in (src_type, dst_type):
        return None  # a uint64 `emitted` meets no float constant
    x = name(src_type, msg)
    roll = rng.random()
    if roll < 0.4:
        op, scaled, pred_op, c = rng.choice([(">", "6.0", ">", "2"), ("<=", "1.5", "<=", "0.5"),
                                             (">=", "1.0", ">", "0.3333333333333333")])
        lhs = Expr("bin", FLOAT, [x, lit(FLOAT, "3.0")], "*")
        cond = Expr("bin", BOOL, [lhs, lit(FLOAT, scaled)], op)
    elif int_like(src_type) and roll < 0.7:
        lhs = Expr("bin", INT, [x, lit(INT, "1")], "-")
        cond = Expr("bin", BOOL, [lhs, lit(INT, "0")], ">=")
        pred_op, c = ">", "0"
    else:
        pred_op, c = rng.choice([(">", "2"), ("<=", "0.5"), (">=", "0.25")])
        cond = Expr("not", BOOL, [Expr("bin", BOOL, [x, lit(FLOAT, c)],
                                       {">": "<=", "<=": ">", ">=": "<"}[pred_op])])
    body = [Stmt("accept", expr=cond), Stmt("emit", expr=x)]
    pred = Expr("bin", BOOL, [name(dst_type, "emitted"), lit(FLOAT, c)], pred_op)
    return body, pred


def guarded_u64(rng, msg):
    """A uint64 let through by an unsigned comparison, emitted as it is or plus one; the assert
    over `emitted` holds only if both the proof and the monitor compare unsigned and wrap at
    2^64 (x < 2^64 - 1 makes x + 1 > 0; x >= 2^63 is a uint64 above every int64)."""
    x = name(U64, msg)
    big = lit(U64, rng.choice(["9223372036854775808", "18446744073709551615"]))
    roll = rng.random()
    if roll < 0.4:
        cond = Expr("bin", BOOL, [x, big], ">=")
        body_value, pred = x, Expr("bin", BOOL, [name(U64, "emitted"), lit(INT, "5")], ">")
    elif roll < 0.7:
        cond = Expr("bin", BOOL, [x, lit(U64, "18446744073709551615")], "<")
        body_value = Expr("bin", U64, [x, lit(INT, "1")], "+")
        pred = Expr("bin", BOOL, [name(U64, "emitted"), lit(INT, "0")], ">")
    else:
        cond = Expr("bin", BOOL, [x, lit(INT, "10")], "<=")
        body_value = Expr("bin", U64, [x, lit(INT, "3")], "*")
        pred = Expr("bin", BOOL, [name(U64, "emitted"), lit(INT, "30")], "<=")
    return [Stmt("accept", expr=cond), Stmt("emit", expr=body_value)], pred
