#!/usr/bin/python3
"""Plots of a bench-bem report (benchmarks/README.md, "Collocation BEM"): the condition estimate against the
largest BEM element length h, and the LU / GMRES solve seconds against the boundary dofs, one line per degree.

Usage: bem_plot.py REPORT.json OUT.svg
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: bem_plot.py REPORT.json OUT.svg")
    with open(sys.argv[1]) as f:
        report = json.load(f)
    rows = report["rows"]
    degrees = sorted({r["degree"] for r in rows})
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    for p in degrees:
        rs = [r for r in rows if r["degree"] == p and "condition_estimate" in r]
        ax1.loglog([r["h"] for r in rs], [r["condition_estimate"] for r in rs], "o-", label=f"p = {p}")
        rs = [r for r in rows if r["degree"] == p]
        lu = [r for r in rs if "lu_seconds" in r]
        ax2.loglog([r["dofs"] for r in lu], [r["lu_seconds"] for r in lu], "o-", label=f"LU, p = {p}")
        ax2.loglog([r["dofs"] for r in rs], [r["gmres_seconds"] for r in rs], "s--", label=f"GMRES, p = {p}")
    ax1.set_xlabel("h (largest BEM element length)")
    ax1.set_ylabel("condition estimate (1-norm, LU)")
    ax1.invert_xaxis()
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend()
    ax2.set_xlabel("boundary dofs")
    ax2.set_ylabel("solve seconds")
    ax2.grid(True, which="both", alpha=0.3)
    ax2.legend(fontsize=7)
    fig.suptitle(f"bench-bem on {report['mesh']} ({report['basis']}), {report['threads']} threads")
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
