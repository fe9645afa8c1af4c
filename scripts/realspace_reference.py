#!/usr/bin/env python3
"""Reference real-space numbers of the measured surfaces in
crates/rough-surface/tests/data, from SurfaceTopography itself.

Script: scripts/realspace_reference.py
Pinned: SurfaceTopography==1.27.1.

    python3 scripts/realspace_reference.py

Reads the surfaces scripts/surface_reference.py wrote (the same readers and
unit conventions), detrends them as roughtui does — detrend('center') for
periodic data, detrend('height') (least-squares plane or line) otherwise —
and writes to crates/rough-surface/tests/data/realspace.txt, one line per
file: its name, periodic (0/1), the pixel size it is read with (0: from the
file), then

- maps: Sq = `rms_height_from_area` (m) and Sdq = `rms_gradient`;
- lines: Rq = `rms_height_from_profile` (m) and RΔq =
  `rms_slope_from_profile`,

all without a window (SurfaceTopography applies none to these), and the
height parameters of ISO 25178-2 (maps) and ISO 4287 (lines) of the same
detrended heights h about their mean m: Sa = mean |h - m| (m), Ssk =
mean (h - m)^3 / Sq^3, Sku = mean (h - m)^4 / Sq^4 with Sq the
`rms_height_from_area` (`rms_height_from_profile` for lines) above, and Sz =
`max()` - `min()` (m), SurfaceTopography's own extremes (it computes no Sa,
Ssk or Sku: those are NumPy's of its heights).

requirements: SurfaceTopography==1.27.1
"""
import os

import numpy as np
import scipy
import SurfaceTopography
from SurfaceTopography import UniformLineScan, read_topography

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data")


def r(v):
    return repr(float(v))


def main():
    path = lambda n: os.path.join(DATA, n)
    p = 50e-9
    heights = np.loadtxt(path("line_row.txt"))
    # (file, topography as SurfaceTopography reads it, periodic, pixel size,
    # metres per file unit): as in scripts/surface_reference.py.
    cases = [
        ("map_periodic.txt", read_topography(path("map_periodic.txt"), periodic=True), True, 0.0, 1e-9),
        ("map_windowed.txt", read_topography(path("map_windowed.txt")), False, 0.0, 1e-6),
        ("map_odd.txt", read_topography(path("map_odd.txt")), False, 0.0, 1e-9),
        ("map_pixel.txt", read_topography(path("map_pixel.txt"), physical_sizes=(40 * p, 64 * p),
                                          unit="m"), False, p, 1.0),
        ("map_rolloff.txt", read_topography(path("map_rolloff.txt"), periodic=True), True, 0.0, 1e-6),
        ("line_xz.txt", read_topography(path("line_xz.txt"), unit="m"), False, 0.0, 1.0),
        ("line_row.txt", UniformLineScan(heights, (200e3,), unit="nm", periodic=True), True, 0.0, 1e-9),
        ("line_column.txt", read_topography(path("line_column.txt")), False, 0.0, 1e-6),
    ]
    with open(path("realspace.txt"), "w") as out:
        out.write("# Real-space rms height (m) and rms slope of the surfaces in this folder, by\n")
        out.write(f"# scripts/realspace_reference.py with SurfaceTopography {SurfaceTopography.__version__}"
                  f" (numpy {np.__version__}, scipy {scipy.__version__}).\n")
        out.write("# file periodic pixel_size kind rms_height rms_slope mean_abs_height skewness"
                  " kurtosis max_height\n")
        for name, t, periodic, pixel, scale in cases:
            t = t.detrend("center" if periodic else "height")
            if t.dim == 2:
                kind, h, s = "map", t.rms_height_from_area(), t.rms_gradient()
            else:
                kind, h, s = "line", t.rms_height_from_profile(), t.rms_slope_from_profile()
            z = np.ma.compressed(t.heights())
            d = z - np.mean(z)
            sa = np.mean(np.abs(d))
            ssk = np.mean(d ** 3) / h ** 3
            sku = np.mean(d ** 4) / h ** 4
            sz = t.max() - t.min()
            out.write(f"{name} {int(periodic)} {r(pixel)} {kind} {r(h * scale)} {r(s)} "
                      f"{r(sa * scale)} {r(ssk)} {r(sku)} {r(sz * scale)}\n")


if __name__ == "__main__":
    main()
