#!/usr/bin/env python3
"""twist_mux's documented configuration, imported by `arbc import twist_mux` and run on the DDS
mediator in front of programs with no arbc in them, against what twist_mux itself does
(docs/twist_mux.md; issue 42 item 5).

The configuration is twist_mux's own example (tests/twist_mux/documented) with the tablet at
priority 95, which resolves the tie the import reports. mux_player plays one script of input
Twists (each numbered in linear.x) and lock Bools; interop_sub prints what the base receives.
The reference is twist_mux's rule, written here from its documentation and topic_handle.hpp:
a message is published when its input, stamped on arrival, is among the inputs not expired
(silent at most `timeout`) and not below an engaged lock's priority, the one of highest
priority. Every message of the script is at least 50 ms from an expiry or a lock change, so the
network's jitter cannot decide it. The base must receive exactly the messages twist_mux would
publish, in order.

usage: twist_mux_run.py ARBC MUX_PLAYER INTEROP_SUB TESTS_DDS_DIR DOCUMENTED_DIR
"""
import os
import signal
import subprocess
import sys

from dds_domain import Domain, environment, scratch_folder

INPUTS = {"navigation": ("nav_vel", 10, 0.5), "joystick": ("joy_vel", 100, 0.5),
          "keyboard": ("key_vel", 90, 0.5), "tablet": ("tab_vel", 95, 0.5)}
LOCKS = {"pause": ("pause_navigation", 100), "loop_closure": ("stop_closing_loop", 200),
         "joystick": ("joy_priority", 100)}


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def script():
    """(seconds, kind, name, value) of each message: the planner throughout, the keyboard, the
    joystick, the pause lock, the tablet, the loop-closure lock over it, the joystick again."""
    lines = [(round(0.05 + 0.1 * i, 3), "input", "navigation", 1000 + i) for i in range(55)]
    lines += [(round(0.5 + 0.1 * i, 3), "input", "keyboard", 2000 + i) for i in range(5)]
    lines += [(round(1.8 + 0.1 * i, 3), "input", "joystick", 3000 + i) for i in range(3)]
    lines += [(2.6, "lock", "pause", 1), (3.3, "lock", "pause", 0)]
    lines += [(3.6, "input", "tablet", 4000), (3.7, "input", "tablet", 4001)]
    lines += [(4.5, "lock", "loop_closure", 1), (4.8, "lock", "loop_closure", 0)]
    lines += [(4.6, "input", "joystick", 3100), (4.9, "input", "joystick", 3101)]
    return sorted(lines)


def twist_mux(lines):
    """The values twist_mux publishes, in order (its documented rule, above)."""
    last = {}        # input -> arrival of its last message
    engaged = set()  # locks whose last message was true (timeout 0: never by silence)
    out = []
    for at, kind, name, value in lines:
        if kind == "lock":
            (engaged.add if value else engaged.discard)(name)
            continue
        last[name] = at
        floor = max((LOCKS[l][1] for l in engaged), default=0)
        live = [i for i, t in last.items()
                if at - t <= INPUTS[i][2] and INPUTS[i][1] >= floor]
        if live and max(live, key=lambda i: INPUTS[i][1]) == name:
            out.append(value)
    return out


def main():
    arbc, player, sub, here, documented = sys.argv[1:6]
    env = environment(os.path.join(here, "loopback_profile.xml"))
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = str(held.id)
    work = scratch_folder("arbc-dds-twist-mux-")
    topics = os.path.join(work, "twist_mux_topics.yaml")
    with open(os.path.join(documented, "twist_mux_topics.yaml")) as f:
        text = f.read()
    at = text.index("tab_vel")  # the tablet one below the joystick: no tie
    with open(topics, "w") as f:
        f.write(text[:at] + text[at:].replace("priority: 100", "priority: 95", 1))
    spec, deploy = os.path.join(work, "mux.spec"), os.path.join(work, "mux.deploy.json")
    imported = subprocess.run([arbc, "import", "twist_mux", topics,
                               os.path.join(documented, "twist_mux_locks.yaml"), "-o", spec,
                               "--deploy", deploy, "--output-topic", "/cmd_vel"],
                              capture_output=True, text=True)
    built = subprocess.run([arbc, "build", spec, "-o", work], capture_output=True, text=True)
    if imported.returncode != 0 or built.returncode != 0:
        fail("arbc import or build", imported.stdout + imported.stderr + built.stdout + built.stderr)
    lines = script()
    with open(os.path.join(work, "script.txt"), "w") as f:
        for at, kind, name, value in lines:
            topic = (INPUTS[name][0] if kind == "input" else LOCKS[name][0])
            f.write(f"{at} rt/{topic} {'twist' if kind == 'input' else 'bool'} {value}\n")
    receiver = subprocess.Popen([sub, domain, "3", "60"], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, env=env)
    mediator = subprocess.Popen(
        [arbc, "run", os.path.join(work, "twist_mux"), "--transport", "dds", "--host", "none",
         "--mediate", "all", "--deploy", deploy, "--domain", domain, "--duration", "100000s"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    played = subprocess.run([player, domain, os.path.join(work, "script.txt")],
                            capture_output=True, text=True, env=env, timeout=90)
    received, _ = receiver.communicate(timeout=90)
    mediator.send_signal(signal.SIGTERM)
    mediated, _ = mediator.communicate(timeout=15)
    if played.returncode != 0:
        fail(f"mux_player exited {played.returncode}", played.stdout + played.stderr, mediated)
    got = [int(float(line)) for line in received.splitlines()[1:] if line.strip()]
    want = twist_mux(lines)
    if got != want:
        fail(f"the base received\n  {got}\ntwist_mux publishes\n  {want}", mediated)
    print(f"ok: the base received the {len(want)} messages twist_mux publishes, of "
          f"{sum(1 for l in lines if l[1] == 'input')} inputs and 4 lock changes\n" + mediated)


if __name__ == "__main__":
    main()
