#!/usr/bin/python3
"""Temperature and pore-water velocity of the thermally driven porous cavity, and its Nusselt number.

    examples/thermal_cavity/plot_cavity.py RUN_DIR [--output RUN_DIR/plots]

RUN_DIR is the --output of `cosim run configs/ice_coupled/thermal_cavity/job.yaml`. Reads the
last snapshot of RUN_DIR/water (ice_fluid) and writes
  cavity.png  the water's temperature with its velocity arrows, and the mean Nusselt number at
              the hot wall over time (second-order one-sided wall gradient)
"""
import argparse
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HEIGHT, HOT, COLD = 5.655, 293.65, 292.65


def read(path):
    with h5py.File(path, "r") as f:
        t = float(f.attrs["time"])
        temperature = np.array(f["fields/temperature_water"])
        velocity = np.array(f["fields/velocity_water"])
    n = int(round(np.sqrt(temperature.size)))
    return t, temperature.reshape(n, n), velocity.reshape(n, n, -1)


def nusselt(temperature):
    n = temperature.shape[0]
    dx = HEIGHT / n
    gradient = (-8 * HOT + 9 * temperature[:, 0] - temperature[:, 1]) / (3 * dx)
    return -np.mean(gradient) * HEIGHT / (HOT - COLD)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--output")
    args = parser.parse_args()
    files = sorted(glob.glob(os.path.join(args.run, "water", "ice_*.h5")))
    history = [(t, nusselt(T)) for t, T, _ in (read(f) for f in files[1:])]
    t, temperature, velocity = read(files[-1])
    n = temperature.shape[0]
    x = (np.arange(n) + 0.5) * HEIGHT / n
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.8))
    image = a.contourf(x, x, temperature - 273.15, levels=21, cmap="coolwarm")
    fig.colorbar(image, ax=a, label="water temperature [°C]")
    step = max(1, n // 20)
    a.quiver(x[::step], x[::step], velocity[::step, ::step, 0], velocity[::step, ::step, 1])
    a.set_aspect("equal")
    a.set_xlabel("x [m]")
    a.set_ylabel("y [m]")
    a.set_title(f"t = {t:.3g} s, Nu = {nusselt(temperature):.3f} (literature 3.10 at Ra = 100)",
                fontsize=9)
    b.plot([h[0] for h in history], [h[1] for h in history], "o-")
    b.axhline(3.10, color="k", ls="--", label="literature, Ra = 100")
    b.set_xlabel("t [s]")
    b.set_ylabel("mean Nusselt number, hot wall")
    b.legend()
    out = args.output or os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "cavity.png"), dpi=110)
    print(f"Nu = {nusselt(temperature):.4f} at t = {t:.3g} s; wrote {os.path.join(out, 'cavity.png')}")


if __name__ == "__main__":
    main()
