"""Readers of a cosim run's outputs shared by the example plot scripts.

    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
    import cosim_outputs
"""
import csv
import glob
import os
import re

import h5py
import numpy as np


def snapshots(directory, pattern):
    """{time: path} of the HDF5 snapshots of one participant (e.g. "particles_*.h5")."""
    out = {}
    for path in sorted(glob.glob(os.path.join(directory, pattern))):
        with h5py.File(path, "r") as f:
            out[float(f.attrs["time"])] = path
    return out


def nearest(snaps, t, tolerance=0.03):
    """The path of the snapshot closest to t, or None when none is within tolerance."""
    if not snaps:
        return None
    key = min(snaps, key=lambda s: abs(s - t))
    return snaps[key] if abs(key - t) <= tolerance else None


def grid(directory, index):
    """(origin, spacing, (nx, ny)) of a participant's 2D cells, from its XDMF index (e.g. "ice.xdmf")."""
    text = open(os.path.join(directory, index)).read()
    dims = [int(v) for v in re.search(r'TopologyType="2DCoRectMesh" Dimensions="(\d+) (\d+)"', text).groups()]
    items = re.findall(r'<DataItem Format="XML" Dimensions="2"[^>]*>([^<]+)</DataItem>', text)
    # XDMF lists the slowest direction first: (y, x).
    origin = [float(v) for v in items[0].split()][::-1]
    spacing = [float(v) for v in items[1].split()][::-1]
    return np.array(origin), np.array(spacing), (dims[1] - 1, dims[0] - 1)


def openfoam_grid(directory):
    """grid() of an OpenFOAM adapter's cells."""
    return grid(directory, "openfoam.xdmf")


def ice_grid(directory):
    """grid() of an ICE solver's cells."""
    return grid(directory, "ice.xdmf")


def wave_gauges(path):
    """(t, names, surface elevations [time x gauge]) of the wave gauges in a gauges.csv.

    Every backend names a gauge's columns `<quantity>_<gauge> [unit]`; the free
    surface is `eta_<gauge> [m]`.
    """
    with open(path) as f:
        rows = list(csv.reader(f))
    header, values = rows[0], np.array([[float(v) for v in r] for r in rows[1:]])
    columns = [i for i, h in enumerate(header) if h.startswith("eta_")]
    names = [header[i][len("eta_"):].split(" [")[0] for i in columns]
    return values[:, 0], names, values[:, columns]


def particles(path):
    """(positions [n x 2], body ids, velocities [n x 2]) of a 2D particle snapshot."""
    with h5py.File(path, "r") as f:
        return f["geometry/xyz"][:, :2], f["fields/body"][:], f["fields/velocity"][:, :2]


def first_wave(t, rise, threshold=1e-3):
    """(arrival time, crest, crest time) of the first rise above threshold, or None."""
    above = np.nonzero(rise > threshold)[0]
    if not above.size:
        return None
    first = above[0]
    # the first crest: the highest point before the surface falls back below the threshold
    after = np.nonzero(rise[first:] <= threshold)[0]
    end = first + (after[0] if after.size else len(t) - first)
    crest = first + int(np.argmax(rise[first:end]))
    return t[first], rise[crest], t[crest]


def water_and_points_figure(path, times, water, soil, extent, speed_max, speed_label, title,
                            panel_height=1.9, point_size=1.5, tolerance=0.03):
    """One panel per time: a coupled OpenFOAM run's cells' water share (alpha_water times the
    fluid fraction, blue), the held bodies' points (grey) and the others' points coloured by speed.
    water and soil are snapshots() of the fluid and the MPM; writes the figure to path."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(times), 1, figsize=(8.0, panel_height * len(times) + 0.6), squeeze=False,
                             constrained_layout=True)
    scatter = None
    for ax, time in zip(axes[:, 0], times):
        w, s = nearest(water, time, tolerance), nearest(soil, time, tolerance)
        if w:
            with h5py.File(w, "r") as f:
                share = f["fields/alpha_water"][:]
                if "fluid_fraction" in f["fields"]:
                    share = share * f["fields/fluid_fraction"][:]
            ax.imshow(share, origin="lower", extent=extent, cmap="Blues", vmin=0.0, vmax=1.6,
                      interpolation="nearest", aspect="equal")
        if s:
            xy, body, v = particles(s)
            held = body != 0
            ax.scatter(xy[held, 0], xy[held, 1], s=0.3, color="0.6", rasterized=True)
            moving = body == 0
            scatter = ax.scatter(xy[moving, 0], xy[moving, 1], c=np.linalg.norm(v[moving], axis=1),
                                 s=point_size, cmap="magma_r", vmin=0.0, vmax=speed_max, rasterized=True)
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], extent[3])
        ax.set_ylabel("y [m]")
        ax.set_title(f"t = {time:g} s", fontsize=9, loc="left")
    axes[-1, 0].set_xlabel("x [m]")
    if scatter is not None:
        fig.colorbar(scatter, ax=axes[:, 0].tolist(), label=speed_label, shrink=0.5)
    fig.suptitle(title, fontsize=10)
    fig.savefig(path, dpi=130)
    plt.close(fig)
