#!/usr/bin/env python3
"""The contact view's surfaces solved by another code: Tamaas.

For each case, `roughtui export --view surface` writes the synthetic surface
the contact views solve; SurfaceTopography's read_topography reads it (as
any user of contact.engineering would), and Tamaas's KatoSaturated solves
it in cell units (x / L, h / L, E* = 1, L = 1, as
scripts/contact_reference.py does) at the hardness the file's header gives,
at p/H = 0.001, 0.01, 0.1 (the loads of `export --view contact --points 4`).

Writes tests/data/contact/surface_tamaas.csv: per case and load, the SHA-256
of the file's height lines (so that the test knows it solves the same
surface), Tamaas's
areas, its corrected area (Statistics2D.contact with the perimeter of
FloodFill's clusters: Yastrebov et al. 2017) and its wall time. The test
tests/contact_surface.rs compares the contact view's areas with these.

Run: python3 scripts/surface_tamaas_reference.py   (minutes; ROUGHTUI=path
of the binary, default target/release/roughtui)
"""
import hashlib
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import SurfaceTopography
import tamaas as tm
from SurfaceTopography import read_topography

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
BIN = os.environ.get("ROUGHTUI", os.path.join(ROOT, "target", "release", "roughtui"))
OUT = os.path.join(ROOT, "tests", "data", "contact", "surface_tamaas.csv")
TOL = 1e-12
LOADS = [0.001, 0.01, 0.1]
# name, the scene as export's arguments (the same for the surface and the
# contact view)
CASES = [
    ("fig2_z16", ["--preset", "fig2", "--set", "zeta=16", "--cell", "1", "--seed", "1"]),
    # Harder (H0/E* = 0.002): a plastic share at every load.
    ("fig2_z16_h002", ["--preset", "fig2", "--set", "zeta=16", "--set", "h0-over-e=0.002",
                       "--cell", "1", "--seed", "2"]),
]
tm.set_log_level(tm.LogLevel.error)


def heights_sha256(path):
    """SHA-256 of the height lines (the `#` header left out: its words may
    change, the heights may not)."""
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for line in f:
            if not line.startswith(b"#"):
                digest.update(line)
    return digest.hexdigest()


def hardness_of(path):
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("# hardness_in_use_over_e = "):
                return float(line.split("=")[1].split()[0])
    raise SystemExit("no hardness line in " + path)


def solve(h, hardness, p_mean):
    n = h.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [n, n])
    model.E, model.nu = 1.0, 0.0
    solver = tm.KatoSaturated(model, np.ascontiguousarray(h), TOL, hardness)
    solver.max_iter = 500000
    t = time.perf_counter()
    solver.solve(p_mean)
    dt = time.perf_counter() - t
    return np.array(model.traction, dtype=np.float64).reshape(n, n), dt


def main():
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, args in CASES:
            path = os.path.join(tmp, name + ".txt")
            with open(path, "wb") as f:
                subprocess.run([BIN, "export", "--view", "surface"] + args, stdout=f, check=True)
            sha = heights_sha256(path)
            t = read_topography(path, periodic=True)
            lx, ly = t.physical_sizes
            assert abs(lx - ly) < 1e-12 * lx and t.unit == "m", (t.physical_sizes, t.unit)
            # heights()[x, y]; the contact view's rows are y.
            h = np.asarray(t.heights()).T / lx
            hard = hardness_of(path)
            for ph in LOADS:
                p, dt = solve(h, hard, ph * hard)
                area = float((p > 0).mean())
                plastic = float((p >= hard * (1 - 1e-9)).mean())
                clusters = tm.FloodFill.getClusters(p > 0, False)
                perimeter = int(sum(c.perimeter for c in clusters))
                corrected = float(tm.Statistics2D.contact(p, perimeter))
                rows.append((name, sha, ph, area, area - plastic, plastic, corrected,
                             perimeter, dt))
                print(name, ph, area, plastic, corrected, "%.1f s" % dt, flush=True)
    with open(OUT, "w") as csv:
        csv.write("# Tamaas %s KatoSaturated (tolerance %g, cell units L = 1, E* = 1) on the "
                  "surfaces of roughtui export --view surface read by SurfaceTopography %s "
                  "read_topography(periodic=True); scripts/surface_tamaas_reference.py\n"
                  % (tm.__version__, TOL, SurfaceTopography.__version__))
        for name, args in CASES:
            csv.write("# case %s: %s\n" % (name, " ".join(args)))
        csv.write("case,sha256,p_over_h,area,elastic_area,plastic_area,corrected_area,"
                  "perimeter_sides,seconds\n")
        for r in rows:
            csv.write("%s,%s,%r,%r,%r,%r,%r,%d,%.1f\n" % r)


if __name__ == "__main__":
    sys.exit(main())
