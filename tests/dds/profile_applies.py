#!/usr/bin/env python3
"""The participant of a Fast-DDS XML profile is the one arbc runs with (docs/distributed.md).

FASTRTPS_DEFAULT_PROFILES_FILE names the profile. An `arbc run --transport dds` under
loopback_udp_profile.xml (UDP on 127.0.0.1 only, no shared memory) must map no Fast-DDS
shared-memory segment and bind its UDP sockets to 127.0.0.1 only (or the discovery multicast
group); under loopback_profile.xml (shared memory and UDP) it must map one, which shows that
this check can see shared memory at all. With segments left in /dev/shm for the domain's first
four participant ids (killed processes leave them), it must take the fifth id's ports rather
than reuse a leftover's, and say that initial peers without a port no longer reach it
(dds/shm_participant_id.h). Fast-DDS only reads the profiles when asked, and arbc
once built its participant from Fast-DDS's built-in defaults: shared memory and every
interface, whatever the profile said. A profile file that is missing or does not parse is bad
input (exit 2, naming the file), not a run on Fast-DDS's defaults, which is all Fast-DDS does.

usage: profile_applies.py ARBC SPEC TESTS_DDS_DIR
"""
import os
import socket
import struct
import subprocess
import sys
import time

from dds_domain import Domain, environment, scratch_folder


def fail(message, *outputs):
    print("FAIL: " + message + "".join("\n--- output ---\n" + o for o in outputs))
    sys.exit(1)


def shm_segments(pid):
    with open(f"/proc/{pid}/maps") as maps:
        return {line.split()[-1] for line in maps if "/dev/shm/fastrtps" in line}


def udp_addresses(pid):
    """The local addresses of the UDP sockets process `pid` holds."""
    inodes = set()
    for fd in os.listdir(f"/proc/{pid}/fd"):
        try:
            target = os.readlink(f"/proc/{pid}/fd/{fd}")
        except OSError:
            continue
        if target.startswith("socket:["):
            inodes.add(target[8:-1])
    addresses = []
    with open("/proc/net/udp") as table:
        for line in table.readlines()[1:]:
            fields = line.split()
            if fields[9] in inodes:
                host, port = fields[1].split(":")
                ip = socket.inet_ntoa(struct.pack("<I", int(host, 16)))
                addresses.append(f"{ip}:{int(port, 16)}")
    return addresses


def run_under(arbc, app, profile, domain):
    """Starts a mediator under `profile`; returns what it maps and binds once its sockets exist."""
    proc = subprocess.Popen([arbc, "run", app, "--transport", "dds", "--host", "none",
                             "--mediate", "all", "--domain", str(domain), "--duration", "100000s",
                             "--wait-peers", "0"], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, env=environment(profile))
    try:
        deadline = time.monotonic() + 20
        addresses = []
        while time.monotonic() < deadline and proc.poll() is None:
            addresses = udp_addresses(proc.pid)
            if len(addresses) >= 3:  # discovery and user traffic, unicast and multicast
                time.sleep(0.5)  # every transport is open once the participant exists
                return shm_segments(proc.pid), udp_addresses(proc.pid), proc
            time.sleep(0.1)
        proc.kill()
        fail(f"arbc under {os.path.basename(profile)} opened no DDS sockets", proc.communicate()[0])
    except BaseException:
        proc.kill()
        raise


def stop(proc):
    proc.terminate()
    return proc.communicate(timeout=15)[0]


def main():
    arbc, spec, here = sys.argv[1:4]
    out_dir = scratch_folder("arbc-dds-profile-")
    built = subprocess.run([arbc, "build", spec, "-o", out_dir], capture_output=True, text=True)
    if built.returncode != 0:
        fail("arbc build", built.stdout + built.stderr)
    app = os.path.join(out_dir, os.path.splitext(os.path.basename(spec))[0])
    held = Domain()  # the lock on the domain lasts as long as this object
    domain = held.id

    shm, addresses, proc = run_under(arbc, app, os.path.join(here, "loopback_udp_profile.xml"),
                                     domain)
    out = stop(proc)
    if shm:
        fail("under loopback_udp_profile.xml (no shared memory) arbc mapped " + ", ".join(sorted(shm)), out)
    stray = [a for a in addresses if not a.startswith(("127.0.0.1:", "239.255.0.1:"))]
    if stray:
        fail("under loopback_udp_profile.xml (UDP on 127.0.0.1 only) arbc bound " + ", ".join(stray), out)
    print("ok: UDP on 127.0.0.1 only: " + ", ".join(addresses))

    shm, addresses, proc = run_under(arbc, app, os.path.join(here, "loopback_profile.xml"), domain)
    out = stop(proc)
    if not shm:
        fail("under loopback_profile.xml (shared memory and UDP) arbc mapped no shared memory", out)
    if "DDS: participant id" in out:
        fail("with no segments left in /dev/shm arbc warned about its participant id", out)
    print("ok: shared memory under loopback_profile.xml: " + ", ".join(sorted(shm)))

    first = 7400 + 250 * domain + 10  # participant id 0's discovery port (Fast-DDS's plan)
    left = [f"/dev/shm/fastrtps_port{first + k}" for k in range(8)]  # ids 0 to 3, two ports each
    try:
        for path in left:
            open(path, "w").close()
        shm, addresses, proc = run_under(arbc, app, os.path.join(here, "loopback_profile.xml"),
                                         domain)
        out = stop(proc)
    finally:
        for path in left:
            os.unlink(path)
    own = f"/dev/shm/fastrtps_port{first + 8}"
    if own not in shm or shm & set(left):
        fail(f"with segments left for ids 0 to 3, arbc mapped {sorted(shm)}, not {own}", out)
    if "DDS: participant id 4: the lower ids' shared-memory ports are taken" not in out:
        fail("arbc took participant id 4 without saying that initial peers may not reach it", out)
    print("ok: past the leftover segments: " + own)

    broken = os.path.join(out_dir, "broken_profile.xml")
    with open(broken, "w") as f:
        f.write('<dds><profiles><participant profile_name="p" is_default_profile="true">\n')
    for profile, what in ((broken, "which is not a Fast-DDS profile"),
                          (os.path.join(out_dir, "missing.xml"), "which is not a file")):
        ran = subprocess.run([arbc, "run", app, "--transport", "dds", "--host", "none",
                              "--mediate", "all", "--domain", str(domain), "--duration", "1s",
                              "--wait-peers", "0"], capture_output=True, text=True,
                             env=environment(profile), timeout=60)
        said = ran.stdout + ran.stderr
        expected = f"FASTRTPS_DEFAULT_PROFILES_FILE names {profile}, {what}"
        if ran.returncode != 2 or expected not in said:
            fail(f"a bad profile ({os.path.basename(profile)}): exit {ran.returncode}, "
                 f"expected 2 and '{expected}'", said)
        print(f"ok: {os.path.basename(profile)} refused: {expected}")


if __name__ == "__main__":
    main()
