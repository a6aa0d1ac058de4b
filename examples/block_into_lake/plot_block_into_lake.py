#!/usr/bin/env python3
"""Plots a run of configs/depth_averaged_coupled/job.yaml (a block sliding into a lake).

    examples/block_into_lake/plot_block_into_lake.py runs/block_into_lake

Writes <run>/plots/sections.png: the long section along the channel's axis
(y = 5 m) at a few times, the ground, the solid layer on it and the water on
top; and <run>/plots/deposit.png: the solid depth and the water's depth
over the plan at the end.
Needs python3-h5py and python3-matplotlib (Debian).
"""
import glob
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def snapshots(pattern):
    """[(time, file)] of a run's HDF5 snapshots, in time order."""
    found = []
    for name in sorted(glob.glob(pattern)):
        with h5py.File(name, "r") as f:
            found.append((float(f.attrs["time"]), name))
    return found


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    run = sys.argv[1]
    water = snapshots(os.path.join(run, "lake", "swe_*.h5"))
    points = snapshots(os.path.join(run, "mass", "points_*.h5"))
    if not water or not points:
        sys.exit(f"no lake/swe_*.h5 or mass/points_*.h5 under {run}")
    os.makedirs(os.path.join(run, "plots"), exist_ok=True)

    with h5py.File(water[0][1], "r") as f:
        ny, nx = f["fields/h"].shape
    dx = 40.0 / nx
    x = (np.arange(nx) + 0.5) * dx
    row = ny // 2

    wanted = [0.0, 1.0, 2.0, 3.0, 5.0, 8.0]
    chosen = [min(water, key=lambda s: abs(s[0] - t)) for t in wanted]
    fig, axes = plt.subplots(len(chosen), 1, figsize=(9, 2.0 * len(chosen)), sharex=True)
    for ax, (t, name) in zip(axes, chosen):
        with h5py.File(name, "r") as f:
            bed = f["fields/bed"][row]
            solid = f["fields/solid_depth"][row]
            h = f["fields/h"][row]
        top = bed + solid
        ax.fill_between(x, 0.0, bed, color="0.75", lw=0)
        ax.fill_between(x, bed, top, color="sienna", lw=0, label="solids")
        ax.fill_between(x, top, top + h, where=h > 1e-4, color="tab:blue", alpha=0.6, lw=0,
                        label="water")
        ax.set_ylim(0.0, 8.0)
        ax.set_ylabel("z [m]")
        ax.text(0.99, 0.85, f"t = {t:.1f} s", transform=ax.transAxes, ha="right")
    axes[0].legend(loc="upper center", ncol=2, frameon=False)
    axes[-1].set_xlabel("x [m] (along the channel's axis, y = 5 m)")
    fig.tight_layout()
    fig.savefig(os.path.join(run, "plots", "sections.png"), dpi=110)

    t_end, last_water = water[-1]
    with h5py.File(last_water, "r") as f:
        solid = f["fields/solid_depth"][:]
        h = f["fields/h"][:]
    with h5py.File(points[-1][1], "r") as f:
        damage = f["fields/damage"][:]
    fig, axes = plt.subplots(2, 1, figsize=(9, 5.5), sharex=True)
    extent = (0.0, 40.0, 0.0, 10.0)
    im = axes[0].imshow(np.where(solid > 1e-3, solid, np.nan), origin="lower", extent=extent,
                        cmap="copper_r", aspect="auto")
    fig.colorbar(im, ax=axes[0], label="solid depth [m]")
    axes[0].set_ylabel("y [m]")
    axes[0].set_title(f"t = {t_end:.1f} s: the deposit ({np.mean(damage >= 1.0):.0%} of its "
                      "points fully fragmented) and the water")
    im = axes[1].imshow(np.where(h > 1e-4, h, np.nan), origin="lower", extent=extent,
                        cmap="Blues", aspect="auto")
    fig.colorbar(im, ax=axes[1], label="water depth [m]")
    axes[1].set_xlabel("x [m]")
    axes[1].set_ylabel("y [m]")
    fig.tight_layout()
    fig.savefig(os.path.join(run, "plots", "deposit.png"), dpi=110)
    print(f"wrote {run}/plots/sections.png and deposit.png")


if __name__ == "__main__":
    main()
