#!/usr/bin/env python3
"""Depth profiles of the depth-averaged dam break against Mangeney et al.'s exact solution.

    plot_dam_break.py RUN [--times 5 10 15]     # writes RUN/plots/depth_profiles.png

RUN is the output of `mpm_solver --config configs/depth_averaged/mangeney_dam_break.yaml`.
"""
import argparse
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
import cosim_outputs  # noqa: E402

G, THETA, DELTA, H0 = 9.81, math.radians(22.0), math.radians(21.0), 1.0
C0 = math.sqrt(G * H0 * math.cos(THETA))
M = G * (math.sin(THETA) - math.cos(THETA) * math.tan(DELTA))


def exact_depth(x, t):
    """Mangeney et al. (2000): h = h0 (2 - xi)^2 / 9 on the rarefaction, xi = (x - m t^2/2) / (c0 t)."""
    xi = (x - 0.5 * M * t * t) / (C0 * t)
    return np.where(xi < -1.0, H0, np.where(xi > 2.0, 0.0, H0 * (2.0 - xi) ** 2 / 9.0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run")
    parser.add_argument("--times", type=float, nargs="+", default=[5.0, 10.0, 15.0])
    args = parser.parse_args()

    origin, spacing, (nx, ny) = cosim_outputs.grid(args.run, "ground.xdmf")
    x = origin[0] + (np.arange(nx) + 0.5) * spacing[0]
    snaps = cosim_outputs.snapshots(args.run, "ground_*.h5")
    fig, ax = plt.subplots(figsize=(9, 3.5))
    for t, colour in zip(args.times, plt.rcParams["axes.prop_cycle"].by_key()["color"]):
        path = cosim_outputs.nearest(snaps, t)
        if path is None:
            print(f"no snapshot at {t} s", file=sys.stderr)
            continue
        with h5py.File(path, "r") as f:
            depth = np.asarray(f["fields/solid_depth"])[0]
        ax.plot(x, depth, color=colour, label=f"computed, {t:g} s")
        ax.plot(x, exact_depth(x, t), ":", color="black", lw=1.2,
                label="exact (Mangeney et al.)" if t == args.times[0] else None)
        # Over the rarefaction and the front: from 10 m behind the exact tail on
        # (the reservoir's upslope end has a rarefaction of its own).
        window = x > -C0 * t + 0.5 * M * t * t - 10.0
        error = np.abs(depth - exact_depth(x, t))[window].sum() / exact_depth(x, t)[window].sum()
        print(f"t = {t:g} s: L1 error of the depth behind the front {100 * error:.2f} %")
    ax.set_xlim(-60, 130)
    ax.set_xlabel("x down the slope [m]")
    ax.set_ylabel("depth [m]")
    ax.set_title("Dam break on a 22° incline, basal friction 21° (Mangeney et al. 2000)")
    ax.legend(ncol=3, fontsize=8)
    out = os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "depth_profiles.png"), dpi=110)
    print(os.path.join(out, "depth_profiles.png"))


if __name__ == "__main__":
    main()
