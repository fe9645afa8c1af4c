#!/usr/bin/env python3
"""Reference numbers of an anisotropic (lay) map, from SurfaceTopography.

Script: scripts/direction_reference.py
Pinned: SurfaceTopography==1.27.1 (requirements line below).

    pip install SurfaceTopography==1.27.1
    python3 scripts/direction_reference.py

Makes a map with a lay (ridges along y: a rough profile along x repeated
on every row, plus a small isotropic roughness), non-periodic and not
square, writes it as a Gwyddion text matrix, and writes to
crates/rough-surface/tests/data/direction_reference.txt:

- `slopes`: the rms slopes along x and along y of the whole map from its
  windowed 2D spectrum, √integrate_psd(q_x²) and √integrate_psd(q_y²)
  (SurfaceTopography's default Hann window, detrend('height'));
- per direction (`--direction x` and `y`), in the format of
  reference.txt: the profile moments m0, m2, m4 at 41 cutoffs from
  `integrate_psd_from_profile` (profiles along x; the transposed map for
  y) and the display spectrum `power_spectrum_from_profile`, both with
  reliable=False, after detrend('height'), and the real-space numbers of
  the profiles: `Rq` and `Rdq` of the topography (each profile along x
  about its own mean; the differences along x), and of the same
  deviations d from each profile's mean Ra = mean |d|, Rsk = mean d^3 /
  Rq^3, Rku = mean d^4 / Rq^4 (NumPy's; SurfaceTopography computes none of
  them) and Rz the profiles' mean max() - min().

requirements: SurfaceTopography==1.27.1
"""
import os
import sys

import numpy as np
import scipy
import SurfaceTopography
from SurfaceTopography import Topography
from SurfaceTopography.Generation import fourier_synthesis

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from surface_reference import NZ, OUT, SAME_Q, r, write_matrix  # noqa: E402

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__


def lay_map():
    """Heights h[i, j] (i along x) in µm over 12 µm x 8 µm, 96 x 64."""
    nx, ny, lx, ly = 96, 64, 12.0, 8.0
    profile = fourier_synthesis((2 * nx,), (2 * lx,), hurst=0.8, rms_height=0.3, unit="µm", rng=21)
    iso = fourier_synthesis((2 * nx, 2 * ny), (2 * lx, 2 * ly), hurst=0.8, rms_height=0.02,
                            unit="µm", rng=22)
    h = profile.heights()[:nx, None] + iso.heights()[:nx, :ny]
    return h, (lx, ly)


def profile_reference(name, t, out):
    """--direction x of t (file units µm, scale 1e-6)."""
    scale = 1e-6
    sx = t.physical_sizes[0]
    nx = t.nb_grid_pts[0]
    q0 = 2 * np.pi / sx
    zeta_max = (nx // 2) * 1.0  # the largest |q_x| of the FFT over q0
    zetas = np.logspace(0, np.log10(zeta_max), NZ)
    zetas[-1] = zeta_max
    out.write(f"surface {name} periodic 0 pixel_size 0.0 profiles n {nx} l {r(sx * scale)}\n")
    out.write(f"q0 {r(q0 / scale)}\nzeta_max {r(zeta_max)}\n")
    h = t.heights()
    d = h - h.mean(axis=0)
    rq = t.Rq()
    real = [rq * scale, t.Rdq(), np.mean(np.abs(d)) * scale, np.mean(d ** 3) / rq ** 3,
            np.mean(d ** 4) / rq ** 4, np.mean(h.max(axis=0) - h.min(axis=0)) * scale]
    out.write("real " + " ".join(r(v) for v in real) + "\nmoments\n")
    for z in zetas:
        q1 = z * q0 * (1 + SAME_Q)
        m = [t.integrate_psd_from_profile(lambda qx, a=a: np.where((qx != 0) & (abs(qx) <= q1),
                                                                   abs(qx) ** a, 0.0),
                                          reliable=False) for a in (0, 2, 4)]
        out.write(f"{r(z)} {r(m[0] * scale ** 2)} {r(m[1])} {r(m[2] / scale ** 2)}\n")
    q, c = t.power_spectrum_from_profile(reliable=False)
    out.write("spectrum\n")
    for qi, ci in zip(np.ma.compressed(q) / scale, np.ma.compressed(c) * scale ** 3):
        out.write(f"{r(qi)} {r(ci)}\n")
    out.write("end\n")


def main():
    path = os.path.join(OUT, "map_lay.txt")
    h, (lx, ly) = lay_map()
    write_matrix(path, h, ["Channel: Height", f"Width: {lx} µm", f"Height: {ly} µm",
                           "Value units: µm"])
    # The file's numbers, as read back.
    h = np.loadtxt(path).T
    t = Topography(h, (lx, ly), unit="µm").detrend("height")
    sx = np.sqrt(t.integrate_psd(lambda qx, qy: qx ** 2, reliable=False))
    sy = np.sqrt(t.integrate_psd(lambda qx, qy: qy ** 2, reliable=False))
    ty = Topography(h.T.copy(), (ly, lx), unit="µm").detrend("height")
    with open(os.path.join(OUT, "direction_reference.txt"), "w") as out:
        out.write("# Reference numbers of map_lay.txt along x and along y, computed by\n")
        out.write(f"# scripts/direction_reference.py with SurfaceTopography "
                  f"{SurfaceTopography.__version__} (numpy {np.__version__}, "
                  f"scipy {scipy.__version__}). SI units.\n")
        out.write(f"slopes {r(sx)} {r(sy)}\n")
        profile_reference("x", t, out)
        profile_reference("y", ty, out)


if __name__ == "__main__":
    main()
