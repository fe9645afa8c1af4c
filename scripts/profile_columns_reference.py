#!/usr/bin/env python3
"""Reference numbers of profiles written as three columns: a Dektak CSV
export (empty trailing cells, x printed to 0.1 µm) and an .hfm profile
(`X;Y;valid`, a validity column), from SurfaceTopography on the same values.

Script: scripts/profile_columns_reference.py
Pinned: SurfaceTopography==1.27.1 (requirements line below).

    pip install SurfaceTopography==1.27.1
    python3 scripts/profile_columns_reference.py

Writes to crates/rough-surface/tests/data:

- dektak_profile.csv: a stylus profile (`fourier_synthesis`, 640 points at
  a spacing of 0.156 µm, heights in µm on a tilt) in the layout of a Bruker
  Dektak CSV export: its `Scan Parameters` and `Analytical Results` blocks
  (Windows-1252, the stylus radius in µm), `Scan Data`, `Lateral um,Raw
  Micrometer,`, then rows `x,z,,` with x printed to one
  decimal (as the instrument prints it) and z to five; CR LF line ends,
  CR CR LF after a section's title and an empty line;
- hfm_profile.hfm: a profile in mm on a 106.6 mm form with `X;Y;valid`
  over `[mm];[mm];[1/0]`, semicolons, six decimals, CRLF; 4.1 % of its
  rows (scattered ones, a run of 12, the last) have validity 0 and a
  height of 0.000000 (not measured);
- profile_columns_reference.txt: per file the spacing (the least-squares
  spacing of the printed x, numpy's `polyfit(i, x, 1)`, beside the true
  one and the end points'), the count of points not measured, Rq =
  `rms_height_from_profile` and RΔq = `rms_slope_from_profile` after
  detrend('height'), and the moments and display spectrum in the format
  of reference.txt (scripts/surface_reference.py's `reference`).

The profile SurfaceTopography is given is the file's values as written:
z read back from the text (µm → m, mm → m), a UniformLineScan of n points
over n·Δx with Δx the least-squares spacing, and for the .hfm the rows of
validity 0 masked, then `interpolate_undefined_data()` (harmonic). (Its own
XYZ reader takes both files' first two columns: the .hfm's validity column
is not read, and the Dektak's x, rounded, make a non-uniform line scan
whose slopes follow the rounding; the script checks that it reads the same
heights in the same unit.)

requirements: SurfaceTopography==1.27.1
"""
import io
import os
import sys

import numpy as np
import scipy
import SurfaceTopography
from SurfaceTopography import UniformLineScan
from SurfaceTopography.Generation import fourier_synthesis
from SurfaceTopography.IO import XYZReader

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from surface_reference import OUT, r, reference  # noqa: E402

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

DEKTAK_HEAD = """Scan Parameters
Scan Type,Standard Scan
ID,0
Stylus,Radius: 2.5 \u00b5m
Location,0.0 um, 0.0 um
Length,99.8 um
Duration,3 sec
Resolution,0.156 um/sample
Force,3.00 mg
Measurement Range,524 um
Profile,Hills&Valleys
Display Range,Auto
R. Cursor,Pos: 10.0 um Width: 0.0 um
M. Cursor,Pos: 90.0 um Width: 0.0 um

Analytical Results
Function,R.Cur Pos,R.Cur Width,M.Cur Pos,M.Cur Width,Result
Ra,50.0 um,0.0 um,50.0 um,0.0 um,0.04125 um
Rq,50.0 um,0.0 um,50.0 um,0.0 um,0.05143 um

Scan Data
Lateral um,Raw Micrometer,
"""
# Section titles and empty lines end with CR CR LF, other lines CR LF, and
# the file with an empty line (as the instrument writes them).
TITLES = ("Scan Parameters", "Analytical Results", "Scan Data", "")


def spacing(x):
    """The least-squares spacing of x against its index, and the end points'."""
    n = len(x)
    return np.polyfit(np.arange(n), x, 1)[0], (x[-1] - x[0]) / (n - 1)


def dektak(path):
    n, dx = 640, 0.156
    t = fourier_synthesis((2 * n,), (2 * n * dx,), hurst=0.75, rms_height=0.05, unit="µm", rng=36)
    x = np.arange(n) * dx
    z = t.heights()[:n] + 0.004 * x  # the stylus' tilt
    rows = "".join(f"{xi:.1f},{zi:.5f},,\n" for xi, zi in zip(x, z))
    text = "".join(line + ("\r\r\n" if line in TITLES else "\r\n")
                   for line in (DEKTAK_HEAD + rows).splitlines() + [""])
    with open(path, "wb") as f:
        f.write(text.encode("cp1252"))
    data = [line.split(",") for line in rows.splitlines()]
    xs = np.array([float(d[0]) for d in data])
    zs = np.array([float(d[1]) for d in data])
    st = XYZReader(path).topography()
    assert st.unit == "µm" and np.array_equal(st.heights(), zs), st.unit
    return xs, zs, dx, None


def hfm(path, rng):
    # 810 points: with 800 an edge of the spectrum's bins (the middle one,
    # sqrt(dq · 400 dq)) falls on q = 20 dq, binned by the rounding.
    n, dx = 810, 0.0005
    t = fourier_synthesis((2 * n,), (2 * n * dx,), hurst=0.6, rms_height=4e-4, unit="mm", rng=37)
    x = 8.6722 + np.arange(n) * dx
    z = 106.6068 + t.heights()[:n] + 2e-4 * (x - x[0])
    valid = rng.random(n) >= 0.025
    valid[300:312] = False
    valid[-1] = False
    lines = ["X;Y;valid", "[mm];[mm];[1/0]"]
    lines += [f"{xi:.6f};{(zi if v else 0.0):.6f};{int(v)}" for xi, zi, v in zip(x, z, valid)]
    with open(path, "w", newline="") as f:
        f.write("\r\n".join(lines) + "\r\n")
    data = [line.split(";") for line in lines[2:]]
    xs = np.array([float(d[0]) for d in data])
    zs = np.array([float(d[1]) for d in data])
    st = XYZReader(path).topography()
    assert st.unit == "mm" and np.array_equal(st.heights(), zs), st.unit
    return xs, np.where(valid, zs, np.nan), dx, ~valid


def main():
    path = lambda n: os.path.join(OUT, n)
    out = open(path("profile_columns_reference.txt"), "w")
    out.write("# Reference numbers of three-column profiles, computed by\n")
    out.write(f"# scripts/profile_columns_reference.py with SurfaceTopography {SurfaceTopography.__version__}"
              f" (numpy {np.__version__}, scipy {scipy.__version__}). SI units.\n")
    out.write("# spacing NAME least-squares true end-points (file units); real NAME Rq RDq;"
              " undefined NAME count total\n")
    rng = np.random.default_rng(36)
    for name, unit, scale, make in [
        ("dektak_profile.csv", "µm", 1e-6, lambda p: dektak(p)),
        ("hfm_profile.hfm", "mm", 1e-3, lambda p: hfm(p, rng)),
    ]:
        x, z, true_dx, mask = make(path(name))
        ls, ends = spacing(x)
        n = len(z)
        out.write(f"spacing {name} {r(ls)} {r(true_dx)} {r(ends)}\n")
        t = UniformLineScan(np.ma.masked_invalid(z), (n * ls,), unit=unit, periodic=False)
        count = 0 if mask is None else int(mask.sum())
        out.write(f"undefined {name} {count} {n}\n")
        if count:
            t = t.interpolate_undefined_data()
        d = t.detrend("height")
        out.write(f"real {name} {r(d.rms_height_from_profile() * scale)} {r(d.rms_slope_from_profile())}\n")
        reference(name, t, False, 0.0, scale, out)
    out.close()


if __name__ == "__main__":
    main()
