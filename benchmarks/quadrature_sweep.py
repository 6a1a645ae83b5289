#!/usr/bin/python3
"""Quadrature error versus points around extraordinary vertices (issue 4, "Performance").

Runs iga-quadrature for the quantities
  area       data/meshes/square_evs.obj (planar; interior EVs of valence 3, 5, 6 and a boundary EV)
  volume     data/meshes/cube.obj (closed; eight EVs of valence 3)
  mass       ring sums of the mass matrix over the elements at the interior EVs of square_evs.obj
  stiffness  the same for the parametric stiffness matrix (planar Poisson on the parameter domain)
  mass-nN, stiffness-nN   the single irregular element of valence N (--valence N; one per --valences entry)
with the methods tiles:P:L (per-tile Gauss), macro:R:L (strip/macro Gauss; not on single elements, where the
folded rule is not exact by construction) and the fitted tables (fitted = phi, fitted:mass, fitted:stiffness),
and writes
  a CSV of every run (quantity, method, family, points per irregular element, relative error),
  a markdown table: per quantity and method family the fewest points per irregular element that reach the
    target relative error (default 1e-12), else the best error reached and its points,
  a plot (matplotlib; SVG, and PNG with --png): relative error against points per irregular element, log-log,
    one panel per quantity, one line per method family (tiles:P over L, macro:R over L), fitted rules as single
    markers, the target as a dashed line.
Relative error: |value - exact| / |exact| for area and volume, the relative Frobenius error for matrices.
A method that does not apply (e.g. no fitted table for a valence) is listed as "n/a" with the reason.

Usage: quadrature_sweep.py [--exe PATH] [--root DIR] [--svg FILE|none] [--png FILE] [--csv FILE]
                           [--markdown FILE] [--valences 3 5] [--target 1e-12]
PATH defaults to the first build*/benchmarks/iga-quadrature under the source root. Run it with /usr/bin/python3
(Debian's matplotlib); without matplotlib, --svg none still gives the table and the CSV.
"""
import argparse
import csv
import glob
import json
import os
import subprocess
import sys
import tempfile

LEVELS = [1, 2, 3, 4, 6, 8, 10, 12, 16, 20, 24]
TILE_POINTS = [2, 3, 4, 5, 6]
MACRO_RINGS = [1, 2, 3]


def find_exe(root):
    hits = sorted(glob.glob(os.path.join(root, "build*", "benchmarks", "iga-quadrature")))
    hits += sorted(glob.glob(os.path.join(root, "..", "build*", "benchmarks", "iga-quadrature")))
    if not hits:
        sys.exit("quadrature_sweep.py: iga-quadrature not found; pass --exe PATH")
    return hits[0]


def cases(root, valences):
    """(label, arguments, is_single_element, fitted specs) per quantity."""
    mesh = lambda name: ["--mesh", os.path.join(root, "data", "meshes", name)]
    out = [
        ("area", mesh("square_evs.obj") + ["--quantity", "area"], False, ["fitted"]),
        ("volume", mesh("cube.obj") + ["--quantity", "volume"], False, ["fitted"]),
        ("mass", mesh("square_evs.obj") + ["--quantity", "mass"], False, ["fitted", "fitted:mass"]),
        ("stiffness", mesh("square_evs.obj") + ["--quantity", "stiffness"], False, ["fitted", "fitted:stiffness"]),
    ]
    for n in valences:
        out.append(("mass-n%d" % n, ["--quantity", "mass", "--valence", str(n)], True, ["fitted", "fitted:mass"]))
        out.append(("stiffness-n%d" % n, ["--quantity", "stiffness", "--valence", str(n)], True,
                    ["fitted", "fitted:stiffness"]))
    return out


def methods(single, fitted):
    """(family, method spec) pairs."""
    out = []
    for p in TILE_POINTS:
        out += [("tiles:%d" % p, "tiles:%d:%d" % (p, l)) for l in LEVELS]
    if not single:
        for r in MACRO_RINGS:
            out += [("macro:%d" % r, "macro:%d:%d" % (r, l)) for l in LEVELS]
    out += [(f, f) for f in fitted]
    return out


def run_one(exe, args, method, scratch, root):
    report = os.path.join(scratch, "r.json")
    proc = subprocess.run([exe] + args + ["--method", method, "--json", report], capture_output=True, text=True)
    if proc.returncode != 0:
        note = proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else "exit %d" % proc.returncode
        # One line, without this machine's paths: "fitted quadrature: no mass table for valence 5 in ..."
        note = note.replace("iga-quadrature: error: ", "").replace(os.path.abspath(root) + os.sep, "")
        return None, note.split(" in '")[0]
    with open(report) as f:
        r = json.load(f)
    if "relative_frobenius_error" in r:
        err = abs(r["relative_frobenius_error"])
    else:
        err = abs(r["relative_error"])
    return (r["points_per_irregular_element"], err), None


def summarise(rows, target):
    """Per (quantity, family): fewest points with error <= target, else best error and its points."""
    best = {}
    for row in rows:
        if row["error"] is None:
            best.setdefault((row["quantity"], row["family"]), {"note": row["note"]})
            continue
        key = (row["quantity"], row["family"])
        b = best.get(key)
        if b is None or "note" in b:
            b = best[key] = {"reach": None, "best": None}
        pts, err = row["points"], row["error"]
        if err <= target and (b["reach"] is None or pts < b["reach"][0]):
            b["reach"] = (pts, err, row["method"])
        if b["best"] is None or err < b["best"][1]:
            b["best"] = (pts, err, row["method"])
    return best


def markdown(best, quantities, target):
    lines = ["| quantity | method | fewest points per irregular element with error <= %.0e | rule | best error (points) |" % target,
             "|---|---|---|---|---|"]
    for q in quantities:
        for (quantity, family), b in best.items():
            if quantity != q:
                continue
            if "note" in b:
                lines.append("| %s | %s | n/a | | %s |" % (q, family, b["note"].replace("|", "/")))
                continue
            reach = "%d" % b["reach"][0] if b["reach"] else "not reached"
            rule = b["reach"][2] if b["reach"] else ""
            lines.append("| %s | %s | %s | %s | %.1e (%d) |" % (q, family, reach, rule, b["best"][1], b["best"][0]))
    return "\n".join(lines) + "\n"


def plot(plt, rows, quantities, target, paths):
    """One log-log panel per quantity (matplotlib): relative error against points per irregular element, one
    line per method family, fitted rules as single markers, the target as a dashed line; saved to each path."""
    shown = [q for q in quantities if any(r["quantity"] == q and r["error"] is not None for r in rows)]
    cols = 3
    nrows = max(1, (len(shown) + cols - 1) // cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(4.2 * cols, 3.2 * nrows), squeeze=False)
    for ax in axes.flat[len(shown):]:
        ax.set_visible(False)
    for ax, q in zip(axes.flat, shown):
        data = [r for r in rows if r["quantity"] == q and r["error"] is not None]
        families = []
        for r in data:
            if r["family"] not in families:
                families.append(r["family"])
        for fam in families:
            pts = sorted((r["points"], max(r["error"], 1e-17)) for r in data if r["family"] == fam)
            xs, ys = [a for a, _ in pts], [b for _, b in pts]
            if len(pts) > 1:
                ax.loglog(xs, ys, "-o", markersize=2.5, linewidth=1.2, label=fam)
            else:
                ax.loglog(xs, ys, "D", markersize=6, label=fam)
        ax.axhline(target, color="black", linestyle="--", linewidth=0.8)
        ax.set_ylim(1e-17, 1.0)
        ax.set_title(q, fontsize=10, fontweight="bold")
        ax.set_xlabel("points per irregular element", fontsize=8)
        ax.set_ylabel("relative error", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(True, which="major", linewidth=0.3)
        ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    for path in paths:
        fig.savefig(path)
    plt.close(fig)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", help="iga-quadrature executable")
    ap.add_argument("--root", default=os.path.dirname(here), help="source tree (for data/)")
    ap.add_argument("--svg", default=os.path.join(here, "quadrature_error.svg"), help="plot as SVG ('none': not)")
    ap.add_argument("--png", help="the plot also as PNG")
    ap.add_argument("--csv", help="CSV of every run")
    ap.add_argument("--markdown", help="markdown summary table (default: stdout only)")
    ap.add_argument("--valences", type=int, nargs="*", default=[3, 5], help="single-element valences for mass/stiffness")
    ap.add_argument("--target", type=float, default=1e-12)
    a = ap.parse_args()
    paths = [p for p in (a.svg, a.png) if p and p != "none"]
    plt = None
    if paths:  # before the sweep: a missing matplotlib stops it at once, not after the runs
        try:
            import matplotlib
            matplotlib.use("Agg")
            matplotlib.rcParams["svg.fonttype"] = "none"  # text as text: smaller, editable SVG
            import matplotlib.pyplot as plt
        except ImportError as e:
            sys.exit("quadrature_sweep.py: cannot import matplotlib (%s); --svg none skips the plot" % e)
    exe = a.exe or find_exe(a.root)
    if not os.access(exe, os.X_OK):
        sys.exit("quadrature_sweep.py: not an executable: %s" % exe)
    rows = []
    all_cases = cases(a.root, a.valences)
    with tempfile.TemporaryDirectory() as scratch:
        for label, args, single, fitted in all_cases:
            ms = methods(single, fitted)
            print("%s: %d runs" % (label, len(ms)), file=sys.stderr, flush=True)
            for family, method in ms:
                res, note = run_one(exe, args, method, scratch, a.root)
                rows.append({"quantity": label, "family": family, "method": method,
                             "points": res[0] if res else None, "error": res[1] if res else None, "note": note})
    quantities = [c[0] for c in all_cases]
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            wr = csv.writer(f)
            wr.writerow(["quantity", "family", "method", "points_per_irregular_element", "relative_error", "note"])
            for r in rows:
                wr.writerow([r["quantity"], r["family"], r["method"], r["points"],
                             "%.3e" % r["error"] if r["error"] is not None else "", r["note"] or ""])
    table = markdown(summarise(rows, a.target), quantities, a.target)
    sys.stdout.write(table)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write(table)
    if paths:
        plot(plt, rows, quantities, a.target, paths)
        print("wrote %s" % ", ".join(paths), file=sys.stderr)


if __name__ == "__main__":
    main()
