#!/usr/bin/env python3
"""Reference pressures for rough-contact's hardness per node (solve_capped).

Writes crates/rough-contact/tests/data/capped/: a 32 x 32 periodic power-law
surface (surface.f64), a hardness per node (caps.f64: two asperity-like
levels, the left half of the cell twice as hard as the right), and for each
load the pressure (<k>.pressure.f64, little-endian float64, row-major), plus
cases.csv. Cell side L = 1, E* = 1.

Independent of the crate's conjugate gradient: the problem
  min 1/2 p.K.p - h.p  over 0 <= p <= c with mean(p) = pbar
is solved exactly by NumPy and SciPy. K is the dense periodic compliance
matrix (2/(E*|q|), the constant mode made stiff: mean(p) is fixed, so it
changes the objective by a constant only); for a multiplier lam the bounded
problem min 1/2 |L^T p - L^-1 (h - lam)|^2 (K = L L^T) is solved by SciPy's
lsq_linear with BVLS, an exact active-set method, and lam by brentq until
mean(p) = pbar.

Run: OMP_NUM_THREADS=1 python3 scripts/contact_capped_reference.py   (minutes;
one BLAS thread: many threads slow the BVLS calls down on a shared machine)
"""
import os
import numpy as np
import scipy
from scipy.optimize import lsq_linear, brentq

N = 32
OUT = os.path.join(os.path.dirname(__file__), "..", "crates", "rough-contact", "tests", "data", "capped")
os.makedirs(OUT, exist_ok=True)


def surface(seed=3, zeta=6, hurst=0.8, slope=0.1):
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
    q = np.fft.fftfreq(N, 1.0 / N) * 2 * np.pi
    g2 = (np.abs(hk) ** 2 * (q[None, :] ** 2 + q[:, None] ** 2)).sum() / N**4
    return h * slope / np.sqrt(g2)


def compliance():
    q = np.fft.fftfreq(N, 1.0 / N) * 2 * np.pi
    qq = np.hypot(q[None, :], q[:, None])
    kern = np.where(qq > 0, 2.0 / np.where(qq > 0, qq, 1.0), 0.0)
    K = np.empty((N * N, N * N))
    for i in range(N * N):
        e = np.zeros(N * N)
        e[i] = 1.0
        K[:, i] = np.fft.ifft2(np.fft.fft2(e.reshape(N, N)) * kern).real.ravel()
    K = 0.5 * (K + K.T)
    return K + np.ones_like(K) * K.diagonal().mean()


def solve(K, h, caps, pbar):
    L = np.linalg.cholesky(K)
    A = L.T

    def p_of(lam):
        y = np.linalg.solve(L, h.ravel() - lam)
        r = lsq_linear(A, y, bounds=(np.zeros(N * N), caps.ravel()), method="bvls", tol=1e-15,
                       max_iter=100000)
        return r.x

    f = lambda lam: p_of(lam).mean() - pbar
    lo, hi = -10.0, 10.0
    while f(lo) < 0:
        lo *= 2
    while f(hi) > 0:
        hi *= 2
    lam = brentq(f, lo, hi, xtol=1e-16, rtol=4 * np.finfo(float).eps, maxiter=500)
    return p_of(lam)


def main():
    h = surface()
    caps = np.empty((N, N))
    caps[:, : N // 2] = 0.10
    caps[:, N // 2 :] = 0.05
    K = compliance()
    h.astype("<f8").tofile(os.path.join(OUT, "surface.f64"))
    caps.astype("<f8").tofile(os.path.join(OUT, "caps.f64"))
    rows = []
    for k, pbar in enumerate([0.002, 0.01, 0.03]):
        p = solve(K, h, caps, pbar)
        # Exact zeros and caps (BVLS leaves bounds exactly on them).
        p.astype("<f8").tofile(os.path.join(OUT, f"{k}.pressure.f64"))
        at_cap = np.isclose(p, caps.ravel(), rtol=0, atol=1e-13)
        contact = p > 1e-13
        rows.append((k, pbar, contact.mean(), (contact & ~at_cap).mean(), at_cap.mean()))
    with open(os.path.join(OUT, "cases.csv"), "w") as f:
        f.write(f"# scripts/contact_capped_reference.py, numpy {np.__version__}, scipy {scipy.__version__}: "
                "exact bounded least squares (BVLS) and brentq on the multiplier; "
                "areas: p > 1e-13, at the cap within 1e-13\n")
        f.write("k,p_mean,area,elastic_area,plastic_area\n")
        for r in rows:
            f.write(",".join(repr(float(v)) if i else str(v) for i, v in enumerate(r)) + "\n")
    print(open(os.path.join(OUT, "cases.csv")).read())


if __name__ == "__main__":
    main()
