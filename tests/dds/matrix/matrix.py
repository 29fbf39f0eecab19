#!/usr/bin/env python3
"""The ROS 2 message matrix through an arbc mediator, byte for byte (issue 41, "Done means").

For each message of messages.MATRIX (the issue's 20, and one of the test's own with bounded
sequences and strings and a fixed array of messages), the test writes its .msg file
(and those it uses) into a --msg-path folder, and a spec that declares it with `use ros2` and
passes it from Pub.mI to Sub.mI by a `connect` with no body. matrix_peer (fastddsgen types, no
arbc in it) publishes four samples of each at their types' edges (samples.py) on rt/in/mI; the
mediator (`arbc run --transport dds --host none --mediate all`) decodes each into the spec's
type and writes it on rt/out/mI, where a second matrix_peer receives it. Each program prints the
bytes of every sample as its own fastddsgen type serializes it; the bytes received must be the
bytes sent, in order. The mediator must count every sample delivered, none dropped or undecodable.

usage: matrix.py ARBC MATRIX_PEER TESTS_DDS_DIR
"""
import os
import signal
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))  # tests/dds: dds_domain, stamped

import messages  # noqa: E402
import samples  # noqa: E402
from dds_domain import Domain, environment, scratch_folder  # noqa: E402
from stamped import connection_rows  # noqa: E402


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o[-6000:] for o in outputs))
    sys.exit(1)


def spec_text():
    names = [full.split("/")[1] for full in messages.MATRIX]
    lines = ['app matrix "Pass ROS 2 messages from a program to another, unchanged.";']
    lines += [f"use ros2 {full.replace('/', '/msg/')};" for full in messages.MATRIX]
    lines.append('module Pub "a plain Fast-DDS publisher" {')
    lines += [f"  out m{i}: {name};" for i, name in enumerate(names)]
    lines.append("}")
    lines.append('module Sub "a plain Fast-DDS subscriber" {')
    lines += [f"  in m{i}: {name};" for i, name in enumerate(names)]
    lines.append("}")
    lines += [f"connect Pub.m{i} -> Sub.m{i};" for i in range(len(names))]
    return "\n".join(lines) + "\n"


def deploy_text():
    topics = []
    for i in range(len(messages.MATRIX)):
        topics += [f'"Pub.m{i}": "/in/m{i}"', f'"Sub.m{i}": "/out/m{i}"']
    return '{ "ros2": true, "topics": { ' + ", ".join(topics) + " } }\n"


def write_inputs(folder):
    """The spec, deployment, .msg files and samples; the --msg-path folder."""
    msg_dir = os.path.join(folder, "msg")
    messages.write_msg_files(msg_dir)
    for name, text in (("matrix.spec", spec_text()), ("matrix.deploy.json", deploy_text())):
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
    with open(os.path.join(folder, "samples.txt"), "w") as f:
        for i, full in enumerate(messages.MATRIX):
            for k in range(samples.SAMPLES):
                f.write(f"{i} {samples.sample(full, k).hex()}\n")
    return msg_dir


def run(arbc, peer, folder, msg_dir, domain, env):
    built = subprocess.run([arbc, "build", os.path.join(folder, "matrix.spec"), "-o",
                            os.path.join(folder, "out"), "--msg-path", msg_dir],
                           capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    receiver = subprocess.Popen([peer, "sub", domain, "5", "90"], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, env=env)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(folder, "out", "matrix"), "--transport", "dds", "--host",
         "none", "--mediate", "all", "--deploy", os.path.join(folder, "matrix.deploy.json"),
         "--msg-path", msg_dir, "--domain", domain, "--duration", "100000s", "--wait-peers", "30"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    sender = subprocess.run([peer, "pub", domain, os.path.join(folder, "samples.txt")],
                            capture_output=True, text=True, env=env, timeout=240)
    received, receiver_errors = receiver.communicate(timeout=240)
    mediator.send_signal(signal.SIGTERM)
    mediated, _ = mediator.communicate(timeout=30)
    if sender.returncode != 0:
        fail(f"matrix_peer pub exited {sender.returncode}", sender.stderr, mediated)
    if receiver.returncode != 0:
        fail(f"matrix_peer sub exited {receiver.returncode}", receiver_errors, mediated)
    return sender.stdout, received, mediated, mediator.returncode


def by_index(output, word):
    out = {i: [] for i in range(len(messages.MATRIX))}
    for line in output.splitlines():
        parts = line.split(" ")
        if len(parts) == 3 and parts[0] == word:
            out[int(parts[1])].append(parts[2])
    return out


def first_difference(a, b):
    """The first byte offset at which two hex strings differ (in the payload, after the
    4-byte encapsulation), and the bytes there."""
    x, y = bytes.fromhex(a), bytes.fromhex(b)
    k = next((i for i in range(min(len(x), len(y))) if x[i] != y[i]), min(len(x), len(y)))
    return (f"{len(x)} bytes sent, {len(y)} received; first difference at payload offset "
            f"{k - 4}: sent {x[k:k + 8].hex()}, received {y[k:k + 8].hex()}")


def compare(sent, received):
    problems = []
    for i, full in enumerate(messages.MATRIX):
        want = [samples.sample(full, k).hex() for k in range(samples.SAMPLES)]
        if sent[i] != want:
            problems.append(f"{full}: matrix_peer did not send the samples written (the test's "
                            "CDR and fastddsgen's disagree): " +
                            first_difference(want[0], sent[i][0] if sent[i] else ""))
            continue
        if len(received[i]) != len(sent[i]):
            problems.append(f"{full}: {len(sent[i])} samples sent, {len(received[i])} received")
            continue
        for k, (a, b) in enumerate(zip(sent[i], received[i])):
            if a != b:
                problems.append(f"{full}: sample {k} altered: {first_difference(a, b)}")
    return problems


def check_mediator(mediated, returncode):
    rows = connection_rows(mediated)
    if len(rows) != len(messages.MATRIX):
        fail(f"the mediator ran {len(rows)} connections, not {len(messages.MATRIX)}", mediated)
    for name, row in rows.items():
        dropped = {c: k for c, k in row.items() if c not in ("arrived", "delivered") and k}
        if row["arrived"] != samples.SAMPLES or row["delivered"] != samples.SAMPLES or dropped:
            fail(f"connection {name}: {row['arrived']} arrived, {row['delivered']} delivered; "
                 f"dropped, pending or failed: {dropped}", mediated)
    if " undecodable" in mediated and ", 0 undecodable" not in mediated:
        fail("the mediator could not decode some sample", mediated)
    if returncode != 0 or "result: success" not in mediated:
        fail(f"the mediator did not end in success (exit {returncode})", mediated)


def main():
    arbc, peer, tests_dds = sys.argv[1:4]
    env = environment(os.path.join(tests_dds, "loopback_profile.xml"))
    folder = scratch_folder("arbc-dds-matrix-")
    msg_dir = write_inputs(folder)
    held = Domain()  # the lock on the domain lasts as long as this object
    sent_text, received_text, mediated, returncode = run(arbc, peer, folder, msg_dir,
                                                         str(held.id), env)
    problems = compare(by_index(sent_text, "sent"), by_index(received_text, "got"))
    for p in problems:
        print("FAIL: " + p)
    if problems:
        fail(f"{len(problems)} message type(s) not passed unchanged", mediated)
    check_mediator(mediated, returncode)
    total = len(messages.MATRIX) * samples.SAMPLES
    print(f"ok: {len(messages.MATRIX)} message types, {total} samples received byte for byte, "
          "none dropped\n" + mediated[-3000:])


if __name__ == "__main__":
    main()
