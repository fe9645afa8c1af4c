#!/usr/bin/env python3
"""Reference numbers of a topography in a contact.engineering container,
read through SurfaceTopography's container reader (its pipeline: the
height scale, then meta.yml's `detrend_mode`).

Script: scripts/container_reference.py
Pinned: SurfaceTopography==1.27.1 (requirements line below).

    pip install SurfaceTopography==1.27.1
    python3 scripts/container_reference.py

Reads crates/rough-surface/tests/data/instruments/container-2.zip
(SurfaceTopography's example container) with `read_container` and writes
to crates/rough-surface/tests/data/instruments/container_reference.txt,
for its stylus profile `uncd_stylus_300um_5mar_3.txt` (meta.yml:
`detrend_mode: curvature`, `unit: mm`, `height_scale: 1.0`): Rq =
`rms_height_from_profile` and RΔq = `rms_slope_from_profile` in SI,
after the pipeline's detrend, and the spacing it read (the end points':
(x_last − x_0)/(n − 1)) beside the least-squares spacing of the same x
(numpy's polyfit), which roughtui reads; RΔq scales with their ratio.

(Its Nanoscope topography is not listed: meta.yml's `height_scale`
0.1120755… is the file's own factor, which the reader has applied
already, and `read_container` applies it a second time — Sq 0.525 nm
where the file read alone gives 4.688 nm; roughtui reads the file's.)

requirements: SurfaceTopography==1.27.1
"""
import io
import os
import zipfile

import numpy as np
import SurfaceTopography
from SurfaceTopography import read_container

assert SurfaceTopography.__version__ == "1.27.1", SurfaceTopography.__version__

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data", "instruments")


def r(v):
    return repr(float(v))


def main():
    path = os.path.join(DATA, "container-2.zip")
    [container] = read_container(path)
    name = "uncd_stylus_300um_5mar_3.txt"
    [t] = [t for t in container if t.info["name"] == name]
    assert t.unit == "mm" and t.dim == 1 and t.is_uniform, (t.unit, t.dim)
    scale = 1e-3
    with zipfile.ZipFile(path) as z:
        member = [m for m in z.namelist() if m.startswith("uncd_stylus")][0]
        x = np.loadtxt(io.BytesIO(z.read(member)))[:, 0]
    n = len(x)
    ls = np.polyfit(np.arange(n), x, 1)[0]
    ends = (x[-1] - x[0]) / (n - 1)
    assert np.isclose(t.physical_sizes[0], n * ends, rtol=1e-12, atol=0)
    with open(os.path.join(DATA, "container_reference.txt"), "w") as out:
        out.write("# A contact.engineering container's topography through SurfaceTopography's\n")
        out.write(f"# read_container, by scripts/container_reference.py with SurfaceTopography "
                  f"{SurfaceTopography.__version__} (numpy {np.__version__}).\n")
        out.write("# container series n rq(m) rdq spacing_end_points spacing_least_squares (mm)\n")
        out.write(f"container-2.zip {name} {n} {r(t.rms_height_from_profile() * scale)} "
                  f"{r(t.rms_slope_from_profile())} {r(ends)} {r(ls)}\n")


if __name__ == "__main__":
    main()
