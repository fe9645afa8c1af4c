#!/usr/bin/env python3
"""Reference numbers of the measured surfaces in crates/rough-surface/tests/data
under each form removal `--detrend` offers, from SurfaceTopography itself.

Script: scripts/detrend_reference.py
Pinned: SurfaceTopography==1.27.1.

    python3 scripts/detrend_reference.py

Reads the surfaces scripts/surface_reference.py wrote (the same readers and
unit conventions as scripts/realspace_reference.py) and, for each of
roughtui's modes, SurfaceTopography's own:

- none: the topography as read (no detrend);
- mean: detrend('center');
- plane: detrend('height') (the least-squares plane, or line);
- curvature: detrend('curvature') (the least-squares quadratic, or
  parabola),

then writes to crates/rough-surface/tests/data/detrend_reference.txt, one
line per file and mode: the file, periodic (0/1), the mode, the rms height
(`rms_height_from_area`, lines `rms_height_from_profile`, m), the rms slope
(`rms_gradient`, `rms_slope_from_profile`), max() - min() (m), and the
paper's profile moments m0 (m^2), m2, m4 (1/m^2) at the largest cutoff and
at a tenth of it: `integrate_psd(|q|^a over 0 < |q| <= q1, reliable=False)`
with its default window (none if the detrended topography is periodic,
Hann otherwise), maps m0 = M0, m2 = M2/2, m4 = 3 M4/8, as
scripts/surface_reference.py does.

A periodic surface is read with none and mean only (a tilt or curvature
would leave it no longer periodic: roughtui refuses them).

requirements: SurfaceTopography==1.27.1
"""
import os

import numpy as np
import scipy
import SurfaceTopography
from SurfaceTopography import read_topography

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data")
SAME_Q = 1e-12
MODES = {"none": None, "mean": "center", "plane": "height", "curvature": "curvature"}


def r(v):
    return repr(float(v))


def weight(a, q1):
    def f(q):
        return np.where((q > 0) & (q <= q1), q ** a, 0.0)
    return f


def moments(t, q1, scale):
    m = [t.integrate_psd(weight(a, q1 * (1 + SAME_Q)), reliable=False) for a in (0, 2, 4)]
    if t.dim == 2:
        m = [m[0], m[1] / 2, 3 * m[2] / 8]
    return m[0] * scale ** 2, m[1], m[2] / scale ** 2


def main():
    path = lambda n: os.path.join(DATA, n)
    # (file, topography as SurfaceTopography reads it, periodic, metres
    # per file unit): as in scripts/realspace_reference.py.
    cases = [
        ("map_periodic.txt", read_topography(path("map_periodic.txt"), periodic=True), True, 1e-9),
        ("map_windowed.txt", read_topography(path("map_windowed.txt")), False, 1e-6),
        ("map_odd.txt", read_topography(path("map_odd.txt")), False, 1e-9),
        ("line_xz.txt", read_topography(path("line_xz.txt"), unit="m"), False, 1.0),
        ("line_column.txt", read_topography(path("line_column.txt")), False, 1e-6),
    ]
    with open(path("detrend_reference.txt"), "w") as out:
        out.write("# The surfaces in this folder under each --detrend mode, by\n")
        out.write(f"# scripts/detrend_reference.py with SurfaceTopography {SurfaceTopography.__version__}"
                  f" (numpy {np.__version__}, scipy {scipy.__version__}). SI units.\n")
        out.write("# file periodic mode rms_height rms_slope max_minus_min"
                  " zeta m0 m2 m4 zeta m0 m2 m4\n")
        for name, t0, periodic, scale in cases:
            for mode, st in MODES.items():
                if periodic and mode in ("plane", "curvature"):
                    continue
                t = t0 if st is None else t0.detrend(st)
                if t.dim == 2:
                    h, s = t.rms_height_from_area(), t.rms_gradient()
                else:
                    h, s = t.rms_height_from_profile(), t.rms_slope_from_profile()
                q0 = 2 * np.pi / max(t.physical_sizes)
                # wavevectors_norm2 gives |q| (as scripts/surface_reference.py uses it).
                zeta_max = np.max(t.wavevectors_norm2()) / q0
                row = [name, str(int(periodic)), mode, r(h * scale), r(s), r((t.max() - t.min()) * scale)]
                for zeta in (zeta_max, zeta_max / 10):
                    row.append(r(zeta))
                    row.extend(r(m) for m in moments(t, zeta * q0, scale))
                out.write(" ".join(row) + "\n")


if __name__ == "__main__":
    main()
