#!/usr/bin/env python3
"""Writes valley.asc: a synthetic valley, 2 km x 2 km on 2 m cells (1001 x 1001 values).

The valley floor falls along x at 8 %; its sides rise across y as a parabola
to 200 m above the floor 1 km away from the axis, with a low hill rippling
the slopes. ESRI ASCII, values at the cell centres (xllcenter/yllcenter).
"""
import math
import sys

N, SIZE = 1001, 2.0
path = sys.argv[1] if len(sys.argv) > 1 else "valley.asc"
with open(path, "w") as f:
    f.write(f"ncols {N}\nnrows {N}\nxllcenter 0\nyllcenter 0\ncellsize {SIZE}\nNODATA_value -9999\n")
    for row in range(N - 1, -1, -1):  # north first
        y = row * SIZE
        across = (y - 1000.0) / 1000.0
        values = []
        for col in range(N):
            x = col * SIZE
            z = 300.0 - 0.08 * x + 200.0 * across * across + 5.0 * math.sin(x / 90.0) * math.cos(y / 70.0)
            values.append(f"{z:.3f}")
        f.write(" ".join(values) + "\n")
print(path)
