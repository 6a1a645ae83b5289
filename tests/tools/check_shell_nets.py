#!/usr/bin/python3
"""The committed net data/meshes/tube_16x8_evs.obj is what scripts/shell_nets.py makes from its description (the
command in its first line); the script refuses a description it cannot make, with one line and exit code 2."""
import filecmp
import os
import subprocess
import sys
import tempfile

source = sys.argv[1]
script = os.path.join(source, "scripts", "shell_nets.py")
net = os.path.join(source, "data", "meshes", "tube_16x8_evs.obj")
failures = []
with open(net) as f:
    words = f.readline().split()  # "# scripts/shell_nets.py tube 300 600 16 8"
with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "net.obj")
    r = subprocess.run(["/usr/bin/python3", script] + words[2:] + [out], capture_output=True, text=True)
    if r.returncode != 0 or not filecmp.cmp(out, net, shallow=False):
        failures.append(f"{' '.join(words[1:])} does not remake {net}: exit {r.returncode} {r.stderr}")
    with open(out) as f:
        lines = f.read().splitlines()
    faces = [l for l in lines if l.startswith("f ")]
    if len(faces) != 16 * 8 or any(len(l.split()) != 5 for l in faces):
        failures.append(f"expected 128 quads, got {len(faces)} faces")
    bad = subprocess.run(["/usr/bin/python3", script, "tube", "-1", "600", "16", "8", os.path.join(tmp, "bad.obj")],
                         capture_output=True, text=True)
    if bad.returncode != 2 or bad.stderr.count("\n") != 1 or not bad.stderr.startswith("shell_nets.py: error: "):
        failures.append(f"a radius -1: exit {bad.returncode}, stderr {bad.stderr!r}")
for f in failures:
    print("FAILED:", f)
sys.exit(1 if failures else 0)
