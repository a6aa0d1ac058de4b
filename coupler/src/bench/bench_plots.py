#!/usr/bin/python3
"""Draws the figures of a `cosim bench` report.

    bench_plots.py PLOTS_DIR

PLOTS_DIR/plots.json (written by `cosim bench`) lists the figures:
  curves       a metric's profile or time series, one line per backend, the
               reference as black points (a file's) or a dashed line (analytic)
  convergence  a metric's error against the number of cells, per backend,
               on log-log axes with the tolerance as a dotted line
  wall_time    wall time per backend, with the coupler's share shaded
Each becomes PLOTS_DIR/<file>. Needs Debian's python3-matplotlib.
"""
import json
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def curves(fig, ax):
    for c in fig["curves"]:
        ax.plot(c["x"], c["y"], label=c["label"], linewidth=1.5)
    ref = fig.get("reference")
    if ref:
        dense = len(ref["x"]) > 40
        ax.plot(ref["x"], ref["y"], "k--" if dense else "ko", label=ref["label"],
                linewidth=1.0, markersize=4)
    ax.set_xlabel(fig["xlabel"] or "")
    ax.set_ylabel(fig["ylabel"])


def convergence(fig, ax):
    for c in fig["curves"]:
        ax.loglog(c["x"], c["y"], "o-", label=c["label"])
    if fig.get("tolerance"):
        ax.axhline(fig["tolerance"], color="k", linestyle=":", label="tolerance")
    ax.set_xlabel(fig["xlabel"])
    ax.set_ylabel(fig["ylabel"])


def wall_time(fig, ax):
    labels = [b["label"] for b in fig["bars"]]
    total = [b["wall_time_s"] for b in fig["bars"]]
    share = [b["coupling_share"] or 0.0 for b in fig["bars"]]
    ax.bar(labels, total, color="tab:blue", label="wall time")
    ax.bar(labels, [t * s for t, s in zip(total, share)], color="tab:orange", label="coupler's share")
    ax.set_ylabel("wall time [s]")
    if max(total) > 50 * max(min(total), 1e-9):
        ax.set_yscale("log")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    directory = sys.argv[1]
    with open(os.path.join(directory, "plots.json")) as f:
        manifest = json.load(f)
    draw = {"curves": curves, "convergence": convergence, "wall_time": wall_time}
    for fig in manifest["figures"]:
        figure, ax = plt.subplots(figsize=(6.4, 4.0))
        draw[fig["kind"]](fig, ax)
        ax.set_title("\n".join(textwrap.wrap(fig["title"], 80)), fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
        figure.tight_layout()
        figure.savefig(os.path.join(directory, fig["file"]), dpi=110)
        plt.close(figure)


if __name__ == "__main__":
    main()
