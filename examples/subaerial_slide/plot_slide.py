#!/usr/bin/python3
"""Wave gauges and snapshots of the subaerial granular slide (MPM + OpenFOAM).

    examples/subaerial_slide/plot_slide.py RUN_DIR [--times 0 0.23 0.41 0.52] [--still-water 0.15]
                                           [--soil soil] [--water water] [--output RUN_DIR/plots]

RUN_DIR is the --output of `cosim run configs/openfoam_coupled/subaerial_slide/job.yaml`. It reads the wave gauges (RUN_DIR/water/gauges.csv), the particle snapshots
(RUN_DIR/soil/particles_*.h5) and the OpenFOAM snapshots (RUN_DIR/water/openfoam_*.h5, the grid
from openfoam.xdmf) and writes, like Pan et al. 2021, Figs. 10-12:
  gauges.png     the water surface at the four gauges G1-G4, eta - h0 against time
  snapshots.png  one panel per time: the cells' water fraction (blue), the plane (grey points)
                 and the grains coloured by their speed
and prints, per gauge, the first wave's arrival (eta - h0 first above 1 mm) and its crest.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from cosim_outputs import (  # noqa: E402
    first_wave, openfoam_grid, snapshots, water_and_points_figure, wave_gauges)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--times", type=float, nargs="+", default=[0.0, 0.23, 0.41, 0.52])
    parser.add_argument("--still-water", type=float, default=0.15, help="still-water depth h0 [m]")
    parser.add_argument("--soil", default="soil")
    parser.add_argument("--water", default="water")
    parser.add_argument("--output")
    args = parser.parse_args()
    water_dir = os.path.join(args.run, args.water)
    soil_dir = os.path.join(args.run, args.soil)
    out = args.output or os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)

    t, names, eta = wave_gauges(os.path.join(water_dir, "gauges.csv"))
    rise = eta - args.still_water
    fig, ax = plt.subplots(figsize=(7.5, 3.4))
    for g, name in enumerate(names):
        ax.plot(t, 1e3 * rise[:, g], lw=1.0, label=name)
        wave = first_wave(t, rise[:, g])
        if wave:
            print(f"{name}: first wave arrives at t = {wave[0]:.3f} s, crest {1e3 * wave[1]:.1f} mm "
                  f"at t = {wave[2]:.3f} s")
        else:
            print(f"{name}: no wave above 1 mm by t = {t[-1]:.3f} s")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("t [s]")
    ax.set_ylabel(r"$\eta - h_0$ [mm]")
    ax.set_title("Wave gauges (cf. Pan et al. 2021, Fig. 12)", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(out, "gauges.png")
    fig.savefig(path, dpi=130)
    plt.close(fig)
    print(path)

    water = snapshots(water_dir, "openfoam_*.h5")
    soil = snapshots(soil_dir, "particles_*.h5")
    if not water or not soil:
        print(f"{args.run}: no OpenFOAM or particle snapshots", file=sys.stderr)
        return 0
    origin, spacing, (nx, ny) = openfoam_grid(water_dir)
    extent = [origin[0], origin[0] + nx * spacing[0], origin[1], origin[1] + ny * spacing[1]]
    path = os.path.join(out, "snapshots.png")
    water_and_points_figure(path, args.times, water, soil, extent, 2.5, "grain speed [m/s]",
                            "Subaerial granular slide: grains (points), water fraction (blue)")
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
