#!/usr/bin/env python3
"""Writes valley_bed.asc: a hillside above a flat valley floor, 1.6 km x 400 m on 10 m cells.

A 30 deg slope down to the valley floor at x = 600 m (elevation 0), flat
beyond. ESRI ASCII, values at the cell centres (xllcenter/yllcenter).
"""
import math
import sys

DX, NX, NY = 10.0, 161, 41
path = sys.argv[1] if len(sys.argv) > 1 else "valley_bed.asc"
slope = math.tan(math.radians(30.0))
with open(path, "w") as f:
    f.write(f"ncols {NX}\nnrows {NY}\nxllcenter 0\nyllcenter 0\ncellsize {DX}\nNODATA_value -9999\n")
    for _ in range(NY):
        f.write(" ".join(f"{max(0.0, (600.0 - i * DX) * slope):.3f}" for i in range(NX)) + "\n")
