#!/usr/bin/env python3
"""The peer of `driftlab fit LOG`: numpy loadtxt of a driftlab log and scipy's curve_fit (Levenberg-Marquardt) of
eq. 1 to each of its four channels, as an engineer without driftlab would write it. Prints C1, C2, T per channel."""
import sys

import numpy as np
from scipy.optimize import curve_fit


def eq1(t, c1, c2, tau):
    return c1 * -np.expm1(-t / tau) + c2


def main(path):
    # A driftlab log: '#' metadata, then a header line t_s,seq,gyro,accel_x,accel_y,accel_z,...
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                names = line.strip().split(",")
                break
        data = np.loadtxt(f, delimiter=",", usecols=range(len(names)))
    t = data[:, names.index("t_s")]
    for name in ("gyro", "accel_x", "accel_y", "accel_z"):
        y = data[:, names.index(name)]
        start = (y[-1] - y[0], y[0], (t[-1] - t[0]) / 5)
        (c1, c2, tau), _ = curve_fit(eq1, t, y, p0=start, method="lm")
        print(f"{name}: C1 {c1:.4f} C2 {c2:.4f} T {tau:.2f}")


if __name__ == "__main__":
    main(sys.argv[1])
