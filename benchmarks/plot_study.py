#!/usr/bin/python3
"""Plots of an iga-poisson convergence study (iga-poisson --study K0:K1 writes PREFIX.json and runs this).

Usage: plot_study.py STUDY.json PREFIX [--formats png,svg]

Writes PREFIX_dofs.{png,svg}: error against dofs, and PREFIX_seconds.{png,svg}: error against assembly + solve
seconds; log-log, one line per norm (L2 solid, H1 seminorm dashed) and per degree, with dotted reference slopes
e ~ N^(-(p+1)/2) (L2) and N^(-p/2) (H1) through each series' finest level (for the seconds plot the same slopes
in t, i.e. what a solver whose cost grows like N would give).
Exit codes: 0 plotted, 2 usage or unreadable study, 3 matplotlib cannot be imported (one line saying why).
"""
import argparse
import json
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("study")
    ap.add_argument("prefix")
    ap.add_argument("--formats", default="png,svg")
    a = ap.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        matplotlib.rcParams["svg.fonttype"] = "none"  # text as text: smaller, editable SVG
        import matplotlib.pyplot as plt
    except Exception as e:  # ImportError, or a broken installation
        print("cannot import matplotlib (%s: %s)" % (type(e).__name__, str(e).splitlines()[0] if str(e) else ""),
              file=sys.stderr)
        return 3
    try:
        with open(a.study) as f:
            study = json.load(f)
        series = study["series"]
    except (OSError, ValueError, KeyError) as e:
        print("plot_study.py: cannot read the study %s: %s" % (a.study, e), file=sys.stderr)
        return 2
    formats = [f for f in a.formats.split(",") if f]
    for axis, label in (("dofs", "degrees of freedom N"), ("seconds", "assembly + solve seconds")):
        fig, ax = plt.subplots(figsize=(6.4, 4.8))
        for i, s in enumerate(series):
            p = s["degree"]
            levels = s["levels"]
            if axis == "dofs":
                xs = [l["dofs"] for l in levels]
            else:
                xs = [max(l["assembly_seconds"] + l["solve_seconds"], 1e-9) for l in levels]
            colour = "C%d" % (i % 10)
            for key, name, style, marker, slope in (("l2", "L2", "-", "o", p + 1), ("h1", "H1 seminorm", "--", "s", p)):
                es = [l[key + "_error"] for l in levels]
                fitted = s["fitted_rates"][key]
                rate = "" if fitted is None else ", fitted rate %.2f" % fitted
                ax.loglog(xs, es, style, marker=marker, color=colour, label="p=%d %s%s" % (p, name, rate))
                # reference slope through the finest level: e ~ N^(-r/2) with the theoretical r
                x0, e0 = xs[-1], es[-1]
                if e0 > 0:
                    ref = [e0 * (x / x0) ** (-slope / 2.0) for x in xs]
                    ax.loglog(xs, ref, ":", color=colour, linewidth=1,
                              label="slope -%g (h^%d)" % (slope / 2.0, slope))
        ax.set_xlabel(label)
        ax.set_ylabel("error")
        ax.set_title("%s, %s: error against %s" % (study.get("basis", ""), study.get("mesh", ""), axis))
        ax.grid(True, which="both", linewidth=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        for fmt in formats:
            fig.savefig("%s_%s.%s" % (a.prefix, axis, fmt))
        plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
