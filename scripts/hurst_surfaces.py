#!/usr/bin/env python3
"""Surfaces of known Hurst exponent for the default Hurst fit's target.

Script: scripts/hurst_surfaces.py
Pinned: SurfaceTopography==1.27.1.

    python3 scripts/hurst_surfaces.py OUT_DIR [REALISATIONS]

Writes SurfaceTopography `fourier_synthesis` surfaces with a roll-off at
L/4 and a short cutoff at L/128, H in {0.3, 0.6, 0.85}, as Gwyddion text
matrices (sizes in µm, heights in nm):

- `periodic_H{H}_r{k}.txt`: 512 × 512, periodic (read with --periodic);
- `cropped_H{H}_r{k}.txt`: the 512 × 512 corner of a 1024 × 1024 periodic
  surface made with the same cutoffs (so still at L/4 and L/128 of the map
  read), plus a tilt of 2 nm per µm in x and −1 in y and an offset of 40 nm:
  non-periodic, read with the plane removed and the Hann window.

and `surfaces.txt`, one line per file: name, generated H, periodic.
`scripts/hurst_check.py` fits them with roughtui and checks the target.
"""
import os
import sys

import numpy as np
import SurfaceTopography
from SurfaceTopography.Generation import fourier_synthesis

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

N = 512
L = 10.0  # µm
HURSTS = (0.3, 0.6, 0.85)


def write(path, h_xy, size):
    """h_xy[i, j]: i along x; rows of the file are y. Heights in nm."""
    with open(path, "w") as f:
        f.write(f"# Channel: Height\n# Width: {size} µm\n# Height: {size} µm\n# Value units: nm\n")
        np.savetxt(f, h_xy.T * 1e3, fmt="%.6e")


def main():
    out = sys.argv[1]
    reps = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    os.makedirs(out, exist_ok=True)
    listing = open(os.path.join(out, "surfaces.txt"), "w")
    for k in range(reps):
        for i, hurst in enumerate(HURSTS):
            seed = 100 * k + i
            t = fourier_synthesis((N, N), (L, L), hurst, rms_height=0.1, long_cutoff=L / 4,
                                  short_cutoff=L / 128, unit="µm", rng=seed)
            name = f"periodic_H{hurst}_r{k}.txt"
            write(os.path.join(out, name), t.heights(), L)
            listing.write(f"{name} {hurst} 1\n")
            t = fourier_synthesis((2 * N, 2 * N), (2 * L, 2 * L), hurst, rms_height=0.1,
                                  long_cutoff=L / 4, short_cutoff=L / 128, unit="µm",
                                  rng=seed + 50)
            h = t.heights()[:N, :N]
            x = np.arange(N) * L / N
            h = h + 0.04 + 2e-3 * x[:, None] - 1e-3 * x[None, :]
            name = f"cropped_H{hurst}_r{k}.txt"
            write(os.path.join(out, name), h, L)
            listing.write(f"{name} {hurst} 0\n")
    listing.close()


if __name__ == "__main__":
    main()
