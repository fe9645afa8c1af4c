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
  `rms_slope_from_profile`;
- a map read as its profiles along x and along y (`--direction`; the map's
  plane removed, then each profile about its own mean): Rq =
  `rms_height_from_profile`, RΔq = `rms_slope_from_profile` (y's on the
  transposed map);

then Sa, Ssk, Sku, Sz (Ra, Rsk, Rku, Rz), which SurfaceTopography 1.27.1
does not compute, from the same detrended heights with numpy (ISO 25178-2
and ISO 4287 over the whole data: the mean |h - mean|, the third and
fourth central moments over Sq^3 and Sq^4, the largest height minus the
smallest; profiles each about its own mean, Rz their ranges' mean); all
without a window (SurfaceTopography applies none to these).

requirements: SurfaceTopography==1.27.1
"""
import os

import numpy as np
import scipy
import SurfaceTopography
from SurfaceTopography import Topography, UniformLineScan, read_topography

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data")


def r(v):
    return repr(float(v))


def amplitude(h, per_row=False):
    """Sa, Ssk, Sku, Sz of heights h (rows of profiles when per_row)."""
    h = np.atleast_2d(h)
    d = h - (h.mean(axis=1, keepdims=True) if per_row else h.mean())
    q = np.sqrt(np.mean(d ** 2))
    sz = np.mean(h.max(axis=1) - h.min(axis=1)) if per_row else h.max() - h.min()
    return np.mean(np.abs(d)), np.mean(d ** 3) / q ** 3, np.mean(d ** 4) / q ** 4, sz


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
        out.write("# file periodic pixel_size kind rms_height rms_slope sa ssk sku sz\n")
        out.write("# (kind: map, line, or x/y for the map's profiles along x or y)\n")

        def write(name, periodic, pixel, kind, h, s, a, scale):
            sa, ssk, sku, sz = a
            out.write(f"{name} {int(periodic)} {r(pixel)} {kind} {r(h * scale)} {r(s)} "
                      f"{r(sa * scale)} {r(ssk)} {r(sku)} {r(sz * scale)}\n")

        for name, t, periodic, pixel, scale in cases:
            t = t.detrend("center" if periodic else "height")
            if t.dim == 2:
                kind, h, s = "map", t.rms_height_from_area(), t.rms_gradient()
            else:
                kind, h, s = "line", t.rms_height_from_profile(), t.rms_slope_from_profile()
            write(name, periodic, pixel, kind, h, s, amplitude(t.heights()), scale)
        # The lay map's profiles along x and y (direction_reference.py's map).
        t = read_topography(path("map_lay.txt")).detrend("height")
        hx = t.heights()
        ty = Topography(hx.T.copy(), t.physical_sizes[::-1], unit=t.unit)
        scale = 1e-6
        assert t.unit == "µm", t.unit
        for kind, tt, rows in [("x", t, hx.T), ("y", ty, hx)]:
            write("map_lay.txt", False, 0.0, kind, tt.rms_height_from_profile(),
                  tt.rms_slope_from_profile(), amplitude(rows, per_row=True), scale)


if __name__ == "__main__":
    main()
