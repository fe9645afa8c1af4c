#!/usr/bin/env python3
"""Reference numbers of instrument makers' files (Keyence, JPK, Park
Systems, Sensofar, Zygo), read by independent readers: SurfaceTopography
1.27.1's (its VK, ZON, JPK, PS, PLUX and DATX readers) and, for JPK's
HDF5 scans, which SurfaceTopography does not read, AFMReader 0.0.7's
`load_h5jpk`.

Script: scripts/makers_reference.py
Pinned: SurfaceTopography==1.27.1, AFMReader==0.0.7 (requirements line
below; numpy as pip resolves it, its version is written into the output).

    pip install SurfaceTopography==1.27.1 AFMReader==0.0.7
    python3 scripts/makers_reference.py [--samples DIR]

Committed files (crates/rough-surface/tests/data/makers/, README.md
there): JPK's real `.jpk`, `.jpk-qi-image` and `.h5-jpk` from AFMReader
0.0.7's PyPI sdist (LGPL-3.0; gzip-compressed), and the synthetic files
scripts/makers_synthetic.py writes. For each file (and channel) this
writes to makers.txt there:

- `file NAME channel C`: the file as roughtui reads it (C: `--channel`,
  `-` for the default);
- `grid nx ny lx ly undefined`: the grid, its size in metres and how many
  points the file marks undefined;
- `real sq sdq`: the undefined points filled
  (`interpolate_undefined_data()`, harmonic), the plane removed
  (`detrend('height')`), Sq = `rms_height_from_area` in m and Sdq =
  `rms_gradient`.

With `--samples DIR` (a folder of real files fetched from public
repositories, which may not be committed: DIR/PROVENANCE.txt names each
file's repository and commit, DIR/owner+name/path holds it) it also
writes samples.txt there: the same numbers for each real file named in
SAMPLES below, after a line `sample REPOSITORY COMMIT PATH SHA256 channel
C`, which tests/makers_samples.rs checks when ROUGHTUI_SAMPLES=DIR is
set. A `.vk4` inside a `.vk6` is named `PATH!Vk4File`.

requirements: SurfaceTopography==1.27.1 AFMReader==0.0.7
"""
import argparse
import gzip
import hashlib
import io
import os
import tempfile
import zipfile

import numpy as np
import SurfaceTopography
from SurfaceTopography import Topography, open_topography
from SurfaceTopography.Support.UnitConversion import get_unit_conversion_factor

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data", "makers")

# (file, SurfaceTopography's channel index or None, roughtui's --channel or
# None, reader: "st" SurfaceTopography, "afm" AFMReader's load_h5jpk)
CASES = [
    ("sample_0.jpk.gz", None, None, "st"),
    ("sample_0.jpk.gz", 3, "5", "st"),
    ("sample_0.jpk-qi-image.gz", 2, None, "st"),
    ("sample_0.h5-jpk.gz", None, None, "afm"),
    ("synthetic.vk4", None, None, "st"),
    ("synthetic.vk4", 1, "1", "st"),
    ("synthetic.vk7", None, None, "st"),
    ("synthetic.zon", None, None, "st"),
    ("synthetic.plux", None, None, "st"),
    ("synthetic.datx", None, None, "st"),
    ("synthetic_park.tiff", None, None, "st"),
]

# Real files, not committed: (repository, path, SurfaceTopography's
# channel or None, roughtui's --channel or None, reader).
SAMPLES = [
    ("duserzym+Keyence_VKX3000_data_processing", "data/60um_50E_30-50shots_depthpro.vk6", None, None, "st"),
    ("duserzym+Keyence_VKX3000_data_processing", "data/60um_50E_30-50shots_depthpro.vk6!Vk4File", None, None, "st"),
    ("thomasgredig+nanoAFMr", "inst/extdata/Park_20210916_034.tiff", None, None, "st"),
    ("thomasgredig+nanoAFMr", "inst/extdata/ForceCurve_009.tiff", None, None, "st"),
    ("AFM-SPM+AFMReader", "tests/resources/sample_0.jpk", None, None, "st"),
    ("AFM-SPM+AFMReader", "tests/resources/sample_0.h5-jpk", None, None, "afm"),
    ("AFM-SPM+TopoStats", "tests/resources/file.jpk", None, None, "st"),
]


def r(x):
    return repr(float(x))


def plain(path, tmp):
    """The file's bytes as a file (a .gz unpacked, a zip member taken)."""
    if "!" in path:
        outer, member = path.split("!")
        data = zipfile.ZipFile(outer).read(member)
        name = os.path.basename(outer) + "." + member.lower()
    elif path.endswith(".gz"):
        with gzip.open(path, "rb") as g:
            data = g.read()
        name = os.path.basename(path)[:-3]
    else:
        return path
    if name.endswith(".vk6.vk4file"):
        name = name[: -len(".vk6.vk4file")] + ".vk4"
    out = os.path.join(tmp, name)
    with open(out, "wb") as f:
        f.write(data)
    return out


def h5jpk_topography(path):
    """AFMReader's height trace, first frame, as a topography in m."""
    from AFMReader.h5_jpk import load_h5jpk

    frames, nm_per_pixel, _ = load_h5jpk(path, channel="height_trace")
    z = frames[0] * 1e-9
    ny, nx = z.shape
    # SurfaceTopography's order: (x, y).
    return Topography(z.T, (nx * nm_per_pixel * 1e-9, ny * nm_per_pixel * 1e-9), unit="m")


def numbers(path, channel, reader):
    if reader == "afm":
        t = h5jpk_topography(path)
    else:
        rd = open_topography(path)
        t = rd.topography() if channel is None else rd.topography(channel_index=channel)
    scale = 1.0 if t.unit is None else get_unit_conversion_factor(t.unit, "m")
    h = t.heights()
    undefined = int(np.ma.getmaskarray(h).sum()) if np.ma.isMaskedArray(h) else int(np.isnan(h).sum())
    if t.has_undefined_data:
        t = t.interpolate_undefined_data()
    d = t.detrend("height")
    nx, ny = t.nb_grid_pts
    lx, ly = (s * scale for s in t.physical_sizes)
    sq, sdq = d.rms_height_from_area() * scale, d.rms_gradient()
    return (
        f"grid {nx} {ny} {r(lx)} {r(ly)} {undefined}\n"
        f"real {r(sq)} {r(sdq)}\n"
    )


def header(out, what):
    out.write(f"# {what}, by scripts/makers_reference.py with SurfaceTopography "
              f"{SurfaceTopography.__version__} (numpy {np.__version__}) and AFMReader 0.0.7 "
              "(.h5-jpk). SI units.\n")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--samples", help="a folder of real files and their PROVENANCE.txt")
    a = p.parse_args()
    tmp = tempfile.mkdtemp()
    with open(os.path.join(OUT, "makers.txt"), "w") as out:
        header(out, "What independent readers read from and compute on makers' files")
        for name, channel, ours, reader in CASES:
            path = plain(os.path.join(OUT, name), tmp)
            out.write(f"file {name} channel {ours or '-'}\n")
            out.write(numbers(path, channel, reader))
    if not a.samples:
        return
    commits = {}
    with open(os.path.join(a.samples, "PROVENANCE.txt")) as f:
        for line in f:
            w = line.split()
            if len(w) == 3:
                commits[(w[0], w[2])] = w[1]
    with open(os.path.join(OUT, "samples.txt"), "w") as out:
        header(out, "Real files that may not be committed (ROUGHTUI_SAMPLES=DIR)")
        for repo, path, channel, ours, reader in SAMPLES:
            outer = path.split("!")[0]
            full = os.path.join(a.samples, repo, outer)
            with open(full, "rb") as f:
                sha = hashlib.sha256(f.read()).hexdigest()
            commit = commits[(repo, outer)]
            local = plain(os.path.join(a.samples, repo, path), tmp)
            out.write(f"sample {repo} {commit} {path} {sha} channel {ours or '-'}\n")
            out.write(numbers(local, channel, reader))


if __name__ == "__main__":
    main()
