#!/usr/bin/env python3
"""Times a command N times and prints the median wall time in seconds.

usage: median.py N COMMAND [ARGS...]   (the command's output is discarded)
"""
import statistics
import subprocess
import sys
import time

n = int(sys.argv[1])
times = []
for _ in range(n):
    start = time.perf_counter()
    subprocess.run(sys.argv[2:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    times.append(time.perf_counter() - start)
print(f"{statistics.median(times):.6f}")
