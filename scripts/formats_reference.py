#!/usr/bin/env python3
"""Test files in the instruments' formats, and what independent readers
read from them.

Script: scripts/formats_reference.py
Pinned: x3pio==2.0.0, gwyfile==0.3.0, SurfaceTopography==1.27.1
(requirements line below).

    pip install x3pio==2.0.0 gwyfile==0.3.0 SurfaceTopography==1.27.1
    python3 scripts/formats_reference.py

Writes into crates/rough-surface/tests/data/formats/:

- x3p files written by x3pio (ISO 25178-72): maps of each data type (D, F,
  L, I), a profile, a map with NaN points (float64) and one with a
  validity file (int16), a map of three layers;
- x3p files written here by hand from the standard (ISO 5436-2 XML as
  ISO 25178-72 specifies it): heights inside main.xml as a DataList with
  one empty Datum (an invalid point), and a stored (uncompressed) zip with
  bindata/data.bin, bindata/valid.bin and md5checksum.hex, the x and y
  increments in another order of elements and no z increment;
- Gwyddion .gwy files written by gwyfile: one channel (sizes in µm,
  heights in nm), three channels (Height in m, Amplitude in V, Phase in
  deg, and a second height channel titled "Height (retrace)" in µm), a
  channel with a mask;
- .gwy files written by Gwyddion 2.62 itself (Debian's `gwyddion`, run
  headless with `--convert-to-gwy`) from five of the x3p files: Gwyddion's
  own x3p reader and serialisation, checked against x3pio's reading (the
  heights exactly up to the z offset, which Gwyddion adds as
  SurfaceTopography does; the mask on the invalid points); without gwyddion
  installed these are left as they are;
- Gwyddion ASCII data matrices as Gwyddion writes them in a locale with
  decimal commas (its default "use dot" off), one UTF-8 and one Latin-1,
  and two exports (Phase in deg, then Height in m) concatenated in one
  file, whose height channel SurfaceTopography is checked to read;
- for each x3p and .gwy file the same heights as a text matrix
  (`NAME.txt`, sizes and heights in metres, shortest round-trip digits),
  for the comparison of heights and moments;
- reference.txt: per file, its size in points and in metres as read by
  x3pio (x3p) and gwyfile (.gwy); NAME.txt holds the heights they read
  (metres, nan for an undefined point). Where SurfaceTopography's own
  readers (`read_topography`) read the file they are checked here to
  agree to 1e-12 (size in points and metres, heights): the .gwy files, the
  x3p files SurfaceTopography wrote and the one written by hand with
  binary data. It reads neither x3pio's revision "ISO25178-72:2017/DAM1"
  nor a DataList, and adds the z axis's Offset to the heights (x3pio and
  roughtui leave it to the placement: the heights agree up to that
  constant).

x3p files carry the date they were written (main.xml, the zip's times): a
new run changes their bytes, not their heights.

requirements: x3pio==2.0.0 gwyfile==0.3.0 SurfaceTopography==1.27.1
"""
import hashlib
import io
import os
import shutil
import subprocess
import zipfile

import gwyfile
import numpy as np
import SurfaceTopography
import x3pio
from gwyfile.objects import GwyContainer, GwyDataField, GwySIUnit
from SurfaceTopography import read_topography
from SurfaceTopography.Support.UnitConversion import get_unit_conversion_factor

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__
assert x3pio.__version__ == "2.0.0", x3pio.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data", "formats")
rng = np.random.default_rng(26)


def r(v):
    """Shortest repr that reads back to the same double."""
    return repr(float(v))


def rough(ny, nx, rms=1e-7):
    """A smooth random surface (rows y, columns x), heights in metres."""
    k = np.fft.fftfreq(nx)[None, :] ** 2 + np.fft.fftfreq(ny)[:, None] ** 2
    spec = (rng.normal(size=(ny, nx)) + 1j * rng.normal(size=(ny, nx))) / (k + 1e-3)
    h = np.real(np.fft.ifft2(spec))
    return rms * h / h.std() + 3e-7


def write_text(name, z, lx, ly):
    """The same heights as a text matrix, sizes and heights in metres."""
    with open(os.path.join(OUT, name + ".txt"), "w") as f:
        f.write(f"# Width: {r(lx)} m\n")
        if z.shape[0] > 1:
            f.write(f"# Height: {r(ly)} m\n")
        f.write("# Value units: m\n")
        for row in z:
            f.write(" ".join(r(v) for v in row) + "\n")


REFS = []


def reference(name, nx, ny, lx, ly, z):
    """One file's reference: sizes in points and metres, heights in metres
    (rows y, columns x)."""
    REFS.append((name, nx, ny, lx, ly, np.asarray(z, dtype=float).reshape(ny, nx)))


def st_read(path):
    """SurfaceTopography's reading: (nx, ny, lx, ly, z rows y) in metres."""
    t = read_topography(path)
    to_m = get_unit_conversion_factor(t.unit, "m")
    h = t.heights()
    if np.ma.isMaskedArray(h):
        h = np.ma.filled(h.astype(float), np.nan)
    h = np.asarray(h, dtype=float) * to_m
    if t.dim == 1:
        (nx,) = t.nb_grid_pts
        (lx,) = t.physical_sizes
        return nx, 1, lx * to_m, 0.0, h.reshape(1, nx)
    nx, ny = t.nb_grid_pts
    lx, ly = t.physical_sizes
    # SurfaceTopography indexes [x, y]; files hold rows of y.
    return nx, ny, lx * to_m, ly * to_m, h.T


def same(a, b, what):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert a.shape == b.shape, (what, a.shape, b.shape)
    assert np.array_equal(np.isnan(a), np.isnan(b)), what
    ok = ~np.isnan(a)
    scale = np.abs(a[ok]).max()
    assert np.abs(a[ok] - b[ok]).max() <= 1e-12 * scale, (what, np.abs(a[ok] - b[ok]).max())


def x3p_files():
    dx, dy = 0.5e-6, 0.7e-6
    z = rough(24, 32)
    for t, dtype in [("d", "FLOAT64"), ("f", "FLOAT32"), ("l", "INT32"), ("i", "INT16")]:
        name = f"sur_{t}"
        path = os.path.join(OUT, name + ".x3p")
        x3pio.write(path, z, x_scale=dx, y_scale=dy, z_type=getattr(x3pio.DataType, dtype))
        check_x3p(name, path)
    prf = rough(1, 64)[0]
    path = os.path.join(OUT, "prf_d.x3p")
    x3pio.write(path, prf, x_scale=0.25e-6)
    check_x3p("prf_d", path)
    holes = z.copy()
    holes[3, 5] = holes[10, 0] = holes[23, 31] = np.nan
    path = os.path.join(OUT, "sur_nan_d.x3p")
    x3pio.write(path, holes, x_scale=dx, y_scale=dy)
    check_x3p("sur_nan_d", path)
    path = os.path.join(OUT, "sur_valid_i.x3p")
    x3pio.write(path, holes, x_scale=dx, y_scale=dy, z_type=x3pio.DataType.INT16)
    with zipfile.ZipFile(path) as zf:
        assert "bindata/valid.bin" in zf.namelist()
    check_x3p("sur_valid_i", path)
    layers = np.stack([z, z[::-1], 2 * z])
    path = os.path.join(OUT, "sur_layers.x3p")
    x3pio.write(path, layers, x_scale=dx, y_scale=dy)
    x = x3pio.read(path)
    assert len(x.layers) == 3
    # SurfaceTopography reads one layer: the first.
    check_x3p("sur_layers", path)
    # Written by SurfaceTopography's own x3p writer, read by both readers.
    from SurfaceTopography import Topography
    for t in ["D", "I"]:
        name = f"st_sur_{t.lower()}"
        path = os.path.join(OUT, name + ".x3p")
        zz = holes if t == "I" else z
        Topography(np.ma.masked_invalid(zz.T), (32 * dx, 24 * dy), unit="m").to_x3p(path, dtype=t)
        # SurfaceTopography 1.27.1 writes the checksum of bindata/data.bin
        # (named so) into md5checksum.hex, where the standard has that of
        # main.xml: x3pio refuses it unless told not to verify.
        with zipfile.ZipFile(path) as zf:
            assert zf.read("md5checksum.hex").decode().strip().endswith("*bindata/data.bin")
        check_x3p(name, path, st=True, verify=False)


def check_x3p(name, path, st=False, verify=True):
    """x3pio's reading (metres) as the reference; with `st`, checked against
    SurfaceTopography's reader (which reads files of the revision
    "ISO5436 - 2000" only, not x3pio's "ISO25178-72:2017/DAM1")."""
    x = x3pio.read(path, verify=verify)
    h = np.asarray(x.layers[0].z, dtype=float)
    if h.ndim == 1:
        h = h.reshape(1, -1)
    ny, nx = h.shape
    lx = nx * x.header.x.increment
    ly = ny * x.header.y.increment if ny > 1 else 0.0
    if st:
        snx, sny, slx, sly, sh = st_read(path)
        assert (snx, sny) == (nx, ny), name
        assert abs(slx - lx) <= 1e-12 * lx and abs(sly - ly) <= 1e-12 * ly, name
        # SurfaceTopography adds the z axis's Offset (x3pio, as roughtui,
        # leaves it to the placement): the heights agree up to a constant.
        off = np.nanmean(sh - h)
        same(sh - off, h, name + " x3pio vs SurfaceTopography")
    reference(name, nx, ny, lx, ly, h)
    write_text(name, h, lx, ly)


MAIN_XML = """<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
  <Record1>
    <Revision>ISO5436 - 2000</Revision>
    <FeatureType>SUR</FeatureType>
    <Axes>
      <CX><AxisType>I</AxisType><DataType>D</DataType>
        <Offset>0</Offset><Increment>{dx}</Increment></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType>
        <Offset>0</Offset><Increment>{dy}</Increment></CY>
      <CZ><AxisType>A</AxisType>{ztype}</CZ>
    </Axes>
  </Record1>
  <Record2>
    <Date>2026-01-01T00:00:00+00:00</Date>
    <Instrument><Manufacturer>by hand</Manufacturer><Model>ISO 25178-72</Model>
      <Serial>0</Serial><Version>1</Version></Instrument>
    <CalibrationDate>2026-01-01T00:00:00+00:00</CalibrationDate>
    <ProbingSystem><Type>NonContacting</Type><Identification>none</Identification></ProbingSystem>
    <Comment>written from the standard by scripts/formats_reference.py</Comment>
  </Record2>
  <Record3>
    <MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>
{data}
  </Record3>
  <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>
"""


def hand_files():
    nx, ny, dx, dy = 12, 9, 2e-6, 2e-6
    z = rough(ny, nx, rms=5e-8)
    # Heights inside main.xml; one point invalid (an empty Datum).
    zl = z.copy()
    zl[4, 7] = np.nan
    datums = "\n".join(
        "      <Datum>{}</Datum>".format("" if np.isnan(v) else r(v)) for v in zl.ravel()
    )
    xml = MAIN_XML.format(
        dx=r(dx), dy=r(dy), nx=nx, ny=ny, ztype="<DataType>D</DataType>",
        data="    <DataList>\n" + datums + "\n    </DataList>",
    ).encode()
    path = os.path.join(OUT, "hand_list.x3p")
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as zf:
        zf.writestr("main.xml", xml)
        zf.writestr("md5checksum.hex", hashlib.md5(xml).hexdigest() + " *main.xml\n")
    check_x3p("hand_list", path)  # SurfaceTopography reads no DataList
    # Binary float32 data, validity bits (LSB first), stored uncompressed;
    # no z increment (1 is meant).
    z32 = z.astype("<f4")
    valid = np.ones(nx * ny, bool)
    valid[[0, 13, 50]] = False
    data = z32.tobytes()
    vbits = np.packbits(valid, bitorder="little").tobytes()
    link = (
        "    <DataLink>\n"
        "      <PointDataLink>bindata/data.bin</PointDataLink>\n"
        f"      <MD5ChecksumPointData>{hashlib.md5(data).hexdigest()}</MD5ChecksumPointData>\n"
        "      <ValidPointsLink>bindata/valid.bin</ValidPointsLink>\n"
        f"      <MD5ChecksumValidPoints>{hashlib.md5(vbits).hexdigest()}</MD5ChecksumValidPoints>\n"
        "    </DataLink>"
    )
    xml = MAIN_XML.format(
        dx=r(dx), dy=r(dy), nx=nx, ny=ny, ztype="<DataType>F</DataType>", data=link
    ).encode()
    path = os.path.join(OUT, "hand_bin.x3p")
    with zipfile.ZipFile(path, "w", zipfile.ZIP_STORED) as zf:
        zf.writestr("main.xml", xml)
        zf.writestr("bindata/data.bin", data)
        zf.writestr("bindata/valid.bin", vbits)
        zf.writestr("md5checksum.hex", hashlib.md5(xml).hexdigest() + " *main.xml\n")
    check_x3p("hand_bin", path, st=True)


def unit(s):
    return GwySIUnit(unitstr=s)


def field(z, xreal, yreal, uxy, uz):
    return GwyDataField(
        np.ascontiguousarray(z, dtype=float), xreal=xreal, yreal=yreal,
        si_unit_xy=unit(uxy), si_unit_z=unit(uz),
    )


def gwy_files():
    to = {"m": 1.0, "µm": 1e-6, "nm": 1e-9}
    z = rough(20, 28, rms=4e-8)
    # One channel: sizes in µm, heights in nm.
    c = GwyContainer()
    c["/0/data"] = field(z / 1e-9, 14.0, 10.0, "µm", "nm")
    c["/0/data/title"] = "Topography"
    path = os.path.join(OUT, "one.gwy")
    c.tofile(path)
    check_gwy("one", path, 0, "µm", "nm", to)
    # Three channels (and a second height channel).
    c = GwyContainer()
    c["/0/data"] = field(z, 14e-6, 10e-6, "m", "m")
    c["/0/data/title"] = "Height"
    c["/1/data"] = field(rng.normal(size=z.shape), 14e-6, 10e-6, "m", "V")
    c["/1/data/title"] = "Amplitude"
    c["/2/data"] = field(rng.normal(size=z.shape), 14e-6, 10e-6, "m", "deg")
    c["/2/data/title"] = "Phase"
    z2 = rough(20, 28, rms=4e-8)
    c["/3/data"] = field(z2 / 1e-6, 14.0, 10.0, "µm", "µm")
    c["/3/data/title"] = "Height (retrace)"
    path = os.path.join(OUT, "three.gwy")
    c.tofile(path)
    check_gwy("three", path, 0, "m", "m", to)
    # SurfaceTopography lists the two height channels; the second:
    check_gwy("three", path, 3, "µm", "µm", to, channel=1, suffix="_3")
    # A mask: Gwyddion marks a masked point with 1.
    mask = np.zeros(z.shape)
    mask[2, 3] = mask[2, 4] = mask[15, 27] = 1.0
    c = GwyContainer()
    c["/0/data"] = field(z / 1e-9, 14.0, 10.0, "µm", "nm")
    c["/0/data/title"] = "Height"
    c["/0/mask"] = field(mask, 14.0, 10.0, "µm", "")
    path = os.path.join(OUT, "mask.gwy")
    c.tofile(path)
    check_gwy("mask", path, 0, "µm", "nm", to)


def check_gwy(name, path, n, uxy, uz, to, channel=None, suffix=""):
    g = gwyfile.load(path)
    f = g[f"/{n}/data"]
    nx, ny = f["xres"], f["yres"]
    zg = np.asarray(f.data, dtype=float).reshape(ny, nx) * to[uz]
    m = g.get(f"/{n}/mask")
    if m is not None:
        zg[np.asarray(m.data).reshape(ny, nx) > 0.5] = np.nan
    lx, ly = f["xreal"] * to[uxy], f["yreal"] * to[uxy]
    if channel is None:
        snx, sny, slx, sly, h = st_read(path)
    else:
        t = read_topography(path, channel_index=channel)
        k = get_unit_conversion_factor(t.unit, "m")
        h = np.asarray(t.heights(), float).T * k
        (snx, sny), (slx, sly) = t.nb_grid_pts, [s * k for s in t.physical_sizes]
    assert (snx, sny) == (nx, ny)
    assert abs(slx - lx) <= 1e-12 * lx and abs(sly - ly) <= 1e-12 * ly
    same(h, zg, name + " gwyfile vs SurfaceTopography")
    reference(name + suffix, nx, ny, slx, sly, h)
    write_text(name + suffix, h, slx, sly)


GWYDDION_FROM = ["sur_d", "sur_valid_i", "st_sur_i", "hand_bin", "hand_list"]


def gwyddion_files():
    """.gwy files written by Gwyddion itself (the Debian package, headless:
    `gwyddion --convert-to-gwy=OUT.gwy FILE.x3p`) from x3p files above:
    Gwyddion reads them with its own x3p reader (invalid points become its
    mask) and writes its own serialisation (with a /0/meta container).
    Checked: the heights (up to the z offset Gwyddion adds) and the mask
    equal x3pio's reading of the x3p."""
    if shutil.which("gwyddion") is None:
        print("gwyddion not installed: the gwyddion_*.gwy files are left as they are")
        return
    for name in GWYDDION_FROM:
        out = os.path.join(OUT, f"gwyddion_{name}.gwy")
        subprocess.run(["gwyddion", "--no-splash", f"--convert-to-gwy={out}",
                        os.path.join(OUT, name + ".x3p")], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        c = gwyfile.load(out)
        f = c["/0/data"]
        z = np.array(f.data, float).reshape(f["yres"], f["xres"])
        m = c.get("/0/mask")
        if m is not None:
            z[np.asarray(m.data).reshape(z.shape) > 0.5] = np.nan
        x = np.asarray(x3pio.read(os.path.join(OUT, name + ".x3p"), verify=False).layers[0].z, float)
        # Gwyddion, like SurfaceTopography, adds the z axis's Offset.
        off = np.nanmean(z - x)
        same(z - off, x, f"gwyddion_{name} vs x3pio")


def ascii_files():
    """Gwyddion's ASCII export in a decimal-comma locale (its "use dot" off):
    a header of comments, values tab-separated with decimal commas."""
    z = rough(10, 12, rms=2e-8)
    lines = ["# Channel: Height", "# Width: 6,000 µm", "# Height: 5,000 µm", "# Value units: m"]
    lines += ["\t".join(f"{v:.6e}".replace(".", ",") for v in row) for row in z]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(OUT, "gwy_ascii_comma.txt"), "w", encoding="utf-8") as f:
        f.write(text)
    with open(os.path.join(OUT, "gwy_ascii_latin1.txt"), "w", encoding="latin-1") as f:
        f.write(text)
    zr = np.array([[float(f"{v:.6e}") for v in row] for row in z])
    # Two channels concatenated (Gwyddion's exports of a phase and a height
    # channel in one file): SurfaceTopography reads the height channel.
    phase = rng.normal(size=z.shape)
    two = ["# Channel: Phase", "# Width: 6.000 µm", "# Height: 5.000 µm", "# Value units: deg"]
    two += ["\t".join(f"{v:.6e}" for v in row) for row in phase]
    two += ["# Channel: Height", "# Width: 6.000 µm", "# Height: 5.000 µm", "# Value units: m"]
    two += ["\t".join(f"{v:.6e}" for v in row) for row in z]
    path = os.path.join(OUT, "gwy_ascii_two.txt")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(two) + "\n")
    t = read_topography(path)
    k = get_unit_conversion_factor(t.unit, "m")
    zr0 = np.array([[float(f"{v:.6e}") for v in row] for row in z])
    same(np.asarray(t.heights(), float).T * k, zr0, "two channels vs SurfaceTopography")
    # SurfaceTopography 1.27.1 reads neither decimal commas nor Latin-1:
    # the reference is the values as printed.
    for name in ["gwy_ascii_comma", "gwy_ascii_latin1"]:
        reference(name, 12, 10, 6e-6, 5e-6, zr)


def main():
    os.makedirs(OUT, exist_ok=True)
    x3p_files()
    hand_files()
    gwy_files()
    gwyddion_files()
    ascii_files()
    with open(os.path.join(OUT, "reference.txt"), "w") as f:
        f.write("# Written by scripts/formats_reference.py: what x3pio "
                f"{x3pio.__version__} and gwyfile {gwyfile.__version__} read (checked "
                f"against SurfaceTopography {SurfaceTopography.__version__} where it "
                "reads the file).\n")
        f.write("# name nx ny lx ly (m); the heights (m, nan undefined) are in NAME.txt\n")
        for name, nx, ny, lx, ly, z in REFS:
            f.write(f"{name} {nx} {ny} {r(lx)} {r(ly)}\n")
    print(len(REFS), "references written to", os.path.normpath(OUT))


if __name__ == "__main__":
    main()
