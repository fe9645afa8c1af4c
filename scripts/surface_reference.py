#!/usr/bin/env python3
"""Reference moments of measured surfaces, from SurfaceTopography itself.

Script: scripts/surface_reference.py
Pinned: SurfaceTopography==1.27.1 (requirements line below; numpy and scipy
as pip resolves them, their versions are written into the output).

    pip install SurfaceTopography==1.27.1
    python3 scripts/surface_reference.py

Generates rough surfaces with SurfaceTopography's `fourier_synthesis`
(periodic maps; non-periodic maps and lines cropped out of larger periodic
ones; square and non-square grids and pixels; odd sizes), writes each as a
text file in a format roughtui reads (Gwyddion/SurfaceTopography matrix
headers in several unit conventions, a header-less matrix read with a pixel
size, a one-row and a one-column line, a two-column x z table), reads each
back with SurfaceTopography's own readers where they read that format, and
writes SurfaceTopography's numbers to crates/rough-surface/tests/data/
reference.txt:

- the paper's profile moments m0, m2, m4 (SI) at 41 cutoffs ζ from 1 to the
  largest the grid allows: detrend('center') for periodic data,
  detrend('height') (least-squares plane or line) otherwise, then
  `integrate_psd(|q|^α over 0 < |q| ≤ ζ q0, reliable=False)` with its
  default window (none if periodic, Hann otherwise); maps m0 = M0,
  m2 = M2/2, m4 = 3 M4/8 (isotropy), lines the 1D sums themselves;
- the display spectrum: `power_spectrum_from_area` (maps) or
  `power_spectrum_from_profile` (lines) with reliable=False.

q0 = 2π/max(Lx, Ly). A wavevector counts as ≤ q1 within a relative 1e-12
(the rounding of |q|² between lattice points at the same distance), as
roughtui's moment table does.

requirements: SurfaceTopography==1.27.1
"""
import os

import numpy as np
import scipy
import SurfaceTopography
from SurfaceTopography import (Topography, UniformLineScan, read_topography)
from SurfaceTopography.Generation import fourier_synthesis
from SurfaceTopography.Support.UnitConversion import length_units

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data")
SAME_Q = 1e-12
NZ = 41


def r(v):
    """Shortest repr that reads back to the same double."""
    return repr(float(v))


def write_matrix(path, heights_xy, header):
    """heights_xy[i, j]: i along x, j along y; rows of the file are y."""
    with open(path, "w") as f:
        for h in header:
            f.write(f"# {h}\n")
        for row in heights_xy.T:
            f.write(" ".join(r(v) for v in row) + "\n")


def crop(t, n):
    """A non-periodic piece (the first n points per axis) of a periodic surface."""
    h = t.heights()
    if t.dim == 1:
        return h[: n[0]]
    return h[: n[0], : n[1]]


def weight(a, q1):
    """|q|^a on 0 < |q| <= q1; one argument, so integrate_psd passes |q|."""
    def f(q):
        return np.where((q > 0) & (q <= q1), q ** a, 0.0)
    return f


def moments(t, zetas, q0, scale):
    """Profile moments in SI at q1 = ζ q0 (q0 and t in file units)."""
    rows = []
    for z in zetas:
        q1 = z * q0 * (1 + SAME_Q)
        m = [t.integrate_psd(weight(a, q1), reliable=False) for a in (0, 2, 4)]
        if t.dim == 2:
            m = [m[0], m[1] / 2, 3 * m[2] / 8]
        rows.append((z, m[0] * scale ** 2, m[1], m[2] / scale ** 2))
    return rows


def reference(name, t, periodic, pixel_size, scale, out):
    """t: the topography as SurfaceTopography reads the file (file units)."""
    t = t.detrend("center" if periodic else "height")
    sizes = t.physical_sizes
    q0 = 2 * np.pi / max(sizes)
    qmax = np.max(t.wavevectors_norm2())
    zeta_max = qmax / q0
    zetas = np.logspace(0, np.log10(zeta_max), NZ)
    zetas[-1] = zeta_max
    if t.dim == 2:
        q, c = t.power_spectrum_from_area(reliable=False)
        c = c * scale ** 4
        kind = f"map nx {t.nb_grid_pts[0]} ny {t.nb_grid_pts[1]} lx {r(sizes[0] * scale)} ly {r(sizes[1] * scale)}"
    else:
        q, c = t.power_spectrum_from_profile(reliable=False)
        c = c * scale ** 3
        kind = f"line n {t.nb_grid_pts[0]} l {r(sizes[0] * scale)}"
    q = np.ma.compressed(q) / scale
    c = np.ma.compressed(c)
    out.write(f"surface {name} periodic {int(periodic)} pixel_size {r(pixel_size)} {kind}\n")
    out.write(f"q0 {r(q0 / scale)}\nzeta_max {r(zeta_max)}\nmoments\n")
    for z, m0, m2, m4 in moments(t, zetas, q0, scale):
        out.write(f"{r(z)} {r(m0)} {r(m2)} {r(m4)}\n")
    out.write("spectrum\n")
    for qi, ci in zip(q, c):
        out.write(f"{r(qi)} {r(ci)}\n")
    out.write("end\n")


def main():
    os.makedirs(OUT, exist_ok=True)
    path = lambda n: os.path.join(OUT, n)
    out = open(path("reference.txt"), "w")
    out.write("# Reference moments and spectra of the surfaces in this folder, computed by\n")
    out.write(f"# scripts/surface_reference.py with SurfaceTopography {SurfaceTopography.__version__}"
              f" (numpy {np.__version__}, scipy {scipy.__version__}). SI units.\n")

    # 1. Periodic square map, Gwyddion header in µm, heights in nm.
    t = fourier_synthesis((64, 64), (10e3, 10e3), hurst=0.8, rms_height=50, unit="nm", rng=1)
    write_matrix(path("map_periodic.txt"), t.heights(),
                 ["Channel: Height", "Width: 10.000 µm", "Height: 10.000 µm", "Value units: nm"])
    reference("map_periodic.txt", read_topography(path("map_periodic.txt"), periodic=True),
              True, 0.0, 1e-9, out)

    # 2. Non-periodic, non-square grid and size (crop of a periodic map).
    t = fourier_synthesis((192, 96), (24.0, 12.0), hurst=0.6, rms_height=0.1, unit="µm", rng=2)
    write_matrix(path("map_windowed.txt"), crop(t, (96, 48)),
                 ["Channel: Topography", "Width: 12 µm", "Height: 6 um", "Value units: µm"])
    reference("map_windowed.txt", read_topography(path("map_windowed.txt")), False, 0.0, 1e-6, out)

    # 3. Odd sizes, non-square pixels, sizes in the value unit (to_matrix style).
    t = fourier_synthesis((90, 74), (9000.0, 11100.0), hurst=0.9, rms_height=20, unit="nm", rng=3)
    write_matrix(path("map_odd.txt"), crop(t, (45, 37)),
                 ["Width: 4500.0", "Height: 5550.0", "Value units: nm"])
    reference("map_odd.txt", read_topography(path("map_odd.txt")), False, 0.0, 1e-9, out)

    # 4. No header: heights in metres, read with a pixel size of 50 nm; ny > nx.
    p = 50e-9
    t = fourier_synthesis((80, 128), (80 * p, 128 * p), hurst=0.7, rms_height=5e-9, unit="m", rng=4)
    h = crop(t, (40, 64))
    write_matrix(path("map_pixel.txt"), h, [])
    reference("map_pixel.txt", read_topography(path("map_pixel.txt"), physical_sizes=(40 * p, 64 * p),
                                               unit="m"), False, p, 1.0, out)

    # 5. Periodic, long-wavelength roll-off and short cutoff, German labels, mm and µm.
    t = fourier_synthesis((96, 48), (0.2, 0.1), hurst=0.75, c0=1e-6, long_cutoff=0.05, rolloff=0.5,
                          short_cutoff=0.01, unit="mm", rng=5)
    write_matrix(path("map_rolloff.txt"), t.heights() * 1e3,
                 ["Kanal: Höhe", "Breite: 0.2 mm", "Höhe: 0.1 mm", "Einheiten: µm"])
    reference("map_rolloff.txt", read_topography(path("map_rolloff.txt"), periodic=True),
              True, 0.0, 1e-6, out)

    # 6. Line scan, two columns x z in metres, non-periodic.
    dx = 2e-8
    t = fourier_synthesis((4096,), (4096 * dx,), hurst=0.8, rms_height=3e-9, unit="m", rng=6)
    z = crop(t, (1024,))
    x = dx * np.arange(1024)
    with open(path("line_xz.txt"), "w") as f:
        for xi, zi in zip(x, z):
            f.write(f"{r(xi)} {r(zi)}\n")
    reference("line_xz.txt", read_topography(path("line_xz.txt"), unit="m"), False, 0.0, 1.0, out)

    # 7. One-row matrix with a width, periodic. SurfaceTopography reads a
    # one-row matrix as a map one point high, so its reference is the line.
    t = fourier_synthesis((500,), (200.0,), hurst=0.5, rms_height=0.05, unit="µm", rng=7)
    with open(path("line_row.txt"), "w") as f:
        f.write("# Width: 200 µm\n# Value units: nm\n")
        f.write(" ".join(r(v * 1e3) for v in t.heights()) + "\n")
    heights = np.loadtxt(path("line_row.txt"))
    reference("line_row.txt", UniformLineScan(heights, (200e3,), unit="nm", periodic=True),
              True, 0.0, 1e-9, out)

    # 8. One column (SurfaceTopography's to_matrix layout for a line), odd n.
    t = fourier_synthesis((1554,), (155.4,), hurst=0.3, rms_height=0.2, unit="µm", rng=8)
    lt = UniformLineScan(crop(t, (777,)), (77.7,), unit="µm")
    lt.to_matrix(path("line_column.txt"))
    reference("line_column.txt", read_topography(path("line_column.txt")), False, 0.0, 1e-6, out)

    out.close()


if __name__ == "__main__":
    main()
