#!/usr/bin/env python3
"""The example surface shipped with roughtui: surfaces/example.txt.

Script: scripts/example_surface.py
Pinned: SurfaceTopography==1.27.1 (requirements line below).

    python3 scripts/example_surface.py

A synthetic, isotropic, self-affine surface with a roll-off, made with
SurfaceTopography's `fourier_synthesis` (seed 2024): Hurst exponent 0.8,
C^iso(q) = (2π)² Z q^(−3.6) with the paper's convention's Z = 5e-8 m^0.4
above q_L = 2π/25 µm and flat below it, synthesised periodic on
100 µm × 100 µm (384 × 384 points) and cut to its first quarter, 50 µm ×
50 µm, 192 × 192 points (so it is not periodic, like a measurement).
Written as Gwyddion's ASCII export writes a map (heights in nm with three
decimals, ~330 kB). Licence: CC0 1.0 (public domain dedication); made by
the roughtui authors with this script.

requirements: SurfaceTopography==1.27.1
"""
import os

import numpy as np
import SurfaceTopography
from SurfaceTopography.Generation import fourier_synthesis

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "surfaces", "example.txt")
N, L = 192, 50e-6


def main():
    t = fourier_synthesis((2 * N, 2 * N), (2 * L, 2 * L), hurst=0.8, c0=(2 * np.pi) ** 2 * 5e-8,
                          long_cutoff=25e-6, unit="m", rng=2024)
    h = t.heights()[:N, :N] * 1e9
    with open(OUT, "w") as f:
        f.write("# Channel: Height (synthetic, H = 0.8, roll-off at 25 µm; "
                "scripts/example_surface.py, CC0 1.0)\n")
        f.write("# Width: 50.000 µm\n# Height: 50.000 µm\n# Value units: nm\n")
        np.savetxt(f, h.T, fmt="%.3f", delimiter="\t")


if __name__ == "__main__":
    main()
