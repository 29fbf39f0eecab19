"""When a process under test has installed its signal handlers (check_interrupt.py,
dds/split_run.py).

`arbc run` handles SIGINT and SIGTERM only once its run has started: before, while it loads and
proves the app or waits for DDS peers, a signal ends the process as usual. A test that sends a
signal "mid-run" must therefore wait for the handler, or a slow start (a sanitizer, a loaded
machine) looks like a process that ignored its handler.
"""
import time


def catches(pid, sig):
    """Has process pid installed a handler for sig? (Linux: the SigCgt mask of /proc/PID/status.)"""
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("SigCgt:"):
                    return bool(int(line.split()[1], 16) >> (int(sig) - 1) & 1)
    except OSError:
        pass
    return False


def wait_until_caught(proc, sig, timeout=60):
    """Waits until proc (a Popen) handles sig, or has ended, or `timeout` seconds passed."""
    deadline = time.monotonic() + timeout
    while not catches(proc.pid, sig) and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
