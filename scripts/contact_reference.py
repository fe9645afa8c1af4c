#!/usr/bin/env python3
"""Reference pressures for rough-contact from Tamaas's KatoSaturated.

Writes crates/rough-contact/tests/data/tamaas/: one surface per case
(<case>.surface.f32, 256 x 256 little-endian float32, row-major) and one
pressure field per (case, load) (<case>.<k>.pressure.f32), plus cases.csv
with the parameters, Tamaas's areas and its wall time. The surfaces are
synthesised here with numpy (not by the crate): white noise filtered by
sqrt(C(q)), q0 = 1, rescaled to the rms slope; both solvers then read the
same float32 values. Cell side L = 1, E* = 1 (Tamaas E = 1, nu = 0).

Run: python3 scripts/contact_reference.py [case ...]   (Tamaas needs minutes per load)
"""
import os, sys, time
import numpy as np
import tamaas as tm

N = 256
OUT = os.path.join(os.path.dirname(__file__), "..", "crates", "rough-contact", "tests", "data", "tamaas")
os.makedirs(OUT, exist_ok=True)
tm.set_log_level(tm.LogLevel.error)


def powerlaw(seed, zeta, hurst, slope):
    rng = np.random.default_rng(seed)
    w = np.fft.rfft2(rng.standard_normal((N, N)))
    kx = np.fft.rfftfreq(N, 1.0 / N)[None, :]
    ky = np.fft.fftfreq(N, 1.0 / N)[:, None]
    k = np.hypot(kx, ky)
    band = (k >= 1 - 1e-9) & (k <= zeta + 1e-9)
    filt = np.zeros_like(k)
    filt[band] = k[band] ** (-(1 + hurst))
    h = np.fft.irfft2(w * filt, s=(N, N))
    hk = np.fft.fft2(h)
    kxf = np.fft.fftfreq(N, 1.0 / N)[None, :] * 2 * np.pi
    kyf = np.fft.fftfreq(N, 1.0 / N)[:, None] * 2 * np.pi
    g2 = (np.abs(hk) ** 2 * (kxf**2 + kyf**2)).sum() / N**4
    return h * slope / np.sqrt(g2)


def tamaas_solve(h, hardness, p_mean):
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [N, N])
    model.E = 1.0
    model.nu = 0.0
    solver = tm.KatoSaturated(model, np.ascontiguousarray(h, dtype=np.float64), 1e-13, hardness)
    solver.setMaxIterations(200000)
    t = time.perf_counter()
    solver.solve(p_mean)
    dt = time.perf_counter() - t
    return np.array(model.traction, dtype=np.float64).reshape(N, N), dt


base = powerlaw(1, 16, 0.8, 0.1)
plateau = np.minimum(base, np.quantile(base, 0.995))
cases = [
    # name, surface, hardness, loads as p/H
    ("powerlaw", base, 0.05, [1e-4, 0.005, 0.02, 0.1, 0.5]),
    ("plateau", plateau, 0.05, [0.02]),
    ("elastic", base, 1e3, [1e-6]),
    ("plastic", base, 0.002, [0.1]),
    ("zeta1", powerlaw(2, 1, 0.8, 0.1), 0.05, [0.1]),
]
only = set(sys.argv[1:])
# A subset given on the command line goes to its own file (cases-<names>.csv),
# so that two runs can share the machine; the test reads every cases*.csv.
csv_name = "cases-%s.csv" % "-".join(sorted(only)) if only else "cases.csv"
with open(os.path.join(OUT, csv_name), "w") as csv:
    if True:
        csv.write("# Tamaas %s KatoSaturated, tolerance 1e-13, N = %d, L = 1, E* = 1\n" % (tm.__version__, N))
        csv.write("case,k,hardness,p_over_h,area,elastic_area,plastic_area,seconds\n")
    for name, h, hard, loads in cases:
        if only and name not in only:
            continue
        h32 = h.astype("<f4")
        h32.tofile(os.path.join(OUT, name + ".surface.f32"))
        for k, ph in enumerate(loads):
            p, dt = tamaas_solve(h32.astype(np.float64), hard, ph * hard)
            area = (p > 0).mean()
            plastic = (p >= hard * (1 - 1e-9)).mean()
            p.astype("<f4").tofile(os.path.join(OUT, "%s.%d.pressure.f32" % (name, k)))
            csv.write("%s,%d,%r,%r,%r,%r,%r,%.3f\n" % (name, k, float(hard), float(ph), float(area), float(area - plastic), float(plastic), dt))
            csv.flush()
            print(name, ph, area, plastic, dt, flush=True)
