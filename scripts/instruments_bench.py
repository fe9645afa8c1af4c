#!/usr/bin/env python3
"""Times the reading of real instruments' files: roughtui's `read_surface`
example (release build: read, fill, detrend, window, FFT, moment table,
spectrum) beside SurfaceTopography 1.27.1 (read, fill the undefined points,
detrend, one moment), best of N runs each, on the example files in
crates/rough-surface/tests/data/instruments/ (unpacked to a temporary
folder first). A benchmark, not a test: the machine's load shows in the
figures, so run it on a quiet machine and read the ratio.

    cargo build --release -p rough-surface --example read_surface
    python3 scripts/instruments_bench.py [--repeat 3]

requirements: SurfaceTopography==1.27.1
"""
import argparse
import gzip
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import SurfaceTopography
from SurfaceTopography import open_topography

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data", "instruments")
EXE = os.path.join(HERE, "..", "target", "release", "examples", "read_surface")

# (file, share of undefined points allowed, in percent, or None)
FILES = [
    ("sur-2.sur", None),
    ("plu-1.plu", None),
    ("di-3.di", None),
    ("di-5.di", None),
    ("opd-1.opd", None),
    ("metropro-1.dat", None),
    ("al3d-1.al3d", None),
    ("nid-1.nid", None),
    ("spot_1-1000nm.ibw", None),
    ("opdx-3.opdx", None),
    ("frt-2.frt", 35),
    ("frt-1.frt", 35),
]


def st_time(path):
    t0 = time.perf_counter()
    t = open_topography(path).topography()
    if t.has_undefined_data:
        t = t.interpolate_undefined_data()
    t = t.detrend("height")
    t.integrate_psd(lambda q: q ** 2, reliable=False)
    return time.perf_counter() - t0


def ours(path, allowed, repeat):
    args = [EXE, path, "--repeat", str(repeat)]
    if allowed is not None:
        args += ["--max-undefined", str(allowed)]
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    line = next(l for l in out.splitlines() if l.startswith("read + compute:"))
    return float(line.split()[2]) / 1e3


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--repeat", type=int, default=3)
    a = p.parse_args()
    tmp = tempfile.mkdtemp()
    print(f"# SurfaceTopography {SurfaceTopography.__version__}, numpy {np.__version__}; "
          f"best of {a.repeat}; load {os.getloadavg()[0]:.1f}")
    print(f"{'file':20} {'roughtui':>10} {'SurfaceTopography':>18}")
    for name, allowed in FILES:
        path = os.path.join(tmp, name)
        with gzip.open(os.path.join(DATA, name + ".gz"), "rb") as g, open(path, "wb") as f:
            f.write(g.read())
        st = min(st_time(path) for _ in range(a.repeat))
        rt = ours(path, allowed, a.repeat)
        print(f"{name:20} {rt * 1e3:8.1f} ms {st * 1e3:15.1f} ms")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
