#!/usr/bin/python3
"""Writes shaking_table_velocity.csv: the prescribed velocity of the shaking table of
configs/ice_coupled/submarine_landslide (Tran et al., MPMICE, Fig. 19: 1 g at 2 Hz for 20 s).

The ground acceleration a(t) = A cos(omega (t - t0)) (A = 9.81 m/s^2, omega = 2 pi 2 Hz)
integrates to the velocity v(t) = (A / omega) sin(omega (t - t0)) and the displacement
x(t) = (A / omega^2) (1 - cos(omega (t - t0))): both zero when the shaking starts at t0, the
velocity back at zero when it ends (20 s is 40 whole periods), the table between 0 and
2 A / omega^2 = 0.124 m from its start (never behind it). Velocity amplitude A / omega =
0.781 m/s. Rows every 1/200 s (100 per period; the solver interpolates linearly, which keeps
the displacement per half period within 0.03 % and the peak acceleration within 0.07 %); zero before t0 and after
t0 + 20 s.

    configs/ice_coupled/submarine_landslide/make_shaking_table_velocity.py [--start 3.0]
"""
import argparse
import math
import os

A = 9.81           # 1 g [m/s^2]
FREQUENCY = 2.0    # [Hz]
DURATION = 20.0    # [s]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--start", type=float, default=3.0, help="time the shaking starts [s]")
    parser.add_argument("--rows-per-second", type=int, default=200)
    parser.add_argument("--output", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                         "shaking_table_velocity.csv"))
    args = parser.parse_args()
    omega = 2.0 * math.pi * FREQUENCY
    rows = [(0.0, 0.0)] if args.start > 0.0 else []
    count = int(round(DURATION * args.rows_per_second))
    for k in range(count + 1):
        s = k / args.rows_per_second
        v = A / omega * math.sin(omega * s)
        rows.append((args.start + s, 0.0 if k in (0, count) else v))
    with open(args.output, "w") as f:
        f.write("time [s],vx [m/s],vy [m/s]\n")
        for t, v in rows:
            f.write(f"{t:.6f},{v:.9f},0\n")
    print(f"wrote {args.output}: {len(rows)} rows, shaking {args.start} s to {args.start + DURATION} s")


if __name__ == "__main__":
    main()
