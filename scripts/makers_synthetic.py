#!/usr/bin/env python3
"""Small synthetic files in instrument makers' formats that no real file
committed here shows, written to the layouts the makers' software writes
as Gwyddion's, SurfaceTopography's, surfalize's and prysm's readers
read them (read for the facts: the code here is our own).

Script: scripts/makers_synthetic.py
Pinned: numpy, h5py and tifffile as pip resolves them.

    python3 scripts/makers_synthetic.py

Writes to crates/rough-surface/tests/data/makers/ (the same bytes every
run: a seeded random surface, no times):

- `synthetic.vk4`: Keyence VK4 (two height images: 32-bit and 16-bit);
- `synthetic.vk7`: Keyence VK7, the same VK4 bytes in a zip member
  `Vk4File` behind the magic `VK7` and a small thumbnail;
- `synthetic.zon`: Keyence ZON (`KPK0`, a thumbnail, a zip of XML and
  binary planes named by UUIDs; a validity plane marks points not
  measured);
- `synthetic.plux`: Sensofar PLUX (a zip of `index.xml` and float32
  `LAYER_0.raw` in µm; NaN marks points not measured);
- `synthetic.datx`: Zygo DATX (HDF5: `/MetaData` links to
  `/Measurement/Surface`, float64 heights in nm, `No Data` points);
- `synthetic_park.tiff`: Park Systems TIFF (float32 heights in tag 50434,
  the 580-byte version-2 header in 50435).

scripts/makers_reference.py reads them with independent readers
(SurfaceTopography 1.27.1) for the reference numbers.

requirements: numpy, h5py, tifffile
"""
import io
import os
import struct
import zipfile

import h5py
import numpy as np
import tifffile

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data", "makers")


def surface(nx, ny, seed, hurst=0.8):
    """A self-affine random surface of nx × ny points, unit rms, rows y."""
    rng = np.random.default_rng(seed)
    qx = np.fft.fftfreq(nx)[None, :]
    qy = np.fft.fftfreq(ny)[:, None]
    q = np.hypot(qx, qy)
    q[0, 0] = 1.0
    amp = q ** (-1.0 - hurst)
    amp[0, 0] = 0.0
    phase = np.exp(2j * np.pi * rng.random((ny, nx)))
    z = np.fft.ifft2(amp * phase).real
    return z / z.std()


def zipped(members):
    """A zip (deflated, fixed times) of (name, bytes) members."""
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in members:
            info = zipfile.ZipInfo(name, date_time=(2024, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, data)
    return buf.getvalue()


def thumbnail():
    """A tiny BMP, as the makers put before their zip."""
    w = h = 2
    pixels = b"\x80\x80\x80\x00" * (w * h)
    head = b"BM" + struct.pack("<IHHI", 54 + len(pixels), 0, 0, 54)
    info = struct.pack("<IiiHHIIiiII", 40, w, h, 1, 32, 0, len(pixels), 0, 0, 0, 0)
    return head + info + pixels


def vk4():
    nx, ny = 60, 40
    z1 = surface(nx, ny, 1)
    raw1 = np.round((z1 - z1.min()) * 2.0e5).astype("<u4")  # digits of 5 pm
    raw2 = np.round((z1 - z1.min()) * 1.0e4).astype("<u2")
    conditions = [0] * 75
    conditions[0] = 300
    conditions[1:7] = [2024, 1, 1, 0, 0, 0]
    conditions[42] = 271217  # x pixel, pm
    conditions[43] = 271300  # y pixel, pm
    conditions[44] = 5  # pm a digit
    cond = struct.pack("<75I", *conditions)
    at_cond = 12 + 18 * 4

    def image(raw, bits):
        head = struct.pack("<7I", nx, ny, bits, 0, raw.nbytes, 0, int(raw.max()))
        return head + bytes(768) + raw.tobytes()

    img1 = image(raw1, 32)
    img2 = image(raw2, 16)
    at1 = at_cond + len(cond)
    at2 = at1 + len(img1)
    table = [0] * 18
    table[0] = at_cond
    table[6] = at1
    table[7] = at2
    # One step for both (pm a digit): the second image holds the same
    # surface at a twentieth of the heights, in 16 bits.
    data = b"VK4_" + bytes([0, 0, 2, 1]) + bytes(4) + struct.pack("<18I", *table) + cond + img1 + img2
    return data


def vk7(vk4_bytes):
    bmp = thumbnail()
    inner = zipped([("Vk4File", vk4_bytes), ("Vk6ImageData", b"PK\x05\x06" + bytes(18))])
    return b"VK7" + struct.pack("<I", len(bmp)) + bmp + inner


ZON_HEIGHT = "4cdb0c75-5706-48cc-a9a1-adf395d609ae"
ZON_VALID = "9e7ca6dd-0e6a-4d7b-8986-f0a7b773c916"
ZON_UNIT = "686613b8-27b5-4a29-8ffc-438c2780873e"
ZON_DEVICE = "cbc1d39b-215f-4d56-a20e-cf8e5f570755"
ZON_SCAN = "1d35862b-3b48-4df2-9235-833ef590b043"


def plane(arr, element):
    """A ZON binary plane: a 16-byte header, rows padded to 8 bytes."""
    ny, nx = arr.shape
    row = -(-nx * element // 8) * 8
    padded = np.zeros((ny, row // element), dtype=arr.dtype)
    padded[:, :nx] = arr
    return struct.pack("<4i", nx, ny, element, row) + padded.tobytes()


def zon():
    nx, ny = 50, 30
    z = surface(nx, ny, 2)
    raw = np.round(z * 1.5e4).astype("<i4")  # nm (MeterPerUnit 1e-9): 15 µm rms
    valid = np.zeros((ny, nx), dtype="u1")
    valid[3, 4] = 0x01  # out of range
    valid[10, 11:14] = 0x02  # not measured
    valid[20, 20] = 0x40  # a quality flag: still a height
    raw[3, 4] = -590000000
    unit = (
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<CalibrationInfo>\n"
        "  <XYCalibration><MeterPerPixel>2.5E-06</MeterPerPixel></XYCalibration>\n"
        "  <ZCalibration><MeterPerUnit>1E-09</MeterPerUnit></ZCalibration>\n"
        "</CalibrationInfo>\n"
    )
    device = (
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<DeviceInfo><DeviceModelName>VR-3200"
        "</DeviceModelName><DeviceSerialId>0</DeviceSerialId></DeviceInfo>\n"
    )
    scan = (
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<ScanInfo><ScanDateTime>2024-01-01T00:00:00"
        "</ScanDateTime></ScanInfo>\n"
    )
    inner = zipped(
        [
            (ZON_DEVICE, device.encode()),
            (ZON_SCAN, scan.encode()),
            (ZON_UNIT, unit.encode()),
            (ZON_HEIGHT, plane(raw, 4)),
            (ZON_VALID, plane(valid, 1)),
        ]
    )
    bmp = thumbnail()
    return b"KPK0" + struct.pack("<I", len(bmp)) + bmp + inner


def plux():
    nx, ny = 48, 36
    z = (surface(nx, ny, 3) * 0.8).astype("<f4")  # µm
    z[5, 7] = np.nan
    z[30, 40:43] = np.nan
    index = (
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<xml>\n  <GENERAL>\n"
        "    <DATE>2024-01-01 00:00:00</DATE>\n"
        f"    <IMAGE_SIZE_X>{nx}</IMAGE_SIZE_X>\n    <IMAGE_SIZE_Y>{ny}</IMAGE_SIZE_Y>\n"
        "    <FOV_X>0.6458</FOV_X>\n    <FOV_Y>0.6458</FOV_Y>\n  </GENERAL>\n"
        "  <INFO>\n    <ITEM_0><NAME>Device</NAME><VALUE>S neox</VALUE></ITEM_0>\n  </INFO>\n"
        "  <LAYER_0>\n    <FILENAME_Z>LAYER_0.raw</FILENAME_Z>\n  </LAYER_0>\n</xml>\n"
    )
    return zipped([("index.xml", index.encode()), ("LAYER_0.raw", z.tobytes())])


def datx(path):
    nx, ny = 64, 40
    z = surface(nx, ny, 4) * 12.0  # nm
    no_data = 1.7976931348623157e308
    z[2, 3] = no_data
    z[25, 30:34] = no_data
    str_dtype = h5py.string_dtype()
    meta = np.array(
        [
            ("Root", "Measurement", "{A}"),
            ("{A}", "Surface", "{B}"),
            ("{B}", "Path", "/Measurement/Surface"),
        ],
        dtype=[("Source", str_dtype), ("Link", str_dtype), ("Destination", str_dtype)],
    )
    conv = np.dtype(
        [("Category", str_dtype), ("BaseUnit", str_dtype), ("Parameters", h5py.vlen_dtype(np.float64))]
    )

    def converter(category, unit, params):
        c = np.empty(1, dtype=conv)
        c[0] = (category, unit, np.array(params, dtype=np.float64))
        return c

    with h5py.File(path, "w", libver="earliest", track_order=False) as h5:
        h5.create_dataset("MetaData", data=meta)
        d = h5.create_dataset("Measurement/Surface", data=z, chunks=(8, 16), compression="gzip")
        d.attrs["X Converter"] = converter("LateralCat", "Pixels", [0, 3.5e-7, 0, 0])
        d.attrs["Y Converter"] = converter("LateralCat", "Pixels", [0, 3.5e-7, 0, 0])
        d.attrs["Z Converter"] = converter("HeightCat", "NanoMeters", [0, 6.328e-7, 0.5, 1])
        d.attrs["Unit"] = np.array(["NanoMeters"], dtype=str_dtype)
        d.attrs["No Data"] = np.array([no_data])


def park(path):
    nx, ny = 64, 48
    z = (surface(nx, ny, 5) * 0.004).astype("<f4")  # µm before the gain
    z[7, 9] = np.nan
    gain = -4.509369689218176
    h = bytearray(580)
    struct.pack_into("<I", h, 0, 0)
    name = "Topography".encode("utf-16-le")
    h[4:4 + len(name)] = name
    h[68:74] = "NCM".encode("utf-16-le")
    struct.pack_into("<II", h, 100, nx, ny)
    struct.pack_into("<III", h, 128, 1, 0, 0)
    struct.pack_into("<dd", h, 140, 2.5, 1.875)
    struct.pack_into("<ddd", h, 220, gain, 1.0, 0.0)
    h[244:248] = "um".encode("utf-16-le")
    struct.pack_into("<I", h, 348, 2)
    image = np.zeros((ny, nx), dtype=np.uint8)
    tifffile.imwrite(
        path,
        image,
        photometric="minisblack",
        software="Park Systems SmartScan",
        extratags=[
            (50432, 4, 1, 0x0E031301, True),
            (50433, 4, 1, 0x01000002, True),
            (50434, 1, z.nbytes, z.tobytes(), True),
            (50435, 7, len(h), bytes(h), True),
        ],
        metadata=None,
    )


def main():
    os.makedirs(OUT, exist_ok=True)
    v = vk4()
    for name, data in [
        ("synthetic.vk4", v),
        ("synthetic.vk7", vk7(v)),
        ("synthetic.zon", zon()),
        ("synthetic.plux", plux()),
    ]:
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(data)
    datx(os.path.join(OUT, "synthetic.datx"))
    park(os.path.join(OUT, "synthetic_park.tiff"))


if __name__ == "__main__":
    main()
