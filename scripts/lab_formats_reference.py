#!/usr/bin/env python3
"""Files in the formats a lab brings (Digital Surf compressed .sur and .pro,
WSxM .stp/.top, Image Metrology .bcr/.bcrf, Nanonis .sxm, Gwyddion 1
.gwy, Seiko/SII .xqd), and what independent readers read from them.

Script: scripts/lab_formats_reference.py
Pinned: SurfaceTopography==1.27.1 gwyfile==0.3.0 rosettasciio==0.15.0
surfalize==0.19.2 nanonispy2==1.2.0 (requirements line below), and
Gwyddion 2.62 (Debian's `gwyddion`, run headless with `--convert-to-gwy`).

    pip install SurfaceTopography==1.27.1 gwyfile==0.3.0 rosettasciio==0.15.0 \\
        surfalize==0.19.2 nanonispy2==1.2.0
    apt-get install gwyddion
    python3 scripts/lab_formats_reference.py --afmreader DIR --pynxtools DIR \\
        [--samples DIR]

Writes into crates/rough-surface/tests/data/lab/:

- files written here from the formats' published layouts, where no real
  file may be committed: Gwyddion 1 (`GWYO`, a channel and its mask and
  entries of every type), Seiko .xqd (square, and oblong pixels), Digital
  Surf compressed files (a surface of 32-bit heights in two zlib streams
  with non-measured points, a profile of 16-bit heights, an inverted
  surface; and one surface written by rosettasciio's own writer), BCR
  (`bcrstm` 16-bit in Latin-1 with void points, `bcrf_unicode` float32 in
  UTF-16 in µm), Nanonis .sxm (a topography scanned upwards, forward and
  backward, the last lines not scanned);
- real files from registry packages, gzip-compressed (-9, no name or
  time): WSxM .top and .stp from AFMReader 0.0.7's sdist (LGPL-3.0,
  `tests/resources/`, `--afmreader` its unpacked folder) and a Nanonis
  .sxm from pynxtools-spm 0.4.1's sdist (Apache-2.0, `--pynxtools`);
- lab.txt: per file (and channel) the grid, its size in metres, the
  undefined points and Sq, Sdq (a profile: Rq, RΔq), computed by
  SurfaceTopography 1.27.1 (undefined points filled harmonically, the
  plane removed: `rms_height_from_area`, `rms_gradient`) on the heights
  an independent reader reads — Gwyddion 2.62 (converted to .gwy, read by
  gwyfile) for GWYO, .xqd, .bcr, .sxm; rosettasciio for compressed
  Digital Surf files; SurfaceTopography's own reader for WSxM (Gwyddion
  2.62 reads a WSxM size in `µm` as nm) — and the largest difference of
  the heights a second reader reads (Gwyddion, SurfaceTopography,
  surfalize, nanonispy2), which must be below 1e-12 of the heights'
  range (1e-5 for Gwyddion on WSxM, which stretches floating-point heights
  to span the header's Z amplitude, printed to 6 digits); a file that holds no heights gets `refused TEXT` (roughtui's
  line starts with TEXT).

With `--samples DIR` (real files fetched from public repositories, not
committed: /work/wt/samples's layout, PROVENANCE.txt naming repository
and commit) it writes samples.txt: per file its repository, commit, path
and SHA-256, then the same reference lines, which
crates/rough-surface/tests/lab_samples.rs checks when ROUGHTUI_SAMPLES
names the folder. Compressed Digital Surf files whose values are in
`a.u.` (rosettasciio's test files hold intensities, not heights) are also
read with that unit patched to `um` (`patch um`), to check the unpacking
on a real file.

requirements: SurfaceTopography==1.27.1 gwyfile==0.3.0 rosettasciio==0.15.0 surfalize==0.19.2 nanonispy2==1.2.0
"""
import argparse
import gzip
import hashlib
import os
import shutil
import struct
import subprocess
import tempfile
import zlib

import gwyfile
import numpy as np
import SurfaceTopography
from gwyfile.objects import GwyDataField, GwySIUnit
from SurfaceTopography import Topography, UniformLineScan, open_topography
from SurfaceTopography.Support.UnitConversion import get_unit_conversion_factor

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data", "lab")
rng = np.random.default_rng(44)


def r(v):
    """Shortest repr that reads back to the same double."""
    return repr(float(v))


def rough(ny, nx, rms):
    """A rough map: white noise smoothed along both axes, rms `rms`."""
    z = rng.normal(size=(ny, nx))
    k = np.exp(-np.arange(-4, 5) ** 2 / 8.0)
    if ny > 1:
        z = np.apply_along_axis(lambda v: np.convolve(v, k, "same"), 0, z)
    z = np.apply_along_axis(lambda v: np.convolve(v, k, "same"), 1, z)
    return z / z.std() * rms


# ---------------------------------------------------------------- writers

def write_gwyo(path):
    """Gwyddion 1: GWYO, a GwyContainer of typed entries (GLib types)."""
    z = rough(40, 48, 2e-9)
    unit = GwySIUnit(unitstr="m")
    df = GwyDataField(z, xreal=3e-6, yreal=2.5e-6, si_unit_xy=unit, si_unit_z=unit)
    mask = GwyDataField((rng.random((40, 48)) < 0.02).astype(float), xreal=3e-6, yreal=2.5e-6)

    def entry(t, key, val):
        return struct.pack("<I", t) + key.encode() + b"\0" + val

    body = b"".join([
        entry(80, "/0/data", df.serialize()),
        entry(64, "/0/data/title", b"Topography\0"),
        entry(20, "/0/data/visible", b"\x01"),
        entry(60, "/0/data/view/scale", struct.pack("<d", 1.0)),
        entry(24, "/0/graph/lastid", struct.pack("<i", 0)),
        entry(40, "/0/base/range-type", struct.pack("<q", 7)),
        entry(16, "/0/base/palette-kind", b"x"),
        entry(80, "/0/mask", mask.serialize()),
        entry(64, "/filename", b"old.gwy\0"),
    ])
    with open(path, "wb") as f:
        f.write(b"GWYO" + b"GwyContainer\0" + struct.pack("<I", len(body)) + body)


def write_xqd(path, nx, ny, dx, dy, dz):
    """Seiko .xqd: a 2944-byte header, then unsigned 16-bit heights."""
    z = np.clip(rough(ny, nx, 4000) + 30000, 0, 65535).astype("<u2")
    h = bytearray(2944)
    h[0:14] = b"SPIZ000DFM300A"
    struct.pack_into("<III", h, 0x10, 20001, 2944 + z.nbytes, 2944)
    struct.pack_into("<ddd", h, 0x98, dx, dy, dz)
    struct.pack_into("<d", h, 0xE0, 12.5)
    struct.pack_into("<HH", h, 0x57A, nx, ny)
    h[0x480:0x48A] = b"Topography"
    with open(path, "wb") as f:
        f.write(bytes(h) + z.tobytes())


def sur_header(sig, kind, nx, ny, bits, dx, dy, dz, units, comment=b"", zmin=0,
               special=0, inversion=0, zipped=0):
    """A Digital Surf object's 512-byte header (MountainsMap SDK layout)."""
    h = bytearray(512)
    h[0:12] = sig
    struct.pack_into("<hHhh", h, 12, 0, 1, 1, kind)
    h[20:20 + 9] = b"synthetic"
    struct.pack_into("<h", h, 80, 1)
    struct.pack_into("<h", h, 86, special)
    struct.pack_into("<h", h, 98, bits)
    struct.pack_into("<iiiii", h, 100, zmin, zmin + 1, nx, ny, nx * ny)
    struct.pack_into("<fff", h, 120, dx, dy, dz)
    for k, u in enumerate(units):
        h[180 + 16 * k:180 + 16 * k + len(u)] = u
        h[228 + 16 * k:228 + 16 * k + len(u)] = u
    struct.pack_into("<fff", h, 276, 1.0, 1.0, 1.0)
    struct.pack_into("<h", h, 290, inversion)
    struct.pack_into("<I", h, 324, zipped)
    struct.pack_into("<hh", h, 334, len(comment), 0)
    return bytes(h) + comment


def write_surz(path, kind, nx, ny, bits, dx, dy, dz, units, streams, special=0,
               inversion=0):
    """Digital Surf compressed: the header, a directory of (unpacked,
    packed) sizes and the zlib streams."""
    dtype = "<i2" if bits == 16 else "<i4"
    top = 30000 if bits == 16 else 2_000_000
    z = np.clip(rough(ny, nx, top / 8), -top, top).astype(dtype)
    zmin = int(z.min())
    if special:
        z.flat[rng.choice(z.size, z.size // 50, replace=False)] = zmin - 2
    raw = z.tobytes()
    cut = [len(raw) * k // streams // z.itemsize * z.itemsize for k in range(streams)] + [len(raw)]
    parts = [raw[a:b] for a, b in zip(cut, cut[1:])]
    packed = [zlib.compress(p, 9) for p in parts]
    directory = struct.pack("<I", streams) + b"".join(
        struct.pack("<II", len(p), len(c)) for p, c in zip(parts, packed))
    head = sur_header(b"DSCOMPRESSED", kind, nx, ny, bits, dx, dy, dz, units,
                      comment=b"written from the published layout", zmin=zmin,
                      special=special, inversion=inversion,
                      zipped=len(directory) + sum(map(len, packed)))
    with open(path, "wb") as f:
        f.write(head + directory + b"".join(packed))


def write_surz_rsciio(path):
    """A compressed surface written by rosettasciio's own writer."""
    from rsciio.digitalsurf import file_writer
    z = rough(50, 60, 0.4)
    signal = {
        "data": z,
        "axes": [
            {"name": "Y", "size": 50, "scale": 0.25, "offset": 0.0, "units": "µm",
             "navigate": False},
            {"name": "X", "size": 60, "scale": 0.2, "offset": 0.0, "units": "µm",
             "navigate": False},
        ],
        "metadata": {"Signal": {"quantity": "Height (µm)"}, "General": {"title": "surface"}},
        "original_metadata": {},
    }
    file_writer(path, signal, compressed=True)


def write_bcr(path, unicode):
    """BCR: a `key = value` header, then the heights."""
    if unicode:
        z = rough(30, 40, 0.05).astype("<f4") + np.float32(1.5)
        z.flat[rng.choice(z.size, 12, replace=False)] = np.float32(3.402823e38)
        keys = ["fileformat = bcrf_unicode", "%", "headersize = 2048", "xpixels = 40",
                "ypixels = 30", "intelmode = 1", "xlength = 8.0", "ylength = 6.0",
                "xunit = um", "yunit = um", "zunit = um", "voidpixels = 12", "forcecurve = 0"]
        text = "\n".join(keys) + "\n"
        head = text.ljust(2048).encode("utf-16-le")
    else:
        z = np.clip(rough(32, 48, 3000), -32000, 32000).astype("<i2")
        z.flat[rng.choice(z.size, 9, replace=False)] = 32767
        keys = ["fileformat = bcrstm", "headersize = 2048", "xpixels = 48", "ypixels = 32",
                "xlength = 1200", "ylength = 800", "bit2nm = 0.0125", "xunit = nm",
                "yunit = nm", "zunit = nm", "voidpixels = 9", "# a comment"]
        head = ("\n".join(keys) + "\n").ljust(2048).encode("latin-1")
    with open(path, "wb") as f:
        f.write(head + z.tobytes())


def write_sxm(path):
    """Nanonis .sxm: tags, then each channel's forward and backward images
    (float32, big-endian), an upward scan whose last 5 lines were not
    scanned (NaN)."""
    nx, ny = 64, 48
    z = rough(ny, nx, 0.3e-9) - 5e-9
    zb = z + rng.normal(size=z.shape) * 0.02e-9
    cur = rng.normal(size=z.shape) * 1e-12
    # As stored: the first line is the bottom one (scan up), a backward
    # line runs right to left; the scan stopped 4 lines short of the top.
    fz, bz = z[::-1].copy(), zb[::-1, ::-1].copy()
    fz[-4:] = np.nan
    bz[-4:] = np.nan
    tags = [
        (":NANONIS_VERSION:", "2"),
        (":SCANIT_TYPE:", "              FLOAT            MSBFIRST"),
        (":REC_DATE:", " 01.02.2024"),
        (":REC_TIME:", "10:11:12"),
        (":ACQ_TIME:", "      120.5"),
        (":SCAN_PIXELS:", f"       {nx}        {ny}"),
        (":SCAN_RANGE:", "           1.600000E-7           1.200000E-7"),
        (":SCAN_OFFSET:", "             0.000000E+0         0.000000E+0"),
        (":SCAN_TIME:", "             1.000E+0             1.000E+0"),
        (":SCAN_ANGLE:", "            0.000E+0"),
        (":SCAN_DIR:", "up"),
        (":BIAS:", "            1.000E-1"),
        (":Z-CONTROLLER:", "\tName\ton\tSetpoint\n\tlog Current\t1\t1.000E-10 A"),
        (":Z-Controller>Controller status:", "ON"),
        (":DATA_INFO:", "\tChannel\tName\tUnit\tDirection\tCalibration\tOffset\n"
                        "\t14\tZ\tm\tboth\t9.000E-9\t0.000E+0\n"
                        "\t0\tCurrent\tA\tboth\t1.000E-9\t0.000E+0\n"),
    ]
    text = "".join(f"{t}\n{v}\n" for t, v in tags) + ":SCANIT_END:\n\n\n"
    data = b"".join(a.astype(">f4").tobytes() for a in [fz, bz, cur[::-1], cur[::-1, ::-1]])
    with open(path, "wb") as f:
        f.write(text.encode("latin-1") + b"\x1a\x04" + data)


def compress(src, dst):
    """gzip -9n: no name, no time, the same bytes every run."""
    with open(src, "rb") as f:
        data = f.read()
    with open(dst, "wb") as raw:
        with gzip.GzipFile(filename="", mode="wb", compresslevel=9, fileobj=raw, mtime=0) as g:
            g.write(data)


# ---------------------------------------------------------------- readers

def gwyddion(path, channel=0):
    """Heights (rows top first, NaN under the mask), sizes in metres and
    the channel's title as Gwyddion 2.62 reads `path`."""
    tmp = tempfile.mkdtemp()
    out = os.path.join(tmp, "out.gwy")
    subprocess.run(["gwyddion", "--no-splash", f"--convert-to-gwy={out}", path],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    o = gwyfile.load(out)
    shutil.rmtree(tmp)
    d = o[f"/{channel}/data"]
    z = np.array(d.data, dtype=float)
    if f"/{channel}/mask" in o:
        z[np.asarray(o[f"/{channel}/mask"].data) > 0.5] = np.nan
    return z, (d["xreal"], d["yreal"]), o.get(f"/{channel}/data/title")


def st_reader(path):
    """Heights (rows top first, metres, NaN where masked) and sizes as
    SurfaceTopography's own reader reads `path`."""
    t = open_topography(path).topography()
    s = get_unit_conversion_factor(t.unit, "m")
    h = t.heights()
    z = np.ma.filled(np.ma.masked_invalid(h).astype(float), np.nan).T * s
    return z, tuple(v * s for v in t.physical_sizes)


def rsciio_reader(path):
    """Heights (metres) and sizes as rosettasciio reads a Digital Surf
    file: the first object; a profile is one row."""
    from rsciio.digitalsurf import file_reader
    d = file_reader(path)[0]
    axes = d["axes"]
    z = np.array(d["data"], dtype=float)
    if z.ndim == 3:
        # A surface with its colour image (RGBSURFACE): the first layer.
        z, axes = z[0], axes[1:]
    z = np.atleast_2d(z)
    m = {"mm": 1e-3, "um": 1e-6, "µm": 1e-6, "nm": 1e-9, "m": 1.0}
    zu = d["metadata"]["Signal"].get("quantity", "").replace("\0", "")
    zs = m[zu[zu.rfind("(") + 1:zu.rfind(")")]] if "(" in zu else 1e-6
    sizes = [a["size"] * a["scale"] * m[a["units"].replace("\0", "")] for a in axes]
    lx = sizes[-1]
    ly = sizes[0] if len(sizes) == 2 else 0.0
    return z * zs, (lx, ly)


def surfalize_reader(path):
    import surfalize
    s = surfalize.Surface.load(path)
    z = np.array(s.data, dtype=float) * 1e-6
    # surfalize's width is first to last point: its steps times the points.
    return z, (s.step_x * z.shape[1] * 1e-6, s.step_y * z.shape[0] * 1e-6)


def nanonis_reader(path, name, backward=False):
    """nanonispy2's image (as stored), turned as Gwyddion shows it: an
    upward scan's lines reversed, a backward image mirrored."""
    import nanonispy2 as nap
    s = nap.read.Scan(path)
    z = np.array(s.signals[name]["backward" if backward else "forward"], dtype=float)
    if s.header["scan_dir"] == "up":
        z = z[::-1]
    if backward:
        z = z[:, ::-1]
    return z, tuple(float(v) for v in s.header["scan_range"])


def st_numbers(z, size):
    """Sq and Sdq (a profile: Rq and RΔq) of heights z (rows of x) over
    size, as SurfaceTopography computes them: undefined points filled,
    the plane (line) removed."""
    if z.shape[0] == 1:
        t = UniformLineScan(z[0], size[0], periodic=False)
        if np.isnan(z).any():
            t = UniformLineScan(np.ma.masked_invalid(z[0]), size[0], periodic=False)
            t = t.interpolate_undefined_data()
        d = t.detrend("height")
        return d.rms_height_from_profile(), d.rms_slope_from_profile()
    t = Topography(np.ma.masked_invalid(z.T), size, periodic=False)
    if np.isnan(z).any():
        t = t.interpolate_undefined_data()
    d = t.detrend("height")
    return d.rms_height_from_area(), d.rms_gradient()


def agree(a, b, what, tol=1e-12):
    """The largest difference of two readings of the same heights, each
    about its mean (Gwyddion adds a BCR file's `zmin`, rosettasciio a
    Digital Surf file's offset: constants the plane removes), relative to
    their range; NaN at the same places."""
    assert a.shape == b.shape, (what, a.shape, b.shape)
    assert (np.isnan(a) == np.isnan(b)).all(), what
    span = np.nanmax(a) - np.nanmin(a)
    e = np.nanmax(np.abs((a - np.nanmean(a)) - (b - np.nanmean(b)))) / span
    assert e < tol, (what, e)
    return e


def case(out, name, z, size, checks, channel="-", patch=None):
    ny, nx = z.shape
    ly = 0.0 if ny == 1 else size[1]
    sq, sdq = st_numbers(z, size)
    out.write(f"file {name} channel {channel}" + (f" patch {patch}" if patch else "") + "\n")
    out.write(f"grid {nx} {ny} {r(size[0])} {r(ly)} {int(np.isnan(z).sum())}\n")
    out.write(f"real {r(sq)} {r(sdq)}\n")
    out.write(f"readers {' '.join(f'{k}:{v:.1e}' for k, v in checks)}\n")
    print(f"{name} {channel}: {nx} x {ny}, Sq {sq:.4g} m, Sdq {sdq:.4g}, {checks}")


def refused(out, name, text, channel="-"):
    out.write(f"file {name} channel {channel}\nrefused {text}\n")


def lab(a):
    os.makedirs(OUT, exist_ok=True)
    p = lambda n: os.path.join(OUT, n)  # noqa: E731
    write_gwyo(p("gwyo-1.gwy"))
    write_xqd(p("xqd-1.xqd"), 64, 64, 15.625, 15.625, 0.001)
    write_xqd(p("xqd-2.xqd"), 96, 40, 10.0, 20.0, 0.002)
    write_surz(p("surz-1.sur"), 2, 72, 56, 32, 0.5, 0.5, 1e-6, [b"um", b"um", b"um"], 2,
               special=1)
    write_surz(p("surz-2.pro"), 1, 300, 1, 16, 0.002, 0.0, 2e-8, [b"mm", b"", b"mm"], 1)
    write_surz(p("surz-3.sur"), 2, 40, 48, 16, 25.0, 20.0, 0.005, [b"nm", b"nm", b"nm"], 3,
               inversion=1)
    write_surz_rsciio(p("surz-rs.sur"))
    write_bcr(p("bcr-1.bcr"), unicode=False)
    write_bcr(p("bcrf-2.bcrf"), unicode=True)
    write_sxm(p("sxm-1.sxm"))
    res = os.path.join(a.afmreader, "tests", "resources")
    for n in ["sample_0.top", "sample_1_um_scale.stp"]:
        compress(os.path.join(res, n), p(n + ".gz"))
    nx = os.path.join(a.pynxtools, "src", "pynxtools_spm", "nomad", "example_uploads", "afm",
                      "AFMExampleWithCustomization", "A151216.123306-02602.sxm")
    compress(nx, p("A151216.123306-02602.sxm.gz"))

    tmp = tempfile.mkdtemp()

    def plain(n):
        if not n.endswith(".gz"):
            return p(n)
        q = os.path.join(tmp, n[:-3])
        with gzip.open(p(n), "rb") as g, open(q, "wb") as f:
            f.write(g.read())
        return q

    out = open(p("lab.txt"), "w")
    out.write("# What independent readers read from files in the lab's formats and what\n")
    out.write(f"# SurfaceTopography {SurfaceTopography.__version__} computes on it, by "
              "scripts/lab_formats_reference.py. SI units.\n")
    for n in ["gwyo-1.gwy", "xqd-1.xqd", "xqd-2.xqd", "bcr-1.bcr", "bcrf-2.bcrf"]:
        z, size, _ = gwyddion(plain(n))
        checks = [("gwyddion", 0.0)]
        if n.startswith("bcr"):
            zs, ss = st_reader(plain(n))
            assert np.allclose(ss, size, rtol=1e-14), (ss, size)
            checks.append(("surfacetopography", agree(z, zs, n)))
        case(out, n, z, size, checks)
    for n in ["surz-1.sur", "surz-2.pro", "surz-3.sur", "surz-rs.sur"]:
        z, size = rsciio_reader(plain(n))
        checks = [("rosettasciio", 0.0)]
        if n.endswith(".sur") and n != "surz-3.sur":
            # surfalize leaves inverted heights as stored.
            zs, ss = surfalize_reader(plain(n))
            assert np.allclose(ss, size, rtol=1e-6), (ss, size)
            checks.append(("surfalize", agree(z, zs, n)))
        case(out, n, z, size, checks)
    # Nanonis: Z, forward (default) and backward; Gwyddion numbers the
    # channels Z forward, Z backward, Current forward …
    sxm = plain("sxm-1.sxm")
    for ch, title, back in [("-", "Z", False), ("1", "Z", True)]:
        z, size, _ = gwyddion(sxm, int(ch) if ch != "-" else 0)
        zn, sn = nanonis_reader(sxm, title, back)
        assert np.allclose(sn, size, rtol=1e-14)
        case(out, "sxm-1.sxm", z, size, [("gwyddion", 0.0), ("nanonispy2", agree(z, zn, ch))],
             channel=ch)
    refused(out, "sxm-1.sxm", "Nanonis .sxm: channel 2 'Current (Forward)' (ampere) holds values in ampere",
            channel="2")
    real = plain("A151216.123306-02602.sxm.gz")
    refused(out, "A151216.123306-02602.sxm.gz", "Nanonis .sxm: channel 'Z (Forward)' is flat")
    z, size, title = gwyddion(real, 8)
    assert title == "Amplitude (Forward)", title
    zn, sn = nanonis_reader(real, "Amplitude")
    case(out, "A151216.123306-02602.sxm.gz", z, size,
         [("gwyddion", 0.0), ("nanonispy2", agree(z, zn, "amplitude"))], channel="8")
    for n in ["sample_0.top.gz", "sample_1_um_scale.stp.gz"]:
        z, size = st_reader(plain(n))
        zg, sg, _ = gwyddion(plain(n))
        checks = [("surfacetopography", 0.0), ("gwyddion-heights", agree(z, zg, n, 1e-5))]
        case(out, n, z, size, checks)
    out.close()
    shutil.rmtree(tmp)


def samples(a):
    """Reference lines for the real files in `a.samples`."""
    prov = {}
    for line in open(os.path.join(a.samples, "PROVENANCE.txt")):
        w = line.split()
        if len(w) == 3:
            prov[os.path.join(w[0], w[2])] = (w[0].replace("+", "/"), w[1], w[2])
    cases = [
        ("AFM-SPM+AFMReader/tests/resources/sample_0.stp", "st"),
        ("AFM-SPM+AFMReader/tests/resources/sample_1_um_scale.top", "st"),
        ("AFM-SPM+TopoStats/tests/resources/file.top", "st"),
        ("AFM-SPM+TopoStats/tests/resources/file.stp", "st"),
        ("ContactEngineering+SurfaceTopography/test/file_format_examples/stp-1.stp", "st"),
        ("ContactEngineering+SurfaceTopography/test/file_format_examples/top-1.top", "st"),
        ("ContactEngineering+SurfaceTopography/test/file_format_examples/bcrf-1.bcrf", "gwy"),
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_surface.sur", "patch"),
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_profile.pro", "patch"),
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_RGBSURFACE.sur", "rs"),
    ]
    refusals = [
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_RGB.sur", "Digital Surf compressed .sur: an RGB image"),
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_spectra.pro", "Digital Surf compressed .sur: a spectrum"),
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_spectrum.pro", "Digital Surf .sur: a spectrum"),
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_spectrum_compressed.pro", "Digital Surf compressed .sur: a spectrum"),
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_spectral_map.sur", "Digital Surf .sur: a hyperspectral map"),
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_spectral_map_compressed.sur", "Digital Surf compressed .sur: a hyperspectral map"),
        ("hyperspy+rosettasciio/rsciio/tests/data/digitalsurf/test_surface.sur", "Digital Surf compressed .sur: the unit of the heights is 'a.u.'"),
        ("Au_mica_2023_Y_A_diPAMY_20230512_058.sxm", "Nanonis .sxm: channel 'Z (Forward)' is flat"),
        ("A151216.123306-02602.sxm", "Nanonis .sxm: channel 'Z (Forward)' is flat"),
    ]
    tmp = tempfile.mkdtemp()
    out = open(os.path.join(OUT, "samples.txt"), "w")
    out.write("# Real files fetched from public repositories (not committed): repository,\n"
              "# commit, path and SHA-256, then what independent readers read from them,\n"
              "# by scripts/lab_formats_reference.py --samples. SI units.\n")

    def where(rel):
        full = os.path.join(a.samples, rel)
        repo, commit, path = prov.get(rel, ("pypi/pynxtools-spm-0.4.1", "sdist", rel))
        sha = hashlib.sha256(open(full, "rb").read()).hexdigest()
        out.write(f"sample {rel} {repo} {commit} {path} {sha}\n")
        return full

    for rel, how in cases:
        full = where(rel)
        if how == "st":
            z, size = st_reader(full)
            zg, _, _ = gwyddion(full)
            # Gwyddion 2.62 stretches a WSxM file's floating-point heights
            # to span its Z amplitude, printed to 6 digits: they differ from
            # the stored ones by up to 1e-6 where it was rounded.
            case(out, rel, z, size, [("surfacetopography", 0.0),
                                     ("gwyddion-heights", agree(z, zg, rel, 1e-5))])
        elif how == "gwy":
            z, size, _ = gwyddion(full)
            zs, ss = st_reader(full)
            assert np.allclose(ss, size, rtol=1e-14)
            case(out, rel, z, size, [("gwyddion", 0.0), ("surfacetopography", agree(z, zs, rel))])
        elif how == "rs":
            z, size = rsciio_reader(full)
            case(out, rel, z, size, [("rosettasciio", 0.0)])
        else:
            b = bytearray(open(full, "rb").read())
            assert b[212:216] == b"a.u."
            b[212:228] = b"um".ljust(16, b"\0")
            q = os.path.join(tmp, os.path.basename(rel))
            open(q, "wb").write(bytes(b))
            z, size = rsciio_reader(q)
            case(out, rel, z, size, [("rosettasciio", 0.0)], patch="um")
    for rel, text in refusals:
        where(rel)
        refused(out, rel, text)
    out.close()
    shutil.rmtree(tmp)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--afmreader", required=True, help="AFMReader 0.0.7's sdist, unpacked")
    ap.add_argument("--pynxtools", required=True, help="pynxtools-spm 0.4.1's sdist, unpacked")
    ap.add_argument("--samples", help="the folder of fetched real files (not committed)")
    a = ap.parse_args()
    lab(a)
    if a.samples:
        samples(a)


if __name__ == "__main__":
    main()
