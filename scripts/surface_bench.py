#!/usr/bin/env python3
"""Time roughtui and SurfaceTopography reading the same 1024 x 1024 text map.

Script: scripts/surface_bench.py (a benchmark, not a test)
Pinned: SurfaceTopography==1.27.1 (requirements line below).

    cargo build --release -p rough-surface --example read_surface
    cargo build --release            # optional: the explorer's figures too
    python3 scripts/surface_bench.py [--n 1024] [--runs 3]
    python3 scripts/surface_bench.py --n 4096 --big   # roughtui alone, big map

Makes a 1024 x 1024 map with SurfaceTopography's `fourier_synthesis`
(non-periodic: cut from a 2048 x 2048 periodic one) in the Gwyddion text
format (~18 MB, 11 significant digits) in a temporary folder, then, in
turn, `runs` times each:

- roughtui: the `read_surface` example (read, parse, plane, Hann window,
  FFT, moment table, display spectrum; the file's SHA-256 beside);
- SurfaceTopography: `read_topography`, `detrend('height')`, one moment
  (`moment_power_spectrum(order=2)`, Hann window, one FFT).

With target/release/roughtui built, also `roughtui bench --surface` on the
same file: the explorer's first screen (file read, moments tabulated,
first 160x48 frame drawn), a zeta step and an H0/E step (update and frame),
and that process's peak memory.

Each under /usr/bin/time -v: wall time of the work itself (timed inside
the process, so Python's start-up and imports are reported apart) and the
peak resident memory of the whole process. Prints the best of the runs.
On a shared machine the absolute times are noisy: the ratio, measured
in one run, is the figure to quote.

requirements: SurfaceTopography==1.27.1
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

ST_CODE = r"""
import sys, time
t0 = time.perf_counter()
from SurfaceTopography import read_topography
t1 = time.perf_counter()
t = read_topography(sys.argv[1]).detrend('height')
m2 = t.moment_power_spectrum(order=2, reliable=False)
t2 = time.perf_counter()
print(f"import {1e3 * (t1 - t0):.1f} ms")
print(f"work {1e3 * (t2 - t1):.1f} ms")
print(f"M2 {m2!r}")
"""


def make_big(path, n):
    """An n x n self-affine map (H = 0.8) by numpy's real FFT alone, in
    Gwyddion's text format with 5 significant digits (a 4096 x 4096 map is
    ~195 MB): for the big-map figures, where SurfaceTopography's
    synthesis of a 2n x 2n map would take minutes and gigabytes."""
    import numpy as np
    rng = np.random.default_rng(1)
    qx = np.fft.fftfreq(n)[:, None]
    qy = np.fft.rfftfreq(n)[None, :]
    q = np.sqrt(qx ** 2 + qy ** 2)
    q[0, 0] = 1
    a = q ** -1.8 * (rng.standard_normal(q.shape) + 1j * rng.standard_normal(q.shape))
    a[0, 0] = 0
    h = np.fft.irfft2(a, s=(n, n))
    h *= 100 / h.std()
    with open(path, "w") as f:
        f.write(f"# Channel: Height\n# Width: {10 * n / 1024:g} µm\n"
                f"# Height: {10 * n / 1024:g} µm\n# Value units: nm\n")
        np.savetxt(f, h, fmt="%.4e", delimiter="\t")


def make(path, n):
    import numpy as np
    from SurfaceTopography.Generation import fourier_synthesis
    t = fourier_synthesis((2 * n, 2 * n), (20e3, 20e3), hurst=0.8, rms_height=100,
                          unit="nm", rng=11)
    h = t.heights()[:n, :n]
    with open(path, "w") as f:
        f.write(f"# Channel: Height\n# Width: {10 * n / 1024:g} µm\n"
                f"# Height: {10 * n / 1024:g} µm\n# Value units: nm\n")
        np.savetxt(f, h.T, fmt="%.10e")


def timed(cmd):
    out = subprocess.run(["/usr/bin/time", "-v"] + cmd, capture_output=True, text=True, check=True)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", out.stderr).group(1))
    return out.stdout, rss / 1024


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1024)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--big", action="store_true",
                    help="make the map with numpy alone (make_big) and time only "
                         "`roughtui bench --surface` (e.g. --n 4096 --big)")
    a = ap.parse_args()
    if a.big:
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "map.txt")
            make_big(path, a.n)
            print(f"{a.n} x {a.n} map, {os.path.getsize(path) / 1e6:.1f} MB of text")
            for _ in range(a.runs):
                out, rss = timed([ROUGHTUI, "bench", "--surface", path])
                print(f"  peak {rss:.0f} MB (whole process, /usr/bin/time)")
                for line in out.splitlines():
                    print(f"    {line.strip()}")
        return
    if not os.path.exists(EXAMPLE):
        sys.exit("build first: cargo build --release -p rough-surface --example read_surface")
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "map.txt")
        make(path, a.n)
        size = os.path.getsize(path)
        ours, theirs = [], []
        for _ in range(a.runs):
            out, rss = timed([EXAMPLE, path])
            ms = float(re.search(r"read \+ compute: ([\d.]+) ms", out).group(1))
            ours.append((ms, rss))
            out, rss = timed([sys.executable, "-c", ST_CODE, path])
            ms = float(re.search(r"work ([\d.]+) ms", out).group(1))
            imp = float(re.search(r"import ([\d.]+) ms", out).group(1))
            theirs.append((ms, rss, imp))
        o, t = min(ours), min(theirs)
        print(f"{a.n} x {a.n} map, {size / 1e6:.1f} MB of text, best of {a.runs}:")
        print(f"  roughtui          read + all moments + spectrum {o[0]:7.1f} ms, peak {max(r for _, r in ours):5.1f} MB")
        print(f"  SurfaceTopography read + one moment             {t[0]:7.1f} ms, peak {max(r for _, r, _ in theirs):5.1f} MB"
              f" (+ {t[2]:.0f} ms to import)")
        print(f"  ratio {t[0] / o[0]:.1f}x")
        if os.path.exists(ROUGHTUI):
            best = None
            for _ in range(a.runs):
                out, rss = timed([ROUGHTUI, "bench", "--surface", path])
                first = float(re.search(r"\(([\d.]+) ms in all\)", out).group(1))
                if best is None or first < best[0]:
                    best = (first, rss, out)
            print(f"  roughtui explorer: first screen {best[0]:.1f} ms, peak {best[1]:.1f} MB;"
                  f" best of {a.runs}:")
            for line in best[2].splitlines():
                print(f"    {line.strip()}")


if __name__ == "__main__":
    main()
