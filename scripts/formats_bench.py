#!/usr/bin/env python3
"""Time roughtui reading the same 2048 x 2048 map as a float64 x3p file, as
a Gwyddion .gwy file and as a text matrix.

Script: scripts/formats_bench.py (a benchmark, not a test)
Pinned: SurfaceTopography==1.27.1, x3pio==2.0.0, gwyfile==0.3.0
(requirements line below).

    cargo build --release -p rough-surface --example read_surface
    cargo build --release            # optional: the explorer's first screen too
    python3 scripts/formats_bench.py [--n 2048] [--runs 3]

Makes an n x n map with SurfaceTopography's `fourier_synthesis` (cut from
a 2n x 2n periodic one) and writes it, in a temporary folder, as

- a text matrix in Gwyddion's format (11 significant digits, as
  scripts/surface_bench.py writes it);
- an x3p file of float64 heights (x3pio, deflated as it writes them);
- a .gwy file (gwyfile).

Then, `runs` times each, the `read_surface` example (read, parse or unpack
and check the MD5, plane, Hann window, FFT, moment table, display
spectrum; the SHA-256 beside) and, with target/release/roughtui built,
`roughtui bench --surface FILE`: the explorer's first screen (file read,
moments tabulated, first 160x48 frame drawn). Prints the best of the runs
and each file's size. On a shared machine the absolute times are noisy:
the ratios, measured in one run, are the figures to quote.

requirements: SurfaceTopography==1.27.1 x3pio==2.0.0 gwyfile==0.3.0
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
EXAMPLE = os.path.join(ROOT, "target", "release", "examples", "read_surface")
ROUGHTUI = os.path.join(ROOT, "target", "release", "roughtui")


def make(d, n):
    import numpy as np
    import x3pio
    from gwyfile.objects import GwyContainer, GwyDataField, GwySIUnit
    from SurfaceTopography.Generation import fourier_synthesis
    t = fourier_synthesis((2 * n, 2 * n), (20e3, 20e3), hurst=0.8, rms_height=100,
                          unit="nm", rng=11)
    h = t.heights()[:n, :n].T * 1e-9  # rows of y, metres
    width = 10e-6 * n / 1024
    files = {}
    p = os.path.join(d, "map.txt")
    with open(p, "w") as f:
        f.write(f"# Channel: Height\n# Width: {width:g} m\n# Height: {width:g} m\n"
                "# Value units: m\n")
        np.savetxt(f, h, fmt="%.10e")
    files["text"] = p
    p = os.path.join(d, "map.x3p")
    x3pio.write(p, h, x_scale=width / n, y_scale=width / n)
    files["x3p (float64)"] = p
    p = os.path.join(d, "map.gwy")
    c = GwyContainer()
    c["/0/data"] = GwyDataField(np.ascontiguousarray(h), xreal=width, yreal=width,
                                si_unit_xy=GwySIUnit(unitstr="m"),
                                si_unit_z=GwySIUnit(unitstr="m"))
    c["/0/data/title"] = "Height"
    c.tofile(p)
    files[".gwy"] = p
    return files


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=2048)
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    if not os.path.exists(EXAMPLE):
        sys.exit("build first: cargo build --release -p rough-surface --example read_surface")
    with tempfile.TemporaryDirectory() as d:
        files = make(d, a.n)
        print(f"{a.n} x {a.n} map, best of {a.runs}:")
        read = {}
        for name, p in files.items():
            out = run([EXAMPLE, p, "--repeat", str(a.runs)])
            read[name] = float(re.search(r"read \+ compute: ([\d.]+) ms", out).group(1))
            line = f"  {name:14} {os.path.getsize(p) / 1e6:6.1f} MB  read + compute {read[name]:7.1f} ms"
            if os.path.exists(ROUGHTUI):
                best = min(
                    float(re.search(r"\(([\d.]+) ms in all\)",
                                    run([ROUGHTUI, "bench", "--surface", p])).group(1))
                    for _ in range(a.runs)
                )
                line += f", first screen {best:7.1f} ms"
            print(line)
        for name in files:
            if name != "text":
                print(f"  {name} takes {read[name] / read['text']:.2f} of the text's time")


if __name__ == "__main__":
    main()
