#!/usr/bin/python3
"""benchmarks/shell_time_to_accuracy.py on its cheapest configuration (the roof, NURBS p = 4, four levels): every level
reports its dofs and value, and the table's dofs at each tolerance are the log-log interpolation between the two
levels whose differences from 0.3006 bracket it, recomputed here from the levels' lines; the tighter tolerance needs
more dofs than the looser one."""
import math
import re
import subprocess
import sys

source, build = sys.argv[1], sys.argv[2]
r = subprocess.run(["/usr/bin/python3", f"{source}/benchmarks/shell_time_to_accuracy.py", build, "--only",
                    "Scordelis-Lo roof (0.3006) NURBS p = 4"], capture_output=True, text=True)
failures = []
if r.returncode != 0:
    print("FAILED: exit", r.returncode, r.stderr)
    sys.exit(1)
levels = [(int(m.group(1)), float(m.group(2))) for m in re.finditer(r": (\d+) dofs, value ([-0-9.e+]+) ", r.stderr)]
rows = [l for l in r.stdout.splitlines() if l.startswith("| Scordelis-Lo roof")]
if len(levels) != 4 or len(rows) != 1:
    print(f"FAILED: expected 4 levels and one row, got {levels} and {rows}")
    sys.exit(1)
cells = re.findall(r"([0-9.]+) %: ([0-9,]+) dofs", rows[0])
if [c[0] for c in cells] != ["0.5", "0.1"]:
    failures.append(f"the row's tolerances: {cells}")
for tol, dofs in cells:
    t = float(tol) / 100
    gaps = [(d, abs(v / 0.3006 - 1)) for d, v in levels]
    expected = None
    for (d0, e0), (d1, e1) in zip(gaps, gaps[1:]):
        if e0 >= t >= e1:
            s = math.log(t / e0) / math.log(e1 / e0)
            expected = d0 * (d1 / d0) ** s
            break
    got = float(dofs.replace(",", ""))
    if expected is None or abs(got - expected) > 0.5:
        failures.append(f"{tol} %: table {got} dofs, interpolated here {expected}")
if len(cells) == 2 and not float(cells[1][1].replace(",", "")) > float(cells[0][1].replace(",", "")):
    failures.append(f"0.1 % needs no more dofs than 0.5 %: {cells}")
for f in failures:
    print("FAILED:", f)
sys.exit(1 if failures else 0)
