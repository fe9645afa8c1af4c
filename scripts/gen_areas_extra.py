#!/usr/bin/env python3
"""Extra mpmath reference points for the finite-load areas (hard corners).

Writes crates/rough-study/data/areas_extra.csv (same columns as areas.csv):
switch points of the Rust forms (exact: psi^2 = 1/pi; closed: x = 1/psi = 0.8;
interval masses: 2 k rho / psi^2 = 1), loads next to 0 and 1, psi at the
underflow edges, and a seeded log-uniform sample.

Every value comes from docs/model.md's definitions evaluated verbatim (differences
and all), not from the cancellation-free forms of the Rust code:
  exact:  A_el = sum_n [M(rho+2n) - M(-rho+2n)] (images, psi < 0.6) or the sine
          series (psi >= 0.6); A_pl = rho - int_0^1 p P dp; A_tot = A_el + A_pl
  closed: a, b from docs/model.md's P0 ratios (normalized: D' = -expm1(-2x^2), ...),
          A_tot = ((1+a)/2) erf(rho/r) + (b/2) erf((rho-2)/r) + (1-a+b)/2,
          A_el = M(rho) - a M(-rho) - b M(2-rho), A_pl = A_tot - A_el
with M(c) the mass of N(c, psi^2) on [0, 1], r = sqrt(2) psi.
Precision: each row at D and D+40 digits, D from 60 upward in steps of 80,
until all six outputs agree to 28 significant digits and each is resolved
(|value| > 10^(35-D)); a value still below 1e-340 at D >= 420 is printed as 0.
Usage: python3 scripts/gen_areas_extra.py   (from the repository root)
"""
import random
import struct

import mpmath
from mpmath import mp, mpf

OUT = "crates/rough-study/data/areas_extra.csv"


BIG = mpf(10) ** 6   # erf(z) = +-1 and e^(-z^2/2) = 0 far beyond any working precision


def erf(z):
    if abs(z) > BIG:
        return mpf(1) if z > 0 else mpf(-1)
    return mpmath.erf(z)


def phi(u):
    if abs(u) > BIG:
        return mpf(0)
    return mpmath.exp(-u * u / 2) / mpmath.sqrt(2 * mpmath.pi)


def M(c, s):
    r = mpmath.sqrt(2) * s
    return (erf((1 - c) / r) + erf(c / r)) / 2


def first_moment(c, s):  # int_0^1 p N(c, s^2)(p) dp
    return c * M(c, s) + s * (phi(c / s) - phi((1 - c) / s))


def exact(psi, rho):
    if rho == 1:
        return mpf(0), mpf(1), mpf(1)
    s = psi
    if psi < mpf("0.6"):
        L = mpmath.sqrt(2 * mpmath.log(10) * (mp.dps + 40))
        N = int(mpmath.ceil((s * L + 2) / 2)) + 2
        el = mpf(0)
        mom = mpf(0)
        for n in range(-N, N + 1):
            el += M(rho + 2 * n, s) - M(-rho + 2 * n, s)
            mom += first_moment(rho + 2 * n, s) - first_moment(-rho + 2 * n, s)
        pl = rho - mom
    else:
        v = psi * psi
        pi = mpmath.pi
        el = mpf(0)
        acc = mpf(0)
        k = 1
        tiny = mpf(10) ** (-mp.dps - 60)
        while True:
            E = mpmath.exp(-k * k * pi * pi * v / 2)
            if k > 3 and E < tiny * rho:
                break
            sn = mpmath.sin(k * pi * rho)
            if k % 2 == 1:
                el += 4 * sn * E / (k * pi)
            acc += (-1) ** (k + 1) * sn * E / (k * pi)
            k += 1
        pl = rho - 2 * acc
    return el, pl, el + pl


def closed(psi, rho):
    x2 = 1 / (psi * psi)
    d = -mpmath.expm1(-2 * x2)
    a = -mpmath.expm1(-2 * (1 - rho) * x2) / d
    b = -mpmath.expm1(-2 * rho * x2) / d
    r = mpmath.sqrt(2) * psi
    tot = (1 + a) / 2 * erf(rho / r) + b / 2 * erf((rho - 2) / r) + (1 - a + b) / 2
    el = M(rho, psi) - a * M(-rho, psi) - b * M(2 - rho, psi)
    return el, tot - el, tot


def row(psi_f, rho_f):
    D = 60
    while True:
        vals = []
        for dps in (D, D + 40):
            mp.dps = dps
            psi, rho = mpf(psi_f), mpf(rho_f)
            if psi_f == float("inf"):
                vals.append([mpf(0), rho, rho] * 2)
                continue
            vals.append(list(exact(psi, rho)) + list(closed(psi, rho)))
        lo, hi = vals
        ok = True
        out = []
        for u, v in zip(lo, hi):
            if abs(v) < mpf(10) ** (35 - D):
                if D >= 420 and abs(v) < mpf("1e-340"):
                    out.append(mpf(0))
                    continue
                ok = False
                break
            if abs(u - v) > abs(v) * mpf(10) ** -28:
                ok = False
                break
            out.append(v)
        if ok:
            return out, D + 40
        D += 80


def fmt_in(v):
    return repr(float(v))


def fmt_out(v):
    if v == 0 or abs(v) < mpf("1e-320"):
        return "0"
    return mpmath.nstr(v, 25, strip_zeros=False, min_fixed=-4, max_fixed=1)


def points():
    pts = []
    rhos = [5e-324, 1e-300, 1e-100, 1e-12, 1e-6, 1e-3, 0.1, 0.3, 0.5, 0.7,
            0.9, 0.999, 1 - 1e-9, 1 - 2.0**-52, 1.0]
    # exact switch psi^2 = 1/pi and closed switch x = 0.8, both sides
    s_exact = float(1 / mpmath.sqrt(mpmath.pi))
    for psi in (s_exact * (1 - 1e-9), s_exact * (1 + 1e-9), 1.25 * (1 - 1e-9), 1.25 * (1 + 1e-9)):
        for rho in rhos:
            pts.append((psi, rho))
    # interval mass switch: 2 k rho/psi^2 = 1 (k = 1, 2, 3)
    for psi in (0.003, 0.05, 0.2, 0.5, 1.0, 1.3):
        for k in (1, 2, 3):
            r0 = psi * psi / (2 * k)
            for f in (1 - 1e-7, 1 + 1e-7):
                if r0 * f < 1:
                    pts.append((psi, r0 * f))
                    pts.append((psi, 1 - r0 * f))
    # underflow edges and extremes
    for psi in (1e-300, 1e-150, 1e-20, 0.004, 0.0125, 0.02, 0.037, 11.9, 12.05,
                17.0, 25.0, 1e10, 1e200, float("inf")):
        for rho in (5e-324, 1e-200, 1e-9, 0.25, 0.5, 0.75, 1 - 1e-6, 1 - 2.0**-53):
            pts.append((psi, rho))
    # small psi, load near 1 (elastic area from the reflection)
    for psi in (0.001, 0.01, 0.1):
        for rho in (1 - 1e-4, 1 - 1e-3, 1 - psi, 1 - 3 * psi, 1 - 10 * psi):
            if 0 < rho < 1:
                pts.append((psi, rho))
    rng = random.Random(20240583)
    for _ in range(240):
        psi = 10 ** rng.uniform(-3, 2.5)
        u = rng.random()
        if u < 0.4:
            rho = 10 ** rng.uniform(-15, 0)
        elif u < 0.7:
            rho = 1 - 10 ** rng.uniform(-15, -0.31)
        else:
            rho = rng.uniform(0, 1) or 0.5
        pts.append((psi, min(rho, 1.0)))
    return pts


def main():
    lines = [
        "# generator: scripts/gen_areas_extra.py (python3 scripts/gen_areas_extra.py from the repository root)",
        f"# mpmath {mpmath.__version__}; model: docs/model.md definitions evaluated verbatim (see the script's doc)",
        "# precision: each row at D and D+40 digits, D = 60, 140, ... until all outputs agree to 28",
        "#   significant digits and are resolved (|v| > 10^(35-D)); printed from the D+40 run;",
        "#   a value below 1e-340 at D >= 420 is printed as 0; 'inf' = +infinity.",
        "# inputs: IEEE doubles printed with Python repr; outputs: 25 significant digits.",
        "# columns as in areas.csv: psi = sqrt(V)/H, rho = pbar/H, areas A/A0.",
    ]
    body = []
    maxd = 0
    pts = points()
    for i, (psi, rho) in enumerate(pts):
        vals, d = row(psi, rho)
        if i % 50 == 0:
            print(f"{i}/{len(pts)}", flush=True)
        maxd = max(maxd, d)
        body.append(",".join([fmt_in(psi), fmt_in(rho)] + [fmt_out(v) for v in vals]))
    lines.append(f"#   highest working precision reached in this file: {maxd} digits")
    lines.append("psi,rho,exact_elastic,exact_plastic,exact_total,closed_elastic,closed_plastic,closed_total")
    with open(OUT, "w") as f:
        f.write("\n".join(lines + body) + "\n")
    print(f"{OUT}: {len(body)} rows, up to {maxd} digits")


if __name__ == "__main__":
    main()
