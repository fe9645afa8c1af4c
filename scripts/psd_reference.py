#!/usr/bin/env python3
"""Analytic PSD tables and their moments at 50 digits.

Script: scripts/psd_reference.py
Pinned: mpmath==1.3.0 (requirements line below).

    pip install mpmath==1.3.0
    python3 scripts/psd_reference.py

Writes to crates/rough-surface/tests/data/:

- psd_knee.txt: an isotropic PSD table in SurfaceTopography's convention,
  C^iso(q) = C0 for q0 ≤ q ≤ qr (the roll-off) and C0 (q/qr)^(−2(1+H))
  above, H = 0.8, C0 = (2π)² Z qr^(−2(1+H)), Z = 1e-8 m^0.4 (the paper's),
  q0 = 1e5, qr = 1e6, q_end = 1e9 1/m, 8 points per decade (the knee is a
  point, so the power-law interpolation between points is the function);
- psd_knee_ce.txt: the same as contact.engineering's TXT download of its
  "q/π × 2D PSD" series (values q C/π, SI), behind a "1D PSD along x"
  block that must not be read;
- psd_profile_ce.txt: a profile PSD with the same knee,
  C1D = C1 (q/qr)^(−(1+2H)) above qr, as the download of a line scan
  ("1D PSD along x") in the older per-measurement units µm⁻¹ and µm³;
- psd_fig2.txt: fig2's spectrum, (2π)² Z q^(−2(1+H)) from 1e5 to 1e9;
- psd_reference.txt: for each table the paper's profile moments at 31
  cutoffs: areal M_α(q1) = (1/2π) ∫_{q0}^{q1} q^(α+1) C dq with m0 = M0,
  m2 = M2/2, m4 = 3 M4/8; profile m_α = (1/π) ∫_{q0}^{q1} q^α C1D dq;
  by mpmath.quad with the knee as a breakpoint, 50 digits; for fig2 also
  docs/model.md's truncated closed forms, which must agree.

The nodes are the doubles written to the files; the function is evaluated
at them exactly.

requirements: mpmath==1.3.0
"""
import os

import mpmath as mp

assert mp.__version__ == "1.3.0", mp.__version__
mp.mp.dps = 50

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "rough-surface", "tests", "data")
H = mp.mpf("0.8")
Z = mp.mpf("1e-8")
Q0, QR, QEND = 1e5, 1e6, 1e9
PER_DECADE = 8


def r(v):
    return repr(float(v))


def nodes():
    n = 4 * PER_DECADE
    return [float(mp.mpf(Q0) * mp.power(10, mp.mpf(i) / PER_DECADE)) for i in range(n + 1)]


def areal_knee(q):
    c0 = (2 * mp.pi) ** 2 * Z * mp.mpf(QR) ** (-2 * (1 + H))
    q = mp.mpf(q)
    return c0 if q <= QR else c0 * (q / QR) ** (-2 * (1 + H))


def profile_knee(q):
    c1 = mp.mpf("1e-30")
    q = mp.mpf(q)
    return c1 if q <= QR else c1 * (q / QR) ** (-(1 + 2 * H))


def fig2(q):
    return (2 * mp.pi) ** 2 * Z * mp.mpf(q) ** (-2 * (1 + H))


def moments(c, dim, q0, q1, knee):
    pts = [mp.mpf(q0)] + ([mp.mpf(knee)] if knee and q0 < knee < q1 else []) + [mp.mpf(q1)]
    if dim == "areal":
        m = [mp.quad(lambda q: q ** (a + 1) * c(q), pts) / (2 * mp.pi) for a in (0, 2, 4)]
        return [m[0], m[1] / 2, 3 * m[2] / 8]
    return [mp.quad(lambda q: q ** a * c(q), pts) / mp.pi for a in (0, 2, 4)]


def zetas(zmax):
    zs = [mp.power(zmax, mp.mpf(i) / 30) for i in range(31)]
    return [float(z) for z in zs]


def main():
    q = nodes()
    path = lambda n: os.path.join(OUT, n)
    with open(path("psd_knee.txt"), "w") as f:
        f.write("# q (1/m)  C (m^4): isotropic PSD, a power law H = 0.8 with a roll-off below 1e6 1/m\n")
        for qi in q:
            f.write(f"{r(qi)} {r(areal_knee(qi))}\n")
    with open(path("psd_knee_ce.txt"), "w") as f:
        f.write("# Power spectrum\n# ==============\n# IF YOU USE THIS DATA IN A PUBLICATION, PLEASE CITE XXX.\n\n")
        f.write("# Topography: knee\n# ==============\n# Creator: scripts/psd_reference.py\n\n")
        f.write("# 1D PSD along x\n# --------------\n# Columns: Wavevector (1/m), PSD (m³)\n")
        for qi in q:
            f.write(f"{r(qi)} 1.0\n")
        f.write("\n# q/π × 2D PSD\n# ------------\n# Columns: Wavevector (1/m), PSD (m³)\n")
        for qi in q:
            f.write(f"{r(qi)} {r(mp.mpf(qi) * areal_knee(qi) / mp.pi)}\n")
        f.write("\n")
    with open(path("psd_profile_ce.txt"), "w") as f:
        f.write("# Power spectrum\n# ==============\n\n# 1D PSD along x\n# --------------\n")
        f.write("# Columns: Wavevector (µm⁻¹), PSD (µm³)\n")
        for qi in q:
            f.write(f"{r(mp.mpf(qi) * mp.mpf('1e-6'))} {r(profile_knee(qi) * mp.mpf('1e18'))}\n")
    fig2_q = [1e5, 1e6, 1e7, 1e8, 1e9]
    with open(path("psd_fig2.txt"), "w") as f:
        f.write("# q C: fig2's spectrum in SurfaceTopography's convention, (2π)² Z q^(−3.6), Z = 1e-8\n")
        for qi in fig2_q:
            f.write(f"{r(qi)} {r(fig2(qi))}\n")

    with open(path("psd_reference.txt"), "w") as out:
        out.write("# Profile moments of the PSD tables in this folder, by scripts/psd_reference.py\n")
        out.write(f"# (mpmath {mp.__version__}, {mp.mp.dps} digits): zeta m0 m2 m4, SI.\n")
        for name, c, dim, nodes_used in [
            ("psd_knee.txt", areal_knee, "areal", q),
            ("psd_knee_ce.txt", areal_knee, "areal", q),
            ("psd_profile_ce.txt", profile_knee, "profile", q),
            ("psd_fig2.txt", fig2, "areal", fig2_q),
        ]:
            # The table's own nodes: what the reader sees.
            q0, qend = nodes_used[0], nodes_used[-1]
            out.write(f"table {name} {dim}\n")
            for z in zetas(qend / q0):
                q1 = min(z * q0, qend)
                m = moments(c, dim, q0, q1, QR if c is not fig2 else None)
                if c is fig2:
                    # docs/model.md's truncated moments must agree.
                    zz = mp.mpf(q1) / q0
                    g = lambda e: mp.expm1(e * mp.log(zz)) / e
                    closed = [mp.pi * Z / H * mp.mpf(q0) ** (-2 * H) * -mp.expm1(-2 * H * mp.log(zz)),
                              mp.pi * Z * mp.mpf(q0) ** (2 - 2 * H) * g(2 - 2 * H),
                              3 * mp.pi / 4 * Z * mp.mpf(q0) ** (4 - 2 * H) * g(4 - 2 * H)]
                    for a, b in zip(m, closed):
                        assert a == b or abs(a - b) <= mp.mpf("1e-40") * abs(b), (a, b)
                out.write(f"{r(z)} {r(m[0])} {r(m[1])} {r(m[2])}\n")
            out.write("end\n")


if __name__ == "__main__":
    main()
