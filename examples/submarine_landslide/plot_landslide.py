#!/usr/bin/python3
"""Shear strain, pore water pressure and velocity of the earthquake-induced submarine landslide.

    examples/submarine_landslide/plot_landslide.py RUN_DIR [--times 1 2 3 4 5] [--soil soil]
                                                   [--water water] [--sea-level 42]
                                                   [--output RUN_DIR/plots]

RUN_DIR is the --output of `cosim run configs/ice_coupled/submarine_landslide/job.yaml` (or of
full/job.yaml, with e.g. --times 4 8 12 16 20 24). It reads the particle snapshots
(RUN_DIR/soil/particles_*.h5) and the ICE snapshots (RUN_DIR/water/ice_*.h5, grid from ice.xdmf)
and writes, like Tran et al., MPMICE, Figs. 21-23, one row per time:
  landslide.png  left: the soil's points coloured by their largest in-plane shear strain
                 gamma = 2 sqrt(((e_xx - e_yy) / 2)^2 + e_xy^2) of the Hencky strain;
                 middle: the pore water pressure [atm] in the fluid's cells (where the soil is:
                 its pores; elsewhere the sea), with the soil's outline;
                 right: the soil's points coloured by their speed |v| [m/s]
  excess.png     the excess pore pressure p - p_hydrostatic [kPa] in the fluid's cells, the
                 sheared points (top 5 % of the accumulated plastic strain) drawn over it
and prints, per time, the crest's settlement and the toe's advance (probes.csv), the largest
shear strain and the excess pore pressure in the cells of the most and of the least sheared soil.
"""
import argparse
import csv
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from cosim_outputs import ice_grid, nearest, snapshots  # noqa: E402

ATMOSPHERE = 101325.0
RHO_G = 999.8 * 9.81








def soil_points(path):
    with h5py.File(path, "r") as f:
        xy = f["geometry/xyz"][:, :2]
        body = f["fields/body"][:]
        e = f["fields/strain"][:]
        v = f["fields/velocity"][:, :2]
        plastic = f["fields/plastic_strain"][:]
    s = body == 0
    gamma = 2.0 * np.sqrt((0.5 * (e[:, 0] - e[:, 1])) ** 2 + e[:, 3] ** 2)
    return xy[s], gamma[s], np.linalg.norm(v[s], axis=1), plastic[s], xy[~s]


def pressure(path):
    with h5py.File(path, "r") as f:
        return f["fields/pressure"][:]


def excess_field(p, origin, spacing, sea_level):
    ny, nx = p.shape
    y = origin[1] + (np.arange(ny) + 0.5) * spacing[1]
    return p - (ATMOSPHERE + RHO_G * np.clip(sea_level - y, 0.0, None))[:, None]


def cell_of(xy, origin, spacing, shape):
    ny, nx = shape
    i = np.clip(((xy[:, 0] - origin[0]) / spacing[0]).astype(int), 0, nx - 1)
    j = np.clip(((xy[:, 1] - origin[1]) / spacing[1]).astype(int), 0, ny - 1)
    inside = (xy[:, 1] >= origin[1]) & (xy[:, 1] <= origin[1] + ny * spacing[1])
    return j, i, inside


def probes(directory):
    path = os.path.join(directory, "probes.csv")
    if not os.path.exists(path):
        return None, None
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], np.array(rows[1:], dtype=float)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--times", type=float, nargs="+", default=[1.0, 2.0, 3.0, 4.0, 5.0])
    parser.add_argument("--soil", default="soil")
    parser.add_argument("--water", default="water")
    parser.add_argument("--sea-level", type=float, default=42.0)
    parser.add_argument("--output")
    args = parser.parse_args()
    soil_dir, water_dir = os.path.join(args.run, args.soil), os.path.join(args.run, args.water)
    soil, water = snapshots(soil_dir, "particles_*.h5"), snapshots(water_dir, "ice_*.h5")
    if not soil or not water:
        print(f"{args.run}: no particle or ICE snapshots", file=sys.stderr)
        return 2
    origin, spacing, (nx, ny) = ice_grid(water_dir)
    extent = [origin[0], origin[0] + nx * spacing[0], origin[1], origin[1] + ny * spacing[1]]
    header, probe = probes(soil_dir)
    out = args.output or os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)

    times = [t for t in args.times if nearest(soil, t, 0.26) and nearest(water, t, 0.26)]
    fig, axes = plt.subplots(len(times), 3, figsize=(14, 2.0 * len(times) + 0.8), squeeze=False,
                             constrained_layout=True)
    fig2, axes2 = plt.subplots(len(times), 1, figsize=(6.5, 2.0 * len(times) + 0.8), squeeze=False,
                               constrained_layout=True)
    art = [None, None, None, None]
    for row, t in enumerate(times):
        xy, gamma, speed, plastic, table = soil_points(nearest(soil, t, 0.26))
        p = pressure(nearest(water, t, 0.26))
        excess = excess_field(p, origin, spacing, args.sea_level)
        ax = axes[row]
        art[0] = ax[0].scatter(xy[:, 0], xy[:, 1], c=gamma, s=3, cmap="magma_r", vmin=0.0, vmax=0.2, rasterized=True)
        art[1] = ax[1].imshow(p / ATMOSPHERE, origin="lower", extent=extent, cmap="viridis", vmin=0.0, vmax=5.5,
                              interpolation="nearest", aspect="auto")
        ax[1].scatter(xy[:, 0], xy[:, 1], s=0.2, color="w", alpha=0.25, rasterized=True)
        art[2] = ax[2].scatter(xy[:, 0], xy[:, 1], c=speed, s=3, cmap="turbo", vmin=0.0, vmax=1.0, rasterized=True)
        for a in ax:
            a.scatter(table[:, 0], table[:, 1], s=0.5, color="0.5", rasterized=True)
            a.set_xlim(0, 80)
            a.set_ylim(0, 50)
            a.set_aspect("equal")
        ax[0].set_ylabel(f"t = {t:g} s\ny [m]")
        art[3] = axes2[row, 0].imshow(excess / 1e3, origin="lower", extent=extent, cmap="RdBu_r", vmin=-150, vmax=150,
                                      interpolation="nearest", aspect="auto")
        sheared = plastic >= np.percentile(plastic, 95)
        axes2[row, 0].scatter(xy[sheared, 0], xy[sheared, 1], s=1.5, color="k", rasterized=True)
        axes2[row, 0].set_xlim(0, 80)
        axes2[row, 0].set_ylim(0, 50)
        axes2[row, 0].set_aspect("equal")
        axes2[row, 0].set_ylabel(f"t = {t:g} s\ny [m]")
        # Excess pore pressure in the cells of the most and the least sheared soil.
        j, i, inside = cell_of(xy, origin, spacing, p.shape)
        most = sheared & inside
        least = (plastic <= np.percentile(plastic, 50)) & inside
        crest = ""
        if probe is not None:
            r = int(np.argmin(abs(probe[:, 0] - t)))
            col = {n: k for k, n in enumerate(header)}
            crest = (f"crest settles {-probe[r, col['crest_displacement_y [m]']]:.3f} m, "
                     f"toe advances {probe[r, col['toe_displacement_x [m]']]:.3f} m; ")
        print(f"t = {t:g} s: {crest}shear strain max {gamma.max():.3f} (95 % {np.percentile(gamma, 95):.3f}); "
              f"excess pore pressure under the sheared 5 % {excess[j[most], i[most]].mean() / 1e3:+.1f} kPa, "
              f"under the least sheared half {excess[j[least], i[least]].mean() / 1e3:+.1f} kPa, "
              f"lowest in the soil {excess[j[inside], i[inside]].min() / 1e3:+.1f} kPa")
    for k, (a, title) in enumerate(zip(axes[0], ["shear strain (Fig. 21)", "pore water pressure [atm] (Fig. 22)",
                                                   "speed [m/s] (Fig. 23)"])):
        a.set_title(title, fontsize=9)
        fig.colorbar(art[k], ax=axes[:, k].tolist(), shrink=0.7)
    for a in axes[-1]:
        a.set_xlabel("x [m]")
    fig.suptitle("Earthquake-induced submarine landslide (MPM + ICE)", fontsize=10)
    path = os.path.join(out, "landslide.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(path)
    fig2.colorbar(art[3], ax=axes2[:, 0].tolist(), label="excess pore pressure [kPa]", shrink=0.7)
    axes2[0, 0].set_title("excess pore pressure; black: the 5 % most sheared points", fontsize=9)
    axes2[-1, 0].set_xlabel("x [m]")
    path = os.path.join(out, "excess.png")
    fig2.savefig(path, dpi=110)
    plt.close(fig2)
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
