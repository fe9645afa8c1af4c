#!/usr/bin/env python3
"""High-precision reference data for the asymptotic moments (the paper's eq. 10).

Run from the repository root:

    python3 scripts/gen_asymptotic.py

It rewrites, deterministically, crates/rough-study/data/params_asymptotic.csv:
the columns of params.csv (spectrum, hardness, indices, slopes at the indices)
with the moments of eq. 10 (docs/model.md, "Asymptotic"):

    m0 = (pi Z/H) q0^(-2H)
    m2 = pi Z q0^(2-2H) zeta^(2-2H)/(2-2H)
    m4 = (3 pi/4) Z q0^(4-2H) zeta^(4-2H)/(4-2H)

H = 1 is not in the grid (m2 is infinite there; the product refuses it).
Formatting, the adaptive precision driver and the slopes are those of
scripts/gen_reference.py, imported from it.
"""

import random
import sys

import mpmath
from mpmath import mp, mpf

import gen_reference as ref

# h_rms of the paper's Z = 1e-8 m^0.4 at q0 = 1e5 1/m, H = 0.8 (docs/model.md)
H_RMS_PAPER = 19.816636488030044e-9


def params_row_asymptotic(h0_over_e, h_rms, zeta, hurst, r_star, q0):
    """All params_asymptotic.csv outputs at the current precision."""
    e_over_h0 = 1 / mpf(h0_over_e)
    h, z, H, R, q = mpf(h_rms), mpf(zeta), mpf(hurst), mpf(r_star), mpf(q0)
    pi = mpmath.pi
    Z = h * h * H * q ** (2 * H) / pi
    e2, e4 = 2 - 2 * H, 4 - 2 * H
    m0 = (pi * Z / H) * q ** (-2 * H)
    m2 = pi * Z * q ** e2 * z ** e2 / e2
    m4 = 3 * pi / 4 * Z * q ** e4 * z ** e4 / e4
    r_s = mpf(3) / 8 * mpmath.sqrt(pi / m4)
    lambda1 = 2 * pi / (z * q)
    h_act = mpmath.sqrt(m0)
    slope = mpmath.sqrt(2 * m2)
    curv = mpmath.sqrt(8 * m4 / 3)
    r_p_factor = mpf(6) / 5   # R_p = 1.2 R_s
    hr = mpf(1) if R == 0 else mpmath.sqrt(1 + R / (r_p_factor * r_s))
    psi_p = e_over_h0 * mpmath.sqrt(m2 / 2)
    psi_star = psi_p / hr
    psi_gw = e_over_h0 * mpmath.sqrt(h_act / r_s)
    # eq. 13 uses these same moments whatever the convention
    asym = None if R == 0 else psi_p * mpmath.sqrt(r_p_factor * r_s / R)
    out = [Z, m0, m2, m4, r_s, lambda1, h_act, slope, curv, hr,
           psi_gw, psi_p, psi_star, asym]
    out += list(ref.exact_slopes(psi_p)) + list(ref.closed_slopes(psi_p))
    out += list(ref.exact_slopes(psi_star)) + list(ref.closed_slopes(psi_star))
    return out


def check():
    """docs/model.md's check value and the paper's h_rms."""
    with mp.workdps(60):
        pi = mpmath.pi
        h = mpmath.sqrt(pi * mpf("1e-8") * mpf("1e5") ** mpf("-1.6") / mpf("0.8"))
        # docs/model.md's 19.816636488030044 nm is the double of an f64 evaluation;
        # the correctly rounded value is 19.816636488030055 nm (2.5 ulp away)
        assert abs(h / mpf(H_RMS_PAPER) - 1) < mpf(10) ** -15, h
        psi_p = params_row_asymptotic(1e-2, H_RMS_PAPER, 128.0, 0.8, 0.0, 1e5)[11]
        assert abs(psi_p / mpf("0.522964172217328") - 1) < mpf(10) ** -14, psi_p
        # truncated/asymptotic = 1 - zeta^(-e) for each moment (e = 2H, 2-2H, 4-2H)
        zeta, H = mpf(1e3), mpf(0.8)
        t = ref.params_row(1e-2, 2e-8, 1e3, 0.8, 1e-3, 1e5)
        a = params_row_asymptotic(1e-2, 2e-8, 1e3, 0.8, 1e-3, 1e5)
        for k, e in ((1, 2 * H), (2, 2 - 2 * H), (3, 4 - 2 * H)):
            assert abs(t[k] / a[k] - (1 - zeta ** -e)) < mpf(10) ** -50, (k, t[k], a[k])


def grid():
    rows = []
    q0, hurst, rst, npts = 1e5, 0.8, 1e-3, 30
    h = H_RMS_PAPER
    # fig1: H0/E 1e-4 .. 1e-1, zeta 128, no size effect
    for i in range(npts):
        rows.append((10.0 ** (-4 + 3 * i / (npts - 1)), h, 128.0, hurst, 0.0, q0))
    # fig2 / fig3: zeta 1 .. 1e4, H0/E 1e-2; fig3 with R* = 1 mm
    for r in (0.0, rst):
        for i in range(npts):
            rows.append((1e-2, h, 10.0 ** (4 * i / (npts - 1)), hurst, r, q0))
        rows.append((1e-2, h, 128.0, hurst, r, q0))
    # fig4: zeta 1 .. 1e6, h_rms 600 nm, H0/E 1e-3, R* = 1 mm
    for i in range(npts):
        rows.append((1e-3, 6e-7, 10.0 ** (6 * i / (npts - 1)), hurst, rst, q0))
    rows.append((1e-3, 6e-7, 1.7e4, hurst, rst, q0))

    rng = random.Random(20241083)
    zeta_special = [1.0, 1.0 + 2.0 ** -40, 2.0, 1e10]
    hurst_special = [0.5, 0.01, 0.99, 1.0 - 2.0 ** -30]
    rows += ref.random_params(rng, 300, zeta_special, hurst_special, 0.999, 0.0, 0.999,
                              params_row_asymptotic)
    return rows


def main():
    mp.dps = ref.BASE_DPS
    check()
    print("self-checks passed", file=sys.stderr)
    ref.INNER_MAX_DPS = 0
    ad = ref.Adaptive()
    rows = []
    for inp in grid():
        vals = ad(lambda inp=inp: params_row_asymptotic(*inp))
        rows.append([ref.fmt_in(v) for v in inp] + [ref.fmt_out(v) for v in vals])
    hdr = [line.replace(ref.SCRIPT, "scripts/gen_asymptotic.py") for line in ref.header_common(ad)] + [
        "# the columns of params.csv (see scripts/gen_reference.py) with the asymptotic",
        "#   moments of eq. 10 (docs/model.md): m0 = (pi z/hurst) q0^(-2hurst),",
        "#   m2 = pi z q0^e2 zeta^e2/e2, m4 = (3pi/4) z q0^e4 zeta^e4/e4, e_n = n - 2 hurst;",
        "#   r_s = (3/8) sqrt(pi/m4) (finite at zeta = 1); hardness_ratio = sqrt(1 + r_star/(1.2 r_s));",
        "#   psi_gw = sqrt(sqrt(m0)/r_s)/h0_over_e; psi_p = sqrt(m2/2)/h0_over_e;",
        "#   psi_star = psi_p/hardness_ratio; psi_star_asym = psi_p sqrt(1.2 r_s/r_star) (eq. 13),",
        "#   empty when r_star = 0; slopes as in params.csv at psi_p and psi_star.",
    ]
    cols = ("h0_over_e,h_rms,zeta,hurst,r_star,q0,z,m0,m2,m4,r_s,lambda1,h_rms_actual,"
            "rms_slope,rms_curvature,hardness_ratio,psi_gw,psi_p,psi_star,psi_star_asym,"
            "exact_el_p,exact_pl_p,exact_tot_p,closed_el_p,closed_pl_p,closed_tot_p,"
            "exact_el_star,exact_pl_star,exact_tot_star,closed_el_star,closed_pl_star,"
            "closed_tot_star")
    ref.write_file("params_asymptotic.csv", hdr, cols, rows)


if __name__ == "__main__":
    main()
