#!/usr/bin/env python3
"""The peer of `driftlab allan FILE --kind rate --tau0 1 --grid octave`: numpy reads one rate sample a
line and computes the overlapping Allan deviation at octave averaging factors as allantools does (phase as the
cumulative sum of the rate times tau0, then second differences of the phase at stride m). Prints tau and ADEV."""
import sys

import numpy as np


def main(path, tau0=1.0):
    rate = np.loadtxt(path)
    phase = np.concatenate(([0.0], np.cumsum(rate) * tau0))
    n = len(phase)
    m = 1
    while m <= (n - 1) // 4:
        d = phase[2 * m:] - 2 * phase[m:-m] + phase[:-2 * m]
        adev = np.sqrt(np.mean(d * d) / 2.0) / (m * tau0)
        print(f"{m * tau0:g} {adev:.6g}")
        m *= 2


if __name__ == "__main__":
    main(sys.argv[1])
