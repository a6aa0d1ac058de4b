#!/usr/bin/python3
"""Snapshots and free surface of the underwater debris flow (MPM + ICE).

    examples/debris_underwater/plot_debris_flow.py RUN_DIR [--times 0 0.2 0.4 0.8] [--soil soil]
                                                   [--water water] [--still-water 1.6]
                                                   [--output RUN_DIR/plots]

RUN_DIR is the --output of `cosim run configs/ice_coupled/debris_underwater/job.yaml` (or of
full/job.yaml). It reads the particle snapshots (RUN_DIR/soil/particles_*.h5) and the ICE
snapshots (RUN_DIR/water/ice_*.h5, the grid from ice.xdmf) and writes, like Tran et al.,
MPMICE, Figs. 12 and 13:
  snapshots.png     one panel per time: the water's share of the fluid in each cell (blue: water,
                    white: air), the rigid bed (grey points) and the sand's points coloured by
                    their mean effective stress p' = -tr(sigma') / 3 (green: near zero)
  free_surface.png  the free-surface elevation eta(x) - h0 at 0.4 s and 0.8 s (and the other
                    times asked for), eta(x) = y_top - sum_j dy phi_air / (phi_air + phi_water)
and prints, per time, the slide front (the farthest sand point along the bed, from the box's
toe), the deepest trough over the sand and the highest crest ahead of it.
"""
import argparse
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from cosim_outputs import ice_grid, nearest, snapshots  # noqa: E402

TOE = (1.10, 0.90)  # the sand's initial toe on the bed (sand.yaml)








def fluid(path):
    with h5py.File(path, "r") as f:
        water = f["fields/volume_fraction_water"][:]
        air = f["fields/volume_fraction_air"][:]
    return water, air


def free_surface(water, air, origin, spacing):
    """eta per column: the domain top minus the air's share of each cell's fluid."""
    share = air / np.maximum(air + water, 1e-30)
    ny, nx = water.shape
    top = origin[1] + ny * spacing[1]
    x = origin[0] + (np.arange(nx) + 0.5) * spacing[0]
    return x, top - share.sum(axis=0) * spacing[1]


def particles(path):
    with h5py.File(path, "r") as f:
        xy = f["geometry/xyz"][:, :2]
        body = f["fields/body"][:]
        sigma = f["fields/effective_stress"][:]
    mean = -(sigma[:, 0] + sigma[:, 1] + sigma[:, 2]) / 3.0
    return xy, body, mean


def front(xy, body):
    """Farthest sand point along the bed's downslope direction (1, -1)/sqrt(2), from the toe."""
    sand = xy[body == 0]
    along = ((sand[:, 0] - TOE[0]) - (sand[:, 1] - TOE[1])) / math.sqrt(2.0)
    return along.max(), sand[np.argmax(along)]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--times", type=float, nargs="+", default=[0.0, 0.2, 0.4, 0.8])
    parser.add_argument("--soil", default="soil")
    parser.add_argument("--water", default="water")
    parser.add_argument("--still-water", type=float, default=1.6, help="still-water level h0 [m]")
    parser.add_argument("--output")
    args = parser.parse_args()
    soil_dir = os.path.join(args.run, args.soil)
    water_dir = os.path.join(args.run, args.water)
    soil = snapshots(soil_dir, "particles_*.h5")
    water = snapshots(water_dir, "ice_*.h5")
    if not soil or not water:
        print(f"{args.run}: no particle or ICE snapshots", file=sys.stderr)
        return 2
    origin, spacing, (nx, ny) = ice_grid(water_dir)
    extent = [origin[0], origin[0] + nx * spacing[0], origin[1], origin[1] + ny * spacing[1]]
    out = args.output or os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)

    fig, axes = plt.subplots(len(args.times), 1, figsize=(8.0, 2.45 * len(args.times) + 0.6), squeeze=False,
                             constrained_layout=True)
    scatter = None
    profiles = []
    for ax, t in zip(axes[:, 0], args.times):
        w, s = nearest(water, t, 0.026), nearest(soil, t, 0.026)
        if w:
            wf, af = fluid(w)
            share = wf / np.maximum(wf + af, 1e-30)
            ax.imshow(share, origin="lower", extent=extent, cmap="Blues", vmin=0.0, vmax=1.6,
                      interpolation="nearest", aspect="equal")
            x, eta = free_surface(wf, af, origin, spacing)
            profiles.append((t, x, eta))
            ax.plot(x, eta, color="#08306b", lw=0.8)
        if s:
            xy, body, mean = particles(s)
            bed = body != 0
            ax.scatter(xy[bed, 0], xy[bed, 1], s=0.5, color="0.6", rasterized=True)
            sand = body == 0
            scatter = ax.scatter(xy[sand, 0], xy[sand, 1], c=mean[sand] / 1e3, s=2.0, cmap="RdYlGn_r",
                                 vmin=-1.0, vmax=6.0, rasterized=True)
            distance, at = front(xy, body)
            trough = ""
            if w:
                over = (x > 0.45) & (x < at[0] + 0.05)
                ahead = x > at[0]
                trough = (f", trough {eta[over].min() - args.still_water:+.3f} m at x = {x[over][np.argmin(eta[over])]:.2f} m"
                          f", crest {eta[ahead].max() - args.still_water:+.3f} m at x = {x[ahead][np.argmax(eta[ahead])]:.2f} m")
            print(f"t = {t:g} s: front {distance:.3f} m down the bed from the toe (at x = {at[0]:.2f} m){trough}")
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], extent[3])
        ax.set_ylabel("y [m]")
        ax.set_title(f"t = {t:g} s", fontsize=9, loc="left")
    axes[-1, 0].set_xlabel("x [m]")
    if scatter is not None:
        fig.colorbar(scatter, ax=axes[:, 0].tolist(), label="mean effective stress p' [kPa]", shrink=0.5)
    fig.suptitle("Underwater debris flow: sand (points), water share of the fluid (blue)", fontsize=10)
    path = os.path.join(out, "snapshots.png")
    fig.savefig(path, dpi=130)
    plt.close(fig)
    print(path)

    fig, ax = plt.subplots(figsize=(7.5, 3.2))
    for t, x, eta in profiles:
        keep = x > 0.45  # right of the bed's top corner, where there is a free surface
        ax.plot(x[keep], eta[keep] - args.still_water, lw=1.2 if t in (0.4, 0.8) else 0.7,
                label=f"t = {t:g} s")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("x [m]")
    ax.set_ylabel(r"$\eta - h_0$ [m]")
    ax.set_title("Free-surface elevation (cf. Tran et al., MPMICE, Fig. 13)", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(out, "free_surface.png")
    fig.savefig(path, dpi=130)
    plt.close(fig)
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
