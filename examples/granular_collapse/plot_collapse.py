#!/usr/bin/python3
"""Deposit profiles and wave gauges of the underwater granular collapse (MPM + OpenFOAM).

    examples/granular_collapse/plot_collapse.py RUN_DIR [--times 0 0.25 0.5 1 2] [--still-water 0.12]
                                                [--bin 0.005] [--soil soil] [--water water]
                                                [--output RUN_DIR/plots]

RUN_DIR is the --output of `cosim run configs/openfoam_coupled/granular_collapse/job.yaml`. It reads
the particle snapshots (RUN_DIR/soil/particles_*.h5), the OpenFOAM snapshots (RUN_DIR/water/
openfoam_*.h5) and the wave gauges (RUN_DIR/water/gauges.csv), and writes, like Pan et al. 2021,
Figs. 5-6:
  deposit.png    the sand's surface h(x) (the highest point per bin of x) at each time
  gauges.png     the water surface at the gauges, eta - h0 against time
  snapshots.png  one panel per time: the cells' water fraction (blue) and the sand coloured by speed
and prints the runout (the farthest point's x) and the column's height at each time.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from cosim_outputs import (  # noqa: E402
    nearest, openfoam_grid, particles, snapshots, water_and_points_figure, wave_gauges)


def surface(xy, width):
    """(bin centres, highest point per bin) of a set of points."""
    bins = np.floor(xy[:, 0] / width).astype(int)
    top = {}
    for b, y in zip(bins, xy[:, 1]):
        top[b] = max(top.get(b, -np.inf), y)
    keys = sorted(top)
    return (np.array(keys) + 0.5) * width, np.array([top[k] for k in keys])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--times", type=float, nargs="+", default=[0.0, 0.25, 0.5, 1.0, 2.0])
    parser.add_argument("--still-water", type=float, default=0.12, help="still-water depth h0 [m]")
    parser.add_argument("--bin", type=float, default=0.005, help="width of the surface's bins [m]")
    parser.add_argument("--soil", default="soil")
    parser.add_argument("--water", default="water")
    parser.add_argument("--output")
    args = parser.parse_args()
    water_dir = os.path.join(args.run, args.water)
    soil_dir = os.path.join(args.run, args.soil)
    out = args.output or os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)

    soil = snapshots(soil_dir, "particles_*.h5")
    if not soil:
        print(f"{soil_dir}: no particle snapshots", file=sys.stderr)
        return 1
    fig, ax = plt.subplots(figsize=(7.5, 3.0))
    for time in args.times:
        path = nearest(soil, time)
        if not path:
            continue
        xy, _, _ = particles(path)
        x, h = surface(xy, args.bin)
        ax.step(x, h, where="mid", lw=1.0, label=f"t = {time:g} s")
        print(f"t = {time:g} s: runout x = {xy[:, 0].max():.4f} m, column height {xy[:, 1].max():.4f} m")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("h [m]")
    ax.set_title("Deposit profiles (cf. Pan et al. 2021, Fig. 6)", fontsize=9)
    ax.set_aspect("equal")
    ax.legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(out, "deposit.png")
    fig.savefig(path, dpi=130)
    plt.close(fig)
    print(path)

    gauge_path = os.path.join(water_dir, "gauges.csv")
    if os.path.exists(gauge_path):
        t, names, eta = wave_gauges(gauge_path)
        fig, ax = plt.subplots(figsize=(7.5, 3.0))
        for g, name in enumerate(names):
            ax.plot(t, 1e3 * (eta[:, g] - args.still_water), lw=1.0, label=name)
        ax.axhline(0.0, color="k", lw=0.5)
        ax.set_xlabel("t [s]")
        ax.set_ylabel(r"$\eta - h_0$ [mm]")
        ax.legend(fontsize=8)
        fig.tight_layout()
        path = os.path.join(out, "gauges.png")
        fig.savefig(path, dpi=130)
        plt.close(fig)
        print(path)

    water = snapshots(water_dir, "openfoam_*.h5")
    if not water:
        return 0
    origin, spacing, (nx, ny) = openfoam_grid(water_dir)
    extent = [origin[0], origin[0] + nx * spacing[0], origin[1], origin[1] + ny * spacing[1]]
    path = os.path.join(out, "snapshots.png")
    water_and_points_figure(path, args.times, water, soil, extent, 0.3, "sand speed [m/s]",
                            "Underwater granular collapse: sand (points), water fraction (blue)",
                            panel_height=1.6, point_size=1.0)
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
