"""The teleop app of the interop tests (interop/teleop.spec), built by arbc into a fresh folder."""
import os
import subprocess
import sys
from dds_domain import scratch_folder


def build_teleop(arbc, here, prefix):
    """`arbc build` of interop/teleop.spec into a new temporary folder (named after `prefix`),
    returned; a failed build ends the test with its output."""
    out_dir = scratch_folder(prefix)
    built = subprocess.run([arbc, "build", os.path.join(here, "interop", "teleop.spec"), "-o",
                            out_dir], capture_output=True, text=True)
    if built.returncode != 0:
        print("FAIL: arbc build\n--- output ---\n" + built.stdout + built.stderr)
        sys.exit(1)
    return out_dir
