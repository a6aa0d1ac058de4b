#!/usr/bin/python3
"""Free surface and soil of an MPM <-> shallow-water job, and its gauge time series.

    examples/clay_column_in_water/plot_pairing.py RUN_DIR [--times 0 0.5 1 5] [--soil soil] [--water water]
                                                  [--h-s 1.0] [--output RUN_DIR/plots]

RUN_DIR is the --output of `cosim run` (participants' outputs in RUN_DIR/<name>/).
Writes, like Zheng et al.'s Figs. 8-10 and 11/16:
  profiles.png  one panel per time: soil particles coloured by vertical stress, the bed
                and the water between bed and free surface
  gauges.png    (eta - eta_0) / h_s at every gauge of gauges.csv
A standalone swe_fluid or mpm_solver run directory works too (the other half is left out).
"""
import argparse
import csv
import glob
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def snapshots(directory, pattern):
    """{time: path} of the HDF5 snapshots of one participant."""
    out = {}
    for path in sorted(glob.glob(os.path.join(directory, pattern))):
        if path.endswith("_mesh.h5"):
            continue
        with h5py.File(path, "r") as f:
            out[float(f.attrs["time"])] = path
    return out


def nearest(snaps, t):
    if not snaps:
        return None
    key = min(snaps, key=lambda s: abs(s - t))
    return snaps[key] if abs(key - t) < 0.051 else None


def water_profile(directory, path):
    with h5py.File(os.path.join(directory, "swe_mesh.h5"), "r") as m:
        edges = m["geometry/xyz"][:, 0]
    with h5py.File(path, "r") as f:
        return 0.5 * (edges[1:] + edges[:-1]), f["fields/eta"][:], f["fields/bed"][:], f["fields/h"][:]


def soil_points(path):
    with h5py.File(path, "r") as f:
        xy = f["geometry/xyz"][:, :2]
        stress = f["fields/stress"][:, 1] if "fields/stress" in f else np.zeros(len(xy))  # sigma_yy (xx, yy, zz, ...)
    return xy, stress


def plot_profiles(run, soil_dir, water_dir, times, out):
    soil = snapshots(soil_dir, "particles_*.h5") if soil_dir else {}
    water = snapshots(water_dir, "swe_*.h5") if water_dir else {}
    fig, axes = plt.subplots(len(times), 1, figsize=(9, 1.9 * len(times)), sharex=True, squeeze=False)
    scatter = None
    for ax, t in zip(axes[:, 0], times):
        w = nearest(water, t)
        if w:
            x, eta, bed, h = water_profile(water_dir, w)
            wet = h > 1e-6
            ax.fill_between(x, bed, np.where(wet, eta, bed), color="#9ecae1", step="mid", label="water")
            ax.plot(x, np.where(wet, eta, np.nan), color="#08519c", lw=1.2, label="free surface")
            ax.plot(x, bed, color="#636363", lw=0.8, ls="--", label="bed (soil envelope)")
        s = nearest(soil, t)
        if s:
            xy, syy = soil_points(s)
            scatter = ax.scatter(xy[:, 0], xy[:, 1], c=syy / 1e3, s=3, cmap="viridis",
                                 vmin=min(-1.0, np.percentile(syy, 1) / 1e3), vmax=0.0, label="soil")
        ax.set_ylabel("z [m]")
        ax.set_title(f"t = {t:g} s", fontsize=9, loc="left")
        ax.set_aspect("auto")
    axes[-1, 0].set_xlabel("x [m]")
    axes[0, 0].legend(loc="upper right", fontsize=7, ncol=4)
    if scatter is not None:
        fig.colorbar(scatter, ax=axes[:, 0].tolist(), label="vertical stress [kPa]", shrink=0.8)
    fig.suptitle(os.path.basename(os.path.normpath(run)))
    path = os.path.join(out, "profiles.png")
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def plot_gauges(run, water_dir, h_s, out):
    path = os.path.join(water_dir, "gauges.csv") if water_dir else None
    if not path or not os.path.exists(path):
        return None
    with open(path) as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array(rows[1:], dtype=float)
    if len(data) == 0:
        return None
    t = data[:, 0]
    fig, ax = plt.subplots(figsize=(8, 3.2))
    for k, name in enumerate(header):
        if name.startswith("eta_"):
            eta = data[:, k]
            label = name[len("eta_"):].split(" [")[0]
            ax.plot(t, (eta - eta[0]) / h_s, lw=1.0, label=label)
    ax.set_xlabel("t [s]")
    ax.set_ylabel(r"$(\eta - \eta_0) / h_s$")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.legend(fontsize=8)
    ax.set_title(f"{os.path.basename(os.path.normpath(run))}: gauges", fontsize=9)
    fig.tight_layout()
    out_path = os.path.join(out, "gauges.png")
    fig.savefig(out_path, dpi=130)
    plt.close(fig)
    return out_path


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--times", type=float, nargs="+", default=[0.0, 0.5, 1.0, 5.0])
    parser.add_argument("--soil", default="soil", help="participant name of the MPM solver")
    parser.add_argument("--water", default="water", help="participant name of the shallow-water solver")
    parser.add_argument("--h-s", type=float, default=1.0, help="length scale h_s of the gauge plot [m]")
    parser.add_argument("--output", help="directory for the PNGs (default RUN/plots)")
    args = parser.parse_args()

    def participant(name, marker):
        for d in (os.path.join(args.run, name), args.run):
            if glob.glob(os.path.join(d, marker)):
                return d
        return None

    soil_dir = participant(args.soil, "particles_*.h5")
    water_dir = participant(args.water, "swe_*.h5")
    if not soil_dir and not water_dir:
        print(f"{args.run}: no particle or shallow-water snapshots found", file=sys.stderr)
        return 2
    out = args.output or os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)
    print(plot_profiles(args.run, soil_dir, water_dir, args.times, out))
    gauges = plot_gauges(args.run, water_dir, args.h_s, out)
    if gauges:
        print(gauges)
    return 0


if __name__ == "__main__":
    sys.exit(main())
