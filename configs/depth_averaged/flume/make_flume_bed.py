#!/usr/bin/env python3
"""Writes flume_bed.asc: the flume's bed in plan view, 3.2 m x 0.5 m on 0.02 m cells.

A 35 deg incline from x = 0 to the break at x = 1.2 m (1.5 m along the slope),
then a runout falling at 3 deg, the ground at the break at elevation 0.
ESRI ASCII, values at the cell centres (xllcenter/yllcenter).
"""
import math
import sys

DX, NX, NY = 0.02, 161, 26
BREAK = 1.2
path = sys.argv[1] if len(sys.argv) > 1 else "flume_bed.asc"
with open(path, "w") as f:
    f.write(f"ncols {NX}\nnrows {NY}\nxllcenter 0\nyllcenter 0\ncellsize {DX}\nNODATA_value -9999\n")
    for _ in range(NY):
        row = []
        for i in range(NX):
            x = i * DX
            if x < BREAK:
                z = (BREAK - x) * math.tan(math.radians(35.0))
            else:
                z = -(x - BREAK) * math.tan(math.radians(3.0))
            row.append(f"{z:.5f}")
        f.write(" ".join(row) + "\n")
