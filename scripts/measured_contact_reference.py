#!/usr/bin/env python3
"""Reference for the contact simulation of a measured map, from Tamaas.

Writes tests/data/measured_contact/:
- periodic64.txt: a 64 x 64 periodic map, 10 um x 10 um, heights in nm,
  synthesised by SurfaceTopography's fourier_synthesis (H = 0.8, rms slope
  0.1, seed 29), in the text format roughtui reads (--periodic);
- cases.csv: for zeta = 8 and H_use/E* = 0.05 (size effect off), at
  p/H = 0.001, 0.01, 0.1, the areas of Tamaas 2.9's KatoSaturated on the
  map as read back from the text here (numpy: mean removed, wavevectors
  |q| <= zeta q0 kept, q0 = 2 pi / L);
- <k>.pressure.f32: Tamaas's pressure field at load k (E* units, 64 x 64
  row-major little-endian float32).

Tamaas solves the same problem made dimensionless by the cell side
(x / L, h / L): areas and pressures in E* units do not change.

Run: python3 scripts/measured_contact_reference.py   (seconds)
"""
import os
import numpy as np
import tamaas as tm
from SurfaceTopography.Generation import fourier_synthesis

N, L, ZETA, HARD = 64, 10e-6, 8.0, 0.05
LOADS = [0.001, 0.01, 0.1]
OUT = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "measured_contact")
os.makedirs(OUT, exist_ok=True)
tm.set_log_level(tm.LogLevel.error)

t = fourier_synthesis((N, N), (L, L), hurst=0.8, rms_slope=0.1, long_cutoff=L / 2,
                      rng=np.random.default_rng(29), periodic=True)
h = np.asarray(t.heights())  # metres, index [x, y]
path = os.path.join(OUT, "periodic64.txt")
with open(path, "w") as f:
    f.write("# Channel: Height (SurfaceTopography fourier_synthesis, H = 0.8, rms slope 0.1, "
            "seed 29; scripts/measured_contact_reference.py)\n")
    f.write("# Width: 10.000 µm\n# Height: 10.000 µm\n# Value units: nm\n")
    for row in h.T:  # one line per y, values along x
        f.write("\t".join("%.9e" % (v * 1e9) for v in row) + "\n")

# Read back as roughtui does: rows are y, columns x; nm to m; mean removed.
z = np.loadtxt(path, comments="#") * 1e-9
z -= z.mean()
k = np.hypot(np.fft.rfftfreq(N, 1.0 / N)[None, :], np.fft.fftfreq(N, 1.0 / N)[:, None])
spec = np.fft.rfft2(z)
spec[k > ZETA * (1 + 1e-9)] = 0.0
z = np.fft.irfft2(spec, s=(N, N)) / L

with open(os.path.join(OUT, "cases.csv"), "w") as csv:
    csv.write("# Tamaas %s KatoSaturated, tolerance 1e-13, N = %d, zeta = %g, hardness %g E*\n"
              % (tm.__version__, N, ZETA, HARD))
    csv.write("k,p_over_h,area,elastic_area,plastic_area\n")
    for i, ph in enumerate(LOADS):
        model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [N, N])
        model.E, model.nu = 1.0, 0.0
        solver = tm.KatoSaturated(model, np.ascontiguousarray(z), 1e-13, HARD)
        solver.setMaxIterations(200000)
        solver.solve(ph * HARD)
        p = np.array(model.traction, dtype=np.float64).reshape(N, N)
        area = (p > 0).mean()
        plastic = (p >= HARD * (1 - 1e-9)).mean()
        p.astype("<f4").tofile(os.path.join(OUT, "%d.pressure.f32" % i))
        csv.write("%d,%r,%r,%r,%r\n" % (i, ph, float(area), float(area - plastic), float(plastic)))
        print(ph, area, plastic, flush=True)
