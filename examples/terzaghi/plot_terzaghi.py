#!/usr/bin/python3
"""Excess pore pressure of a consolidating column against Terzaghi's solution.

    examples/terzaghi/plot_terzaghi.py RUN_DIR [--setting pan2021|tran] [--tv 0.01 0.1 0.5 1]
                                       [--output RUN_DIR/plots]

RUN_DIR is the --output of `cosim run configs/ice_coupled/terzaghi/job.yaml` (setting pan2021,
Pan et al. 2021, Sec. 4.1) or of configs/ice_coupled/terzaghi_tran/job.yaml (setting tran,
Tran et al., MPMICE, "Isothermal consolidation"). It reads the pore-pressure gauges along the
column (RUN_DIR/water/gauges.csv) and writes
  terzaghi.png  p / p0 against depth at each T_v, points from the run, lines from Terzaghi's
                solution convolved with the job's load ramp (Pan et al. 2021, eqs. 82-84)
and prints the largest error at each T_v in % of p0.
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ATMOSPHERE = 101325.0
LOAD = 1.0e4
HEIGHT = 1.0


def oedometric_modulus(e, nu):
    return e * (1 - nu) / ((1 + nu) * (1 - 2 * nu))


SETTINGS = {
    # c_v [m^2/s], load ramp [s] and its shape (as in the job's soil.yaml)
    "pan2021": (0.527e-3 ** 2 * 0.3 ** 3 / (150 * 0.7 ** 2) * oedometric_modulus(1e7, 0.3) / 1e-3,
                4.54e-3, "cycloidal"),
    "tran": (oedometric_modulus(1e7, 0.3) * 0.3 ** 3 * 1e-6 / (180 * 0.7 ** 2 * 1e-3), 6.81e-3,
             "cycloidal"),
}


def step_solution(z, t, cv):
    """Excess pore pressure under p0 applied at t = 0; z up from the impermeable bottom."""
    if t <= 0:
        return 0.0
    tv = cv * t / HEIGHT ** 2
    total = 0.0
    for m in range(1, 2001):
        k = (2 * m - 1) * math.pi / 2
        term = math.exp(-k * k * tv)
        total += (-1) ** (m - 1) / (2 * m - 1) * math.cos(k * z / HEIGHT) * term
        if term < 1e-16:
            break
    return 4 * LOAD / math.pi * total


def ramp_solution(z, t, cv, ramp, shape):
    """The step solution convolved with the load's rate: linear, or cycloidal
    (s/T - sin(2 pi s/T) / (2 pi), its rate (1 - cos(2 pi s/T)) / T)."""
    if ramp <= 0:
        return step_solution(z, t, cv)
    s = np.linspace(0.0, min(t, ramp), 201)
    rate = (1 - np.cos(2 * np.pi * s / ramp)) / ramp if shape == "cycloidal" else np.full_like(s, 1 / ramp)
    return np.trapz([step_solution(z, t - si, cv) * ri for si, ri in zip(s, rate)], s)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--setting", choices=sorted(SETTINGS), default="pan2021")
    parser.add_argument("--tv", type=float, nargs="+", default=[0.01, 0.1, 0.5, 1.0])
    parser.add_argument("--output")
    args = parser.parse_args()
    cv, ramp, shape = SETTINGS[args.setting]
    with open(os.path.join(args.run, "water", "gauges.csv")) as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array([[float(x) for x in r] for r in rows[1:]])
    columns = [i for i, h in enumerate(header) if h.startswith("p_y")]
    # Gauges are named y000, y001, ... at the cell centres along the column.
    spacing = HEIGHT / len(columns)
    heights = np.array([(i + 0.5) * spacing for i in range(len(columns))])
    fig, ax = plt.subplots(figsize=(5.5, 6))
    for tv, colour in zip(args.tv, plt.rcParams["axes.prop_cycle"].by_key()["color"]):
        t = tv * HEIGHT ** 2 / cv
        row = int(np.argmin(abs(data[:, 0] - t)))
        if abs(data[row, 0] - t) > 0.01 * t + 1e-4:
            print(f"T_v = {tv}: the run ends at t = {data[-1, 0]:.4g} s, before t = {t:.4g} s")
            continue
        p = data[row, columns] - ATMOSPHERE
        z = np.linspace(0.0, HEIGHT, 101)
        exact = [ramp_solution(zi, data[row, 0], cv, ramp, shape) for zi in z]
        at_gauges = np.array([ramp_solution(zi, data[row, 0], cv, ramp, shape) for zi in heights])
        error = np.max(abs(p - at_gauges)) / LOAD
        print(f"T_v = {tv}: largest error {100 * error:.2f} % of p0")
        ax.plot(np.array(exact) / LOAD, HEIGHT - z, color=colour, label=f"Terzaghi, T_v = {tv}")
        ax.plot(p / LOAD, HEIGHT - heights, "o", color=colour, markersize=3, markerfacecolor="none")
    ax.set_xlabel("excess pore pressure p / p0")
    ax.set_ylabel("depth below the drained top [m]")
    ax.invert_yaxis()
    ax.set_xlim(-0.02, 1.1)
    ax.set_title(f"Consolidation, {args.setting}: MPM + ICE (points) vs Terzaghi (lines)", fontsize=9)
    ax.legend(fontsize=8, loc="lower left")
    out = args.output or os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "terzaghi.png"), dpi=120)
    print(f"wrote {os.path.join(out, 'terzaghi.png')}")


if __name__ == "__main__":
    main()
