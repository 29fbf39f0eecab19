#!/usr/bin/env python3
"""Fixed-width numbers through an arbc mediator, bit for bit (issue 41, docs/language.md).

stamped_pub (fastddsgen types of interop/Stamped.idl, plain Fast-DDS) publishes ROS 2
TwistStampeds on rt/in/stamped and arbc_test Widths (a field of every width) on rt/in/widths,
at their types' edges; `arbc run stamped --host none --mediate all --deploy
stamped.deploy.json` passes them on to rt/out/stamped and rt/out/widths, where stamped_sub
prints what it receives. Both programs print each sample as one line of exact text
(interop/stamped_format.h: floats as their bits, integers in decimal at their own type, strings
as the hex of their bytes), and the lines must be equal, in order: a sample missing, altered or
extra fails, naming the sample and the field. The mediator's connection table must count every
sample delivered, none dropped, and its verdict must be success. The spec's Widths is checked
against interop/msg/arbc_test/msg/Widths.msg (--msg-path) before the run.

With SPEC and DEPLOY (in interop/), the same run for another spec of the same app: stamped_use.spec
declares both messages with `use ros2` from their .msg files (TwistStamped from arbc's built-in
definitions) and its deployment file maps no type: the wire names come from the definitions.

usage: stamped.py ARBC STAMPED_PUB STAMPED_SUB TESTS_DDS_DIR [SPEC DEPLOY]
"""
import difflib
import math
import os
import signal
import struct
import subprocess
import sys

from dds_domain import Domain, environment, scratch_folder

# Per message: the topic stamped_pub writes, the one stamped_sub reads, the DDS type, and the
# connection of stamped.spec between them (a `connect`, and an arbitrated port's one rule).
TOPICS = {"stamped": ("rt/in/stamped", "rt/out/stamped", "geometry_msgs::msg::dds_::TwistStamped_",
                      "from_Source_stamped"),
          "widths": ("rt/in/widths", "rt/out/widths", "arbc_test::msg::dds_::Widths_", "pass")}


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def fields(line):
    """A sample's line as its fields, {path: value}, in order."""
    return dict(token.partition("=")[::2] for token in line.split(" ")[1:])


def float_words(bits, width):
    """What a float's bits mean, for a person: NaNs with their kind, sign and payload."""
    exponent_bits = 8 if width == 32 else 11
    mantissa_bits = width - 1 - exponent_bits
    sign = "-" if bits >> (width - 1) else ""
    exponent = (bits >> mantissa_bits) & ((1 << exponent_bits) - 1)
    mantissa = bits & ((1 << mantissa_bits) - 1)
    if exponent == (1 << exponent_bits) - 1 and mantissa:
        quiet = mantissa >> (mantissa_bits - 1)
        payload = mantissa & ((1 << (mantissa_bits - 1)) - 1)
        return f"{sign}NaN, {'quiet' if quiet else 'signalling'}, payload {payload:#x}"
    value = struct.unpack("<f" if width == 32 else "<d",
                          bits.to_bytes(width // 8, "little"))[0]
    words = repr(value) if not math.isinf(value) else sign + "inf"
    return words + (", denormal" if exponent == 0 and mantissa else "")


def words(value):
    """A value of stamped_format.h's text, with what it means where the text does not say."""
    if value.startswith("f32:") or value.startswith("f64:"):
        return f"{value} ({float_words(int(value[4:], 16), int(value[1:3]))})"
    if value.startswith("str:"):
        text = bytes.fromhex(value[4:]).decode("utf-8", "replace")
        shown = text if len(text) <= 40 else text[:40] + "..."
        return f"{len(value[4:]) // 2} bytes {shown!r}"
    return value


def list_items(value):
    """The elements of a `[N:e0,e1,...]` value, or None for a value that is not a list."""
    if not value.startswith("["):
        return None
    body = value[1:-1].partition(":")[2]
    return body.split(",") if body else []


def field_differences(sent, received):
    """Each field whose value differs between two lines, said with both values."""
    a, b = fields(sent), fields(received)
    said = []
    for path in list(a) + [p for p in b if p not in a]:
        x, y = a.get(path), b.get(path)
        if x == y:
            continue
        if x is None or y is None:
            said.append(f"field {path} {'not sent' if x is None else 'not received'}")
            continue
        xs, ys = list_items(x), list_items(y)
        if xs is not None and ys is not None:
            if len(xs) != len(ys):
                said.append(f"field {path}: sent {len(xs)} elements, received {len(ys)}")
                continue
            differ = [i for i in range(len(xs)) if xs[i] != ys[i]]
            k = differ[0]
            x, y = xs[k], ys[k]
            path = f"{path}[{k}] ({len(differ)} of its {len(xs)} elements differ, the first)"
        said.append(f"field {path}: sent {words(x)}, received {words(y)}")
    return said or [f"the line differs: sent {sent[:200]!r}, received {received[:200]!r}"]


def compare(kind, sent, received):
    """What differs between the lines sent and received on one topic (empty when none)."""
    out_topic = TOPICS[kind][1]
    problems = []
    matcher = difflib.SequenceMatcher(None, sent, received, autojunk=False)
    for op, i1, i2, j1, j2 in matcher.get_opcodes():
        if op == "equal":
            continue
        pairs = min(i2 - i1, j2 - j1) if op == "replace" else 0
        for k in range(pairs):
            diff = "; ".join(field_differences(sent[i1 + k], received[j1 + k]))
            problems.append(f"{out_topic}: sample {i1 + k + 1} of {len(sent)} altered: {diff}")
        for k in range(i1 + pairs, i2):
            problems.append(f"{out_topic}: sample {k + 1} of {len(sent)} missing (never received)")
        for k in range(j1 + pairs, j2):
            problems.append(f"{out_topic}: extra sample received (not sent): "
                            f"{received[k][:200]}")
    return problems


def by_kind(output):
    lines = {kind: [] for kind in TOPICS}
    for line in output.splitlines():
        kind = line.split(" ", 1)[0]
        if kind in lines:
            lines[kind].append(line)
    return lines


def connection_rows(mediated):
    """The mediator's connection table: {connection: {column: count}}."""
    lines = mediated.splitlines()
    start = next((i for i, line in enumerate(lines) if line.startswith("connection ")), None)
    if start is None:
        fail("the mediator printed no connection table", mediated)
    columns = lines[start].split()[1:]
    rows = {}
    for line in lines[start + 1:]:
        cells = line.split()
        if len(cells) < len(columns) + 1 or not all(c.isdigit() for c in cells[1:len(columns) + 1]):
            break
        rows[cells[0]] = dict(zip(columns, map(int, cells[1:len(columns) + 1])))
    return rows


def check_mediator(mediated, returncode, sent):
    """Every sample read, decoded, delivered and written by the mediator, none dropped (as
    bad-type above all: a sample that does not decode as the spec's type), a clean end on
    SIGTERM and a success."""
    rows = connection_rows(mediated)
    if sorted(rows) != sorted(t[3] for t in TOPICS.values()):
        fail(f"the mediator ran connections {sorted(rows)}, not one per message", mediated)
    for kind, (in_topic, out_topic, wire_type, connection) in TOPICS.items():
        n = len(sent[kind])
        row = rows[connection]
        dropped = {c: k for c, k in row.items() if c not in ("arrived", "delivered") and k}
        if row["arrived"] != n or row["delivered"] != n or dropped:
            fail(f"connection {connection}: {n} sent, {row['arrived']} arrived, "
                 f"{row['delivered']} delivered; dropped, pending or failed: {dropped}", mediated)
        for line in (f"read  {in_topic} ({wire_type}): {n} received, 0 lost, 0 undecodable",
                     f"wrote {out_topic} ({wire_type}): {n} written"):
            if line not in mediated:
                fail(f"the mediator's dds: summary does not say {line!r}", mediated)
    if returncode != 0 or "interrupted (SIGTERM)" not in mediated:
        fail(f"the mediator did not end cleanly on SIGTERM (exit {returncode})", mediated)
    if "result: success" not in mediated:
        fail("the mediator's verdict is not success", mediated)


def run(arbc, pub, sub, here, domain, env, spec, deploy):
    """Builds the app, runs subscriber, mediator and publisher; their outputs."""
    out_dir = scratch_folder("arbc-dds-sized-types-")
    interop = os.path.join(here, "interop")
    msg_path = ["--msg-path", os.path.join(interop, "msg")]
    built = subprocess.run([arbc, "build", os.path.join(interop, spec), "-o", out_dir] + msg_path,
                           capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    receiver = subprocess.Popen([sub, domain, "4", "60"], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, env=env)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(out_dir, "stamped"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", os.path.join(interop, deploy)] + msg_path +
        ["--domain", domain,
         "--duration", "100000s", "--wait-peers", "30"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    sender = subprocess.run([pub, domain], capture_output=True, text=True, env=env, timeout=90)
    received, receiver_errors = receiver.communicate(timeout=90)
    mediator.send_signal(signal.SIGTERM)
    mediated, _ = mediator.communicate(timeout=30)
    if sender.returncode != 0:
        fail(f"stamped_pub exited {sender.returncode}", sender.stdout + sender.stderr, mediated)
    if receiver.returncode != 0:
        fail(f"stamped_sub exited {receiver.returncode}", receiver_errors, mediated)
    return sender.stdout, received, mediated, mediator.returncode


def main():
    arbc, pub, sub, here = sys.argv[1:5]
    spec, deploy = sys.argv[5:7] if len(sys.argv) > 5 else ("stamped.spec", "stamped.deploy.json")
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    sent_text, received_text, mediated, returncode = run(arbc, pub, sub, here, str(held.id), env,
                                                         spec, deploy)
    sent, received = by_kind(sent_text), by_kind(received_text)
    if not all(sent.values()):
        fail("stamped_pub printed no sample of some topic", sent_text)
    problems = [p for kind in TOPICS for p in compare(kind, sent[kind], received[kind])]
    for p in problems:
        print("FAIL: " + p)
    if problems:
        fail(f"{len(problems)} difference(s) between stamped_pub and stamped_sub", mediated)
    check_mediator(mediated, returncode, sent)
    counts = ", ".join(f"{len(v)} on {TOPICS[k][1]}" for k, v in sent.items())
    print(f"ok: every sample received bit for bit ({counts}), none dropped\n" + mediated)


if __name__ == "__main__":
    main()
