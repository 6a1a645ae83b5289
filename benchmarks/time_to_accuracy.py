#!/usr/bin/python3
"""Dofs and seconds to reach L2 errors of 1e-6 and 1e-8 with iga-poisson, per configuration (issue 16's table).

Usage: benchmarks/time_to_accuracy.py BUILD_DIR [--repeats N]

Runs each configuration over refinement levels on u = sin(pi x) sin(pi y) + x y^2 (all Dirichlet) on the unit
square, one thread, and interpolates log(dofs) and log(seconds) linearly in log(L2 error) between the two levels
that bracket each target (">" when the finest level run does not reach it). Seconds are iga-poisson's own
total_seconds (set-up, assembly, solve and error norms), the median of --repeats runs per level.
"""
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

SOURCE = "2*pi^2*sin(pi*x)*sin(pi*y) - 2*x"
EXACT = "sin(pi*x)*sin(pi*y) + x*y^2"
TARGETS = (1e-6, 1e-8)

CONFIGS = [
    # name, arguments, levels
    ("cc natural, 6x6 net", ["--basis", "cc", "--mesh", "data/meshes/square_6x6.obj", "--cc-boundary", "natural"], range(0, 6)),
    ("cc clamped, 6x6 net", ["--basis", "cc", "--mesh", "data/meshes/square_6x6.obj", "--cc-boundary", "clamped",
                             "--dirichlet-method", "strong"], range(0, 5)),
    ("cc natural, square_evs (Nitsche)", ["--basis", "cc", "--mesh", "data/meshes/square_evs.obj", "--cc-boundary", "natural",
                                          "--dirichlet-method", "nitsche", "--quadrature", "tiles:4:8"], range(1, 6)),
    ("cc clamped, square_evs (Nitsche)", ["--basis", "cc", "--mesh", "data/meshes/square_evs.obj", "--cc-boundary", "clamped",
                                          "--dirichlet-method", "nitsche", "--grade-evs", "0", "--quadrature", "tiles:4:8"],
     range(1, 6)),
    ("cc clamped + EV enrichment, square_evs (Nitsche)",
     ["--basis", "cc", "--mesh", "data/meshes/square_evs.obj", "--cc-boundary", "clamped", "--cc-enrich", "quadratic",
      "--dirichlet-method", "nitsche", "--quadrature", "tiles:4:8"], range(1, 6)),
    ("bspline p=3, 6x6 net", ["--basis", "bspline", "--mesh", "data/meshes/square_6x6.obj", "--degree", "3"], range(0, 7)),
]


def run(build, args, level, repeats):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "r.json")
        seconds = []
        for _ in range(repeats):
            subprocess.run([os.path.join(build, "benchmarks", "iga-poisson"), *args, "--refine", str(level),
                            "--source", SOURCE, "--exact", EXACT, "--threads", "1", "--vtu", "none", "--json", out,
                            "--quiet"], check=True)
            with open(out) as f:
                r = json.load(f)
            seconds.append(r["total_seconds"])
        return r["dofs"], r["l2_error"], statistics.median(seconds)


def at_target(points, target):
    for (d0, e0, s0), (d1, e1, s1) in zip(points, points[1:]):
        if e0 >= target >= e1:
            t = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return (math.exp(math.log(d0) + t * (math.log(d1) - math.log(d0))),
                    math.exp(math.log(s0) + t * (math.log(s1) - math.log(s0))))
    if points and points[0][1] <= target:
        return points[0][0], points[0][2]
    return None


def target_cells(curves, targets):
    """{configuration: [cell per target]} for a study's table: dofs and seconds at each target (at_target), with the
    ratios of time and dofs to the fastest deal.II configuration at that target for the others; "not reached (error
    at dofs)" where a curve does not get there. curves: {name: [(dofs, error, seconds), ...]}, deal.II's names
    starting with "deal.II"."""
    best = {}
    for t in targets:
        hits = [(at_target(p, t), n) for n, p in curves.items() if n.startswith("deal.II")]
        hits = [(h, n) for h, n in hits if h]
        best[t] = min(hits, key=lambda x: x[0][1]) if hits else None
    out = {}
    for name, points in curves.items():
        cells = []
        for t in targets:
            hit = at_target(points, t)
            if not hit:
                cells.append(f"not reached ({points[-1][1]:.1e} at {points[-1][0]:,} dofs)")
                continue
            cell = f"{hit[1]:.3f} s, {hit[0]:,.0f} dofs"
            if best[t] and not name.startswith("deal.II"):
                (bd, bs), bname = best[t]
                cell += f" ({hit[1] / bs:.2f}× time, {hit[0] / bd:.2f}× dofs of {bname.split()[-1]})"
            cells.append(cell)
        out[name] = cells
    return out


def plot_curves(curves, targets, ylabel, title, path):
    """Error against dofs and against seconds, one line per configuration (deal.II's dashed), the targets marked."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for name, points in curves.items():
        style = "--" if name.startswith("deal.II") else "-"
        axes[0].loglog([p[0] for p in points], [p[1] for p in points], style, marker="o", ms=3, label=name)
        axes[1].loglog([p[2] for p in points], [p[1] for p in points], style, marker="o", ms=3, label=name)
    for ax, xlabel in zip(axes, ("dofs", "seconds (one thread, without error norms)")):
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.grid(True, which="major", alpha=0.3)
        for t in targets:
            ax.axhline(t, color="grey", lw=0.6)
    axes[1].legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    repeats = int(sys.argv[sys.argv.index("--repeats") + 1]) if "--repeats" in sys.argv else 3
    print("| configuration | L2 rate (last two levels) | dofs to 1e-6 | s to 1e-6 | dofs to 1e-8 | s to 1e-8 |")
    print("|---|---|---|---|---|---|")
    for name, args, levels in CONFIGS:
        points = [run(build, args, k, repeats) for k in levels]
        (d0, e0, _), (d1, e1, _) = points[-2], points[-1]
        rate = 2 * math.log(e0 / e1) / math.log(d1 / d0)  # against h = N^(-1/2)
        cells = []
        for target in TARGETS:
            hit = at_target(points, target)
            if hit:
                cells += [f"{hit[0]:,.0f}", f"{hit[1]:.3f}"]
            else:
                cells += [f"> {points[-1][0]:,}", f"> {points[-1][2]:.2f}"]
        print(f"| {name} | {rate:.2f} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
