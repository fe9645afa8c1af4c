#!/usr/bin/env python3
"""Reference moments of measured surfaces with undefined points, from
SurfaceTopography itself.

Script: scripts/fill_reference.py
Pinned: SurfaceTopography==1.27.1 (requirements line below).

    pip install SurfaceTopography==1.27.1
    python3 scripts/fill_reference.py

Makes rough surfaces with `fourier_synthesis`, marks points undefined
(scattered single points, a blob, most of a scan line, the corners and
edges), writes each as a text file roughtui reads (`nan` in a Gwyddion
matrix, empty cells in a comma-separated matrix, `nan` in a line scan),
and writes SurfaceTopography's numbers of the *filled* surface,
`interpolate_undefined_data()` (harmonic) then detrended as
scripts/surface_reference.py does, to
crates/rough-surface/tests/data/fill_reference.txt in the same format as
reference.txt (moments at 41 cutoffs, display spectrum), plus, per file,
the number of undefined points and the largest |filled height| found
(file units) for scale.

requirements: SurfaceTopography==1.27.1
"""
import os
import sys

import numpy as np
import scipy
import SurfaceTopography
from SurfaceTopography import Topography, UniformLineScan
from SurfaceTopography.Generation import fourier_synthesis

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from surface_reference import OUT, r, reference  # noqa: E402

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__


def holes(shape, rng, scattered):
    """A mask of undefined points: scattered ones, a blob, a broken scan
    line, the four corners and a run along an edge."""
    nx, ny = shape
    m = rng.random(shape) < scattered
    m[nx // 3: nx // 3 + 6, ny // 2: ny // 2 + 5] = True
    m[5: nx - 9, ny // 4] = True
    m[0, 0] = m[-1, 0] = m[0, -1] = m[-1, -1] = True
    m[nx - 1, 10:20] = True
    return m


def write_matrix(path, h_xy, header, sep=" ", empty="nan"):
    """h_xy[i, j], i along x; the file's rows are y; NaN written as `empty`."""
    with open(path, "w") as f:
        for line in header:
            f.write(f"# {line}\n")
        for row in h_xy.T:
            f.write(sep.join(empty if np.isnan(v) else r(v) for v in row) + "\n")


def filled(t):
    assert t.has_undefined_data
    return t.interpolate_undefined_data()


def main():
    path = lambda n: os.path.join(OUT, n)
    out = open(path("fill_reference.txt"), "w")
    out.write("# Reference moments and spectra of the filled surfaces, computed by\n")
    out.write(f"# scripts/fill_reference.py with SurfaceTopography {SurfaceTopography.__version__}"
              f" (numpy {np.__version__}, scipy {scipy.__version__}). SI units.\n")
    rng = np.random.default_rng(25)

    # 1. Non-periodic map (a crop), `nan` in a Gwyddion matrix, µm.
    t = fourier_synthesis((192, 160), (19.2, 16.0), hurst=0.7, rms_height=0.2, unit="µm", rng=11)
    h = t.heights()[:96, :80].copy()
    mask = holes(h.shape, rng, 0.01)
    h[mask] = np.nan
    write_matrix(path("map_nan.txt"), h,
                 ["Channel: Height", "Width: 9.6 µm", "Height: 8 µm", "Value units: µm"])
    ft = filled(Topography(np.ma.masked_invalid(h), (9.6, 8.0), unit="µm", periodic=False))
    out.write(f"# map_nan.txt: {int(mask.sum())} undefined of {mask.size}\n")
    reference("map_nan.txt", ft, False, 0.0, 1e-6, out)

    # 2. Periodic map, empty cells in a comma-separated matrix, nm over µm.
    t = fourier_synthesis((64, 48), (6.4e3, 4.8e3), hurst=0.5, rms_height=30, unit="nm", rng=12)
    h = t.heights().copy()
    mask = holes(h.shape, rng, 0.02)
    h[mask] = np.nan
    write_matrix(path("map_empty.csv"), h,
                 ["Width: 6.4 µm", "Height: 4.8 µm", "Value units: nm"], sep=",", empty="")
    ft = filled(Topography(np.ma.masked_invalid(h), (6.4e3, 4.8e3), unit="nm", periodic=True))
    out.write(f"# map_empty.csv: {int(mask.sum())} undefined of {mask.size}\n")
    reference("map_empty.csv", ft, True, 0.0, 1e-9, out)

    # 3. A line scan (one column) with gaps, non-periodic, nm.
    t = fourier_synthesis((2000,), (2000.0,), hurst=0.8, rms_height=5.0, unit="nm", rng=13)
    z = t.heights()[:1000].copy()
    lmask = rng.random(z.shape) < 0.03
    lmask[0] = lmask[-1] = True
    lmask[400:420] = True
    z[lmask] = np.nan
    with open(path("line_nan.txt"), "w") as f:
        f.write("# Width: 1 µm\n# Value units: nm\n")
        for v in z:
            f.write(("nan" if np.isnan(v) else r(v)) + "\n")
    ft = filled(UniformLineScan(np.ma.masked_invalid(z), (1000.0,), unit="nm", periodic=False))
    out.write(f"# line_nan.txt: {int(lmask.sum())} undefined of {lmask.size}\n")
    reference("line_nan.txt", ft, False, 0.0, 1e-9, out)

    out.close()


if __name__ == "__main__":
    main()
