#!/usr/bin/python3
"""Runout and soil speed of the clay column collapse (Zheng et al., Sec. 4.3, Table 3) from an mpm_solver run.

    examples/clay_column/measure_clay_column.py RUN_DIR [RUN_DIR ...] [--reference CSV] [--rws 1.0]

For each run directory (the --output of mpm_solver with
configs/mpm/clay_column_seed002.yaml) and each Table 3 instant t = 0.5, 1.0, 5.0 s:
  ds/hs  = (x_front(t) - x_front(0)) / h_s, x_front the largest particle x among the
           points within `base_band` of the floor (the toe of the soil at the base);
           ds_any/hs uses the rightmost particle anywhere (almost always the same point);
  vs_max = max_p |v_p(t)| / sqrt(g h_s), the largest particle speed at that instant.
h_s = h0 = 1 m. Snapshots must exist at these instants (output.every = 0.1 s does it).
The paper's numbers (R_ws = 1.0 by default) are printed alongside with the relative error.
"""
import argparse
import csv
import glob
import math
import os
import sys

import h5py
import numpy as np

G = 9.81
H_S = 1.0
INSTANTS = (0.5, 1.0, 5.0)
DEFAULT_REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "configs", "bench",
                                 "reference", "zheng_table3_clay_column_still_water.csv")


def snapshots(run_dir):
    """{time: path} of the particle snapshots of a run."""
    out = {}
    for path in sorted(glob.glob(os.path.join(run_dir, "particles_*.h5"))):
        with h5py.File(path, "r") as f:
            out[float(f.attrs["time"])] = path
    return out


def read(path):
    with h5py.File(path, "r") as f:
        return f["geometry/xyz"][:, :2], f["fields/velocity"][:, :2]


def front(xy, base_band):
    y0 = xy[:, 1].min()
    near_base = xy[:, 1] <= y0 + base_band
    return xy[near_base, 0].max(), xy[:, 0].max()


def measure(run_dir, base_band):
    snaps = snapshots(run_dir)
    if not snaps:
        raise SystemExit(f"{run_dir}: no particles_*.h5")
    xy0, _ = read(snaps[min(snaps)])
    base0, any0 = front(xy0, base_band)
    rows = {}
    for t in INSTANTS:
        match = [s for s in snaps if abs(s - t) < 1e-6]
        if not match:
            rows[t] = None
            continue
        xy, v = read(snaps[match[0]])
        base, anyx = front(xy, base_band)
        speed = np.linalg.norm(v, axis=1).max()
        rows[t] = {"ds": (base - base0) / H_S, "ds_any": (anyx - any0) / H_S,
                   "vs": speed / math.sqrt(G * H_S)}
    return rows, max(snaps)


def reference(path, rws):
    ref = {}
    with open(path) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            if abs(float(row["R_ws"]) - rws) < 1e-9:
                ref[float(row["t_s"])] = (float(row["ds_over_hs"]), float(row["vs_max"]))
    return ref


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--reference", default=DEFAULT_REFERENCE)
    parser.add_argument("--rws", type=float, default=1.0, help="Table 3 row to compare with")
    parser.add_argument("--base-band", type=float, default=0.1, help="height above the lowest point counted as base [m]")
    args = parser.parse_args()
    ref = reference(args.reference, args.rws) if os.path.exists(args.reference) else {}
    print(f"{'run':28s} {'t':>4s} {'ds/hs':>7s} {'ref':>6s} {'err%':>6s} {'ds_any':>7s} "
          f"{'vs_max':>7s} {'ref':>6s} {'err%':>6s}")
    for run in args.runs:
        rows, last = measure(run, args.base_band)
        name = os.path.basename(os.path.normpath(run))
        for t in INSTANTS:
            r = rows[t]
            if r is None:
                print(f"{name:28s} {t:4.1f}  (no snapshot; run ended at {last:.2f} s)")
                continue
            ds_ref, vs_ref = ref.get(t, (math.nan, math.nan))
            print(f"{name:28s} {t:4.1f} {r['ds']:7.3f} {ds_ref:6.3f} {100 * (r['ds'] / ds_ref - 1):6.1f} "
                  f"{r['ds_any']:7.3f} {r['vs']:7.3f} {vs_ref:6.3f} {100 * (r['vs'] / vs_ref - 1):6.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
