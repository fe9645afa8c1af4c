#!/usr/bin/env python3
"""Reference numbers of real instruments' files, from SurfaceTopography's
own readers.

Script: scripts/instruments_reference.py
Pinned: SurfaceTopography==1.27.1 (requirements line below; numpy and scipy
as pip resolves them, their versions are written into the output).

    pip install SurfaceTopography==1.27.1
    python3 scripts/instruments_reference.py [--from DIR]

The files are SurfaceTopography's example files (its repository's
test/file_format_examples, MIT licence, see
crates/rough-surface/tests/data/instruments/README.md): real files that
instruments and their software wrote (Digital Surf .sur, Sensofar .plu,
Nanoscope .di, Wyko .opd, Zygo MetroPro .dat, Alicona .al3d, Nanosurf .nid,
Igor .ibw, ISO 25178-71 .sdf, Bruker .opdx, FRT .frt). They are kept gzip-compressed (`NAME.gz`, gzip -9 without a
name or a time, so that the bytes do not change); with `--from DIR` (a
checkout's test/file_format_examples) they are compressed into
crates/rough-surface/tests/data/instruments/ first.

For each file (and channel) this writes to instruments.txt in the same
folder what SurfaceTopography 1.27.1 reads and computes:

- `file NAME channel C max_undefined F`: the file as roughtui reads it
  (C: `--channel`, the channel's number in the file, `-` for the default;
  F the share of undefined points allowed, `-` for the default 10 %);
- `grid nx ny lx ly undefined`: the grid, its size in metres and how many
  points the file marks undefined (masked);
- `real sq sdq sa ssk sku sz`: the undefined points filled
  (`interpolate_undefined_data()`, harmonic), the plane (a profile's
  line) removed (`detrend('height')`), then Sq = `rms_height_from_area`,
  Sdq = `rms_gradient` (a profile: Rq = `rms_height_from_profile`, RΔq =
  `rms_slope_from_profile`), in m and dimensionless, and, as
  SurfaceTopography 1.27.1 computes no Sa, Ssk, Sku or Sz (Ra, Rsk, Rku,
  Rz), those from the same detrended heights with numpy (ISO 25178-2 and
  ISO 4287 over the whole data: Sa the mean |h - mean|, Ssk and Sku the
  third and fourth central moments over Sq^3 and Sq^4, Sz the largest
  height minus the smallest);
- the moment table and the display spectrum of the same surface, as
  scripts/surface_reference.py writes them (`surface ...` to `end`).

requirements: SurfaceTopography==1.27.1
"""
import argparse
import gzip
import os
import shutil
import sys
import tempfile
import time

import numpy as np
import scipy
import SurfaceTopography
from SurfaceTopography import open_topography
from SurfaceTopography.Support.UnitConversion import get_unit_conversion_factor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from surface_reference import r, reference  # noqa: E402

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data", "instruments")

# (file, SurfaceTopography's channel index or None for its default,
# roughtui's --channel (the channel's number in the file; SurfaceTopography
# leaves out a .nid's channels that hold no heights) or None, share of
# undefined points allowed or None for the default 10 %)
CASES = [
    ("sur-2.sur", None, None, None),
    ("sur-3.sur", None, None, 0.9),
    ("plu-1.plu", None, None, None),
    ("di-2.di", None, None, None),
    ("di-2.di", 2, "2", None),
    ("di-3.di", None, None, None),
    ("di-3.di", 3, "3", None),
    ("di-5.di", None, None, None),
    ("opd-1.opd", None, None, None),
    ("metropro-1.dat", None, None, None),
    ("al3d-1.al3d", None, None, None),
    ("nid-1.nid", None, None, None),
    ("nid-1.nid", 1, "3", None),
    ("spot_1-1000nm.ibw", None, None, None),
    ("spot_1-1000nm.ibw", 1, "1", None),
    ("10x10-one_channel_without_name.ibw", None, None, None),
    ("sdf-1.sdf", None, None, None),
    ("opdx-3.opdx", None, None, None),
    ("frt-1.frt", None, None, 0.35),
    ("frt-2.frt", None, None, 0.35),
]



def compress(src, dst):
    """gzip -9n: no name, no time, the same bytes every run."""
    with open(src, "rb") as f:
        data = f.read()
    with open(dst, "wb") as raw:
        with gzip.GzipFile(filename="", mode="wb", compresslevel=9, fileobj=raw, mtime=0) as g:
            g.write(data)


def stored(name):
    """The committed file: NAME.gz."""
    return os.path.join(OUT, name + ".gz")


def metres(unit):
    return 1.0 if unit is None else get_unit_conversion_factor(unit, "m")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--from", dest="src", help="SurfaceTopography's test/file_format_examples")
    a = p.parse_args()
    if a.src:
        for name in sorted({c[0] for c in CASES}):
            compress(os.path.join(a.src, name), stored(name))
    tmp = tempfile.mkdtemp()
    out = open(os.path.join(OUT, "instruments.txt"), "w")
    out.write("# What SurfaceTopography reads from and computes on real instruments' files, by\n")
    out.write(f"# scripts/instruments_reference.py with SurfaceTopography {SurfaceTopography.__version__}"
              f" (numpy {np.__version__}, scipy {scipy.__version__}). SI units.\n")
    for name, channel, ours, allowed in CASES:
        t0 = time.time()
        path = os.path.join(tmp, name)
        with gzip.open(stored(name), "rb") as g, open(path, "wb") as f:
            f.write(g.read())
        reader = open_topography(path)
        t = reader.topography() if channel is None else reader.topography(channel_index=channel)
        scale = metres(t.unit)
        h = t.heights()
        undefined = int(np.ma.getmaskarray(h).sum()) if np.ma.isMaskedArray(h) else 0
        undefined += int(np.isnan(np.ma.getdata(h)).sum()) if not np.ma.isMaskedArray(h) else 0
        if t.has_undefined_data:
            t = t.interpolate_undefined_data()
        d = t.detrend("height")
        z = d.heights() * scale
        if t.dim == 2:
            sq, sdq = d.rms_height_from_area() * scale, d.rms_gradient()
        else:
            sq, sdq = d.rms_height_from_profile() * scale, d.rms_slope_from_profile()
        c = z - z.mean()
        sa = np.mean(np.abs(c))
        rq = np.sqrt(np.mean(c ** 2))
        ssk = np.mean(c ** 3) / rq ** 3
        sku = np.mean(c ** 4) / rq ** 4
        sz = z.max() - z.min()
        if t.dim == 2:
            nx, ny = t.nb_grid_pts
            lx, ly = (s * scale for s in t.physical_sizes)
        else:
            (nx,), ny = t.nb_grid_pts, 1
            lx, ly = t.physical_sizes[0] * scale, 0.0
        out.write(f"file {name} channel {'-' if ours is None else ours} "
                  f"max_undefined {'-' if allowed is None else r(allowed)}\n")
        out.write(f"grid {nx} {ny} {r(lx)} {r(ly)} {undefined}\n")
        out.write(f"real {r(sq)} {r(sdq)} {r(sa)} {r(ssk)} {r(sku)} {r(sz)}\n")
        reference(name, t, False, 0.0, scale, out)
        print(f"{time.time() - t0:.1f} s {name} channel {channel}: {nx} x {ny}, {undefined} undefined, Sq {sq:.4g} m")
    out.close()
    shutil.rmtree(tmp)


if __name__ == "__main__":
    main()
