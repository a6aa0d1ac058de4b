#!/usr/bin/env python3
"""Writes slope_break_bed.asc: a hillside in plan view, 2 km x 400 m on 10 m cells.

A 20 deg slope down to the break at x = 700 m (elevation 0), a 40 deg slope
below it down to x = 1300 m, then a flat valley floor. ESRI ASCII, values at
the cell centres (xllcenter/yllcenter).
"""
import math
import sys

DX, NX, NY = 10.0, 201, 41
path = sys.argv[1] if len(sys.argv) > 1 else "slope_break_bed.asc"
upper, lower = math.tan(math.radians(20.0)), math.tan(math.radians(40.0))
with open(path, "w") as f:
    f.write(f"ncols {NX}\nnrows {NY}\nxllcenter 0\nyllcenter 0\ncellsize {DX}\nNODATA_value -9999\n")
    for _ in range(NY):
        row = []
        for i in range(NX):
            x = i * DX
            if x < 700.0:
                z = (700.0 - x) * upper
            else:
                z = -(min(x, 1300.0) - 700.0) * lower
            row.append(f"{z:.3f}")
        f.write(" ".join(row) + "\n")
