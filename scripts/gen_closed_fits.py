#!/usr/bin/env python3
"""Polynomial fits behind the closed-form slopes (rough-model's slopes/closed.rs).

Run from the repository root:

    python3 scripts/gen_closed_fits.py

It rewrites, deterministically, crates/rough-model/src/slopes/closed_fits.rs.
Only python3 and mpmath (1.3.0) are needed.

The closed form of docs/model.md (x = 1/psi, u = x^2, z = x/sqrt2):

    S_tot = sqrt(2/pi) x + u/(e^{2u} - 1) + u erfc(sqrt2 x)/(1 - e^{-2u})
    S_pl  = sqrt(2/pi) x e^{-u/2} + u erfc(x/sqrt2) coth u
    S_el  = S_tot - S_pl

Both slopes share the even part u coth u, so S_el is odd in x; the fits are

    P(u)    = u coth u                     on u in [0, 1]     (S_pl = P + x u R_pl)
    R_pl(u) = (S_pl - u coth u)/(x u)      on u in [0, 1]
    R_el(u) = S_el/(x u^2)                 on u in [0, 1] and [1, 9/4]
    K(v)    = sqrt2 t erfcx(t), t = 1/v    on v in [1/32, 23/16], 23 pieces

each a polynomial in d = (argument - centre), with the centres chosen so that
the subtraction is exact in binary floating point (Sterbenz). The u-fits are
Chebyshev interpolants of degree 15 (the functions have poles at u = +-i pi,
from 1/(1 - e^{-2u})); K's pieces have degree 9 (erfcx is entire, but 1/v has
an essential singularity at v = 0, hence the short pieces). Coefficients are
rounded to the nearest double and printed as the shortest decimal that reads
back to it. The script measures each rounded fit against the function on a
dense grid (exact arithmetic, 60 digits) and fails if any is off by more than
1.5e-16 relative; the largest errors are written into the file's header.
"""

import os
import sys

import mpmath
from mpmath import mp, mpf

SCRIPT = "scripts/gen_closed_fits.py"
OUT = os.path.join("crates", "rough-model", "src", "slopes", "closed_fits.rs")
DPS = 60
U_DEGREE = 15
K_DEGREE = 9
K_PIECES = 23          # v from 1/32 to 23/16: t = x/sqrt2 down to 1/sqrt2 (x = 1)
GRID = 600             # check points per fit
MAX_FIT_ERROR = mpf("1.5e-16")

mp.dps = DPS


def sqrt_2_over_pi():
    return mpmath.sqrt(2 / mpmath.pi)


def closed_slopes(x):
    """(S_el, S_pl, S_tot) at x = 1/psi, at the working precision plus the
    digits S_el's difference loses (it falls like x^5)."""
    with mp.workdps(DPS + 20 + int(max(0, -5 * mpmath.log10(x)))):
        u = x * x
        em = -mpmath.expm1(-2 * u)
        e2 = mpmath.exp(-2 * u)
        tot = (sqrt_2_over_pi() * x + u * e2 / em
               + u * mpmath.erfc(mpmath.sqrt(2) * x) / em)
        coth = 1 + 2 * e2 / em
        pl = (sqrt_2_over_pi() * x * mpmath.exp(-u / 2)
              + u * mpmath.erfc(x / mpmath.sqrt(2)) * coth)
        el = tot - pl
    return +el, +pl, +tot


def p_even(u):
    return u * mpmath.coth(u)


def r_pl(u):
    x = mpmath.sqrt(u)
    with mp.workdps(DPS + 30):
        return (closed_slopes(x)[1] - p_even(u)) / (x * u)


def r_el(u):
    x = mpmath.sqrt(u)
    return closed_slopes(x)[0] / (x * u * u)


def k_of_v(v):
    t = 1 / v
    return mpmath.sqrt(2) * t * mpmath.exp(t * t) * mpmath.erfc(t)


def chebyshev_coefficients(f, a, b, n):
    """Coefficients of the degree-n interpolant of f at the Chebyshev points
    of the first kind on [a, b]."""
    m = n + 1
    nodes = [mpmath.cos(mpmath.pi * (k + mpf(1) / 2) / m) for k in range(m)]
    values = [f((b - a) / 2 * s + (a + b) / 2) for s in nodes]
    c = []
    for j in range(m):
        acc = sum(values[k] * mpmath.cos(mpmath.pi * j * (k + mpf(1) / 2) / m)
                  for k in range(m))
        c.append(2 * acc / m)
    c[0] /= 2
    return c


def to_monomial(c, a, b, centre):
    """sum c_j T_j(s), s = (2v - a - b)/(b - a), as coefficients in d = v - centre."""
    alpha = 2 / (b - a)
    beta = (2 * centre - a - b) / (b - a)
    out = [mpf(0)] * len(c)

    def add(poly, k):
        for i, p in enumerate(poly):
            out[i] += k * p

    t_prev, t_cur = [mpf(1)], [beta, alpha]
    add(t_prev, c[0])
    if len(c) > 1:
        add(t_cur, c[1])
    for j in range(2, len(c)):
        t_next = [mpf(0)] * (j + 1)
        for i, p in enumerate(t_cur):
            t_next[i] += 2 * beta * p
            t_next[i + 1] += 2 * alpha * p
        for i, p in enumerate(t_prev):
            t_next[i] -= p
        add(t_next, c[j])
        t_prev, t_cur = t_cur, t_next
    return out


def horner(coeffs, d):
    acc = mpf(0)
    for c in reversed(coeffs):
        acc = acc * d + c
    return acc


def fit(f, a, b, centre, degree):
    """Rounded monomial coefficients and their max relative error on [a, b]."""
    a, b, centre = mpf(a), mpf(b), mpf(centre)
    mono = to_monomial(chebyshev_coefficients(f, a, b, degree), a, b, centre)
    doubles = [float(m) for m in mono]
    worst = mpf(0)
    for k in range(GRID + 1):
        v = a + (b - a) * k / GRID
        if v == 0:
            v = b * mpf("1e-9")
        want = f(v)
        got = horner([mpf(d) for d in doubles], v - centre)
        worst = max(worst, abs(got / want - 1))
    if worst > MAX_FIT_ERROR:
        sys.exit(f"fit on [{a}, {b}] is off by {mpmath.nstr(worst, 3)}")
    return doubles, worst


def rust_array(name, doc, values):
    lines = [f"/// {line}" for line in doc]
    lines.append(f"pub(super) const {name}: [f64; {len(values)}] = [")
    lines += [f"    {v!r}," for v in values]
    lines.append("];")
    return "\n".join(lines)


def k_piece(i):
    if i == 0:
        return mpf(1) / 32, mpf(1) / 16, mpf(3) / 64
    return mpf(i) / 16, mpf(i + 1) / 16, mpf(2 * i + 1) / 32


def main():
    u_fits = [
        ("P_EVEN", "u coth u on u in [0, 1], in d = u - 1/2", p_even, 0, 1, mpf(1) / 2),
        ("R_PL", "(S_pl - u coth u)/(x u) on u in [0, 1], in d = u - 1/2", r_pl, 0, 1,
         mpf(1) / 2),
        ("R_EL_LOW", "S_el/(x u^2) on u in [0, 1], in d = u - 1/2", r_el, 0, 1, mpf(1) / 2),
        ("R_EL_MID", "S_el/(x u^2) on u in [1, 9/4], in d = u - 13/8", r_el, 1, mpf(9) / 4,
         mpf(13) / 8),
    ]
    blocks, errors = [], []
    for name, doc, f, a, b, centre in u_fits:
        coeffs, err = fit(f, a, b, centre, U_DEGREE)
        errors.append((name, err))
        blocks.append(rust_array(
            name, [f"{doc}: coefficients of d^0 … d^{U_DEGREE}",
                   f"(max relative error of the rounded fit {mpmath.nstr(err, 2)})."], coeffs))
    pieces, k_worst = [], mpf(0)
    for i in range(K_PIECES):
        a, b, centre = k_piece(i)
        coeffs, err = fit(k_of_v, a, b, centre, K_DEGREE)
        k_worst = max(k_worst, err)
        body = ", ".join(repr(c) for c in coeffs)
        pieces.append(f"    // v in [{a}, {b}]\n    ({float(centre)!r}, [{body}]),")
    errors.append(("K", k_worst))
    k_doc = [
        "K(v) = √2 t erfcx(t), t = 1/v: piece i covers v in [i/16, (i+1)/16]",
        "(piece 0: [1/32, 1/16]) as (centre, coefficients of d^0 … d^9 in",
        f"d = v − centre); max relative error of the rounded fits {mpmath.nstr(k_worst, 2)}.",
    ]
    k_block = "\n".join(
        [f"/// {line}" for line in k_doc]
        + ["#[rustfmt::skip]"]
        + [f"pub(super) const K_PIECES: [(f64, [f64; {K_DEGREE + 1}]); {K_PIECES}] = ["]
        + pieces + ["];"])
    header = [
        f"//! Generated by {SCRIPT} (mpmath {mpmath.__version__}); do not edit.",
        "//!",
        "//! Polynomial fits of the closed-form slopes' smooth parts (see the",
        "//! script's doc and `closed.rs`). Largest relative error of each rounded",
        "//! fit on a dense grid, in exact arithmetic:",
    ]
    header += [f"//! {name} {mpmath.nstr(err, 2)}" for name, err in errors]
    text = "\n".join(header) + "\n\n" + "\n\n".join(blocks + [k_block]) + "\n"
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    with open(OUT, "w") as fh:
        fh.write(text)
    print(f"wrote {OUT}", file=sys.stderr)


if __name__ == "__main__":
    main()
