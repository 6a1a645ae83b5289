#!/usr/bin/python3
"""The committed nets data/meshes/tube_16x8_evs.obj and band_32x8_evs.obj are what scripts/shell_nets.py makes from
their descriptions (the command in each first line), of the expected number of quads; the script refuses a
description it cannot make, with one line and exit code 2; --triangles splits every quad in two; a roof is on its
cylinder with its corners at +-A."""
import filecmp
import os
import subprocess
import sys
import tempfile

source = sys.argv[1]
script = os.path.join(source, "scripts", "shell_nets.py")
failures = []
with tempfile.TemporaryDirectory() as tmp:
    for name, quads in (("tube_16x8_evs.obj", 16 * 8), ("band_32x8_evs.obj", 32 * 8)):
        net = os.path.join(source, "data", "meshes", name)
        with open(net) as f:
            words = f.readline().split()  # "# scripts/shell_nets.py tube 300 600 16 8"
        out = os.path.join(tmp, name)
        r = subprocess.run(["/usr/bin/python3", script] + words[2:] + [out], capture_output=True, text=True)
        if r.returncode != 0 or not filecmp.cmp(out, net, shallow=False):
            failures.append(f"{' '.join(words[1:])} does not remake {net}: exit {r.returncode} {r.stderr}")
            continue
        with open(out) as f:
            lines = f.read().splitlines()
        faces = [l for l in lines if l.startswith("f ")]
        if len(faces) != quads or any(len(l.split()) != 5 for l in faces):
            failures.append(f"{name}: expected {quads} quads, got {len(faces)} faces")
    roof = os.path.join(tmp, "roof.obj")
    r = subprocess.run(["/usr/bin/python3", script, "roof", "25", "50", "40", "8", "8", roof], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(f"roof 25 50 40 8 8: exit {r.returncode} {r.stderr}")
    else:
        with open(roof) as f:
            lines = f.read().splitlines()
        vertices = [[float(w) for w in l.split()[1:]] for l in lines if l.startswith("v ")]
        corners = [vertices[0], vertices[8], vertices[-9], vertices[-1]]
        if len([l for l in lines if l.startswith("f ")]) != 64 or len(vertices) != 81:
            failures.append(f"roof 8 x 8: {len(vertices)} vertices, expected 81 and 64 quads")
        if any(abs((x * x + z * z) ** 0.5 - 25) > 1e-12 for x, _, z in vertices) or \
                any(abs(abs(c[0]) - 25 * 0.6427876096865393) > 1e-12 for c in corners):
            failures.append("roof: vertices off the cylinder R = 25 or corners not at +-40 degrees")
    tri = os.path.join(tmp, "tri.obj")
    r = subprocess.run(["/usr/bin/python3", script, "--triangles", "tube", "300", "600", "16", "8", tri],
                       capture_output=True, text=True)
    tris = [l for l in open(tri).read().splitlines() if l.startswith("f ")] if r.returncode == 0 else []
    if len(tris) != 2 * 16 * 8 or any(len(l.split()) != 4 for l in tris):
        failures.append(f"--triangles tube 16 x 8: exit {r.returncode}, {len(tris)} faces, expected 256 triangles")
    bad = subprocess.run(["/usr/bin/python3", script, "tube", "-1", "600", "16", "8", os.path.join(tmp, "bad.obj")],
                         capture_output=True, text=True)
    if bad.returncode != 2 or bad.stderr.count("\n") != 1 or not bad.stderr.startswith("shell_nets.py: error: "):
        failures.append(f"a radius -1: exit {bad.returncode}, stderr {bad.stderr!r}")
for f in failures:
    print("FAILED:", f)
sys.exit(1 if failures else 0)
