#!/usr/bin/env python3
"""High-precision reference data for roughtui's `rough-model` crate.

Run from the repository root:

    python3 scripts/gen_reference.py

It rewrites, deterministically, every file in crates/rough-study/data/:

    slopes.csv         initial slopes of the exact (theta) and closed-form models
    areas.csv          finite-load areas A/A0 of both models
    params.csv         spectrum moments, indices and the slopes at the indices
    closed_series.txt  Taylor coefficients of the closed-form elastic slope

Every formula follows docs/model.md (the project's contract). Only
python3 and mpmath are needed; sympy, if installed, is used for one extra
cross-check of the series coefficients.

Conventions
-----------
* Inputs are IEEE doubles produced as Python floats and converted with
  mpf(float) (exact); they are printed with repr(float) (shortest round trip).
* Outputs are printed with 25 significant digits, `inf` for +infinity, `0` for
  an exact zero or for a magnitude below 1e-320; `nan` is never printed.
* Precision: every row is computed at D and D+40 decimal digits, D starting at
  50 (plus an estimate of the digits lost to cancellation where there is any),
  and D is raised by 40 until every output of the row agrees to 25 significant
  digits; the printed values come from the D+40 evaluation.
* Decimal constants of the model (1.2 in R_p = 1.2 R_s, 3/8, 3pi/4) are exact
  rationals, never floats.
"""

import math
import os
import random
import sys
from fractions import Fraction

import mpmath
from mpmath import mp, mpf

SCRIPT = "scripts/gen_reference.py"
OUT_DIR = os.path.join("crates", "rough-study", "data")

BASE_DPS = 50          # starting working precision, decimal digits
STEP_DPS = 40          # the second evaluation is at D + STEP_DPS; D rises by STEP_DPS
AGREE_DIGITS = 25      # significant digits two evaluations must share
MAX_DPS = 6000         # safety stop for the adaptive loop
PRINT_DIGITS = 25
ZERO_BELOW = "1e-320"  # magnitudes below this print as 0
NEGLIGIBLE = "1e-330"  # two evaluations both below this agree (they both print 0)

INF = mpmath.inf
INNER_MAX_DPS = 0  # highest precision used inside a row (closed-form S_el difference)


# ---------------------------------------------------------------------------
# formatting and the adaptive-precision driver
# ---------------------------------------------------------------------------

def fmt_in(v):
    assert isinstance(v, float) and math.isfinite(v), v
    return repr(v)


def fmt_out(v):
    if v is None:
        return ""
    if mpmath.isnan(v):
        raise ValueError("nan reached the output")
    if mpmath.isinf(v):
        if v > 0:
            return "inf"
        raise ValueError("-inf reached the output")
    if v == 0 or abs(v) < mpf(ZERO_BELOW):
        return "0"
    return mpmath.nstr(v, PRINT_DIGITS, min_fixed=-4, max_fixed=16)


def _agree(a, b):
    if a is None or b is None:
        return a is None and b is None
    if mpmath.isnan(a) or mpmath.isnan(b):
        return False
    if mpmath.isinf(a) or mpmath.isinf(b):
        return a == b
    if a == b:
        return True
    tiny = mpf(NEGLIGIBLE)
    if abs(a) < tiny and abs(b) < tiny:
        return True
    return abs(a - b) <= mpf(10) ** (-(AGREE_DIGITS + 1)) * max(abs(a), abs(b))


class Adaptive:
    """Evaluate f() at D and D+STEP digits, raising D until all outputs agree."""

    def __init__(self):
        self.max_dps = 0

    def __call__(self, f, dps0=BASE_DPS):
        d = max(int(dps0), BASE_DPS)
        while d <= MAX_DPS:
            with mp.workdps(d):
                lo = f()
            with mp.workdps(d + STEP_DPS):
                hi = f()
            if all(_agree(a, b) for a, b in zip(lo, hi)):
                self.max_dps = max(self.max_dps, d + STEP_DPS)
                return hi
            d += STEP_DPS
        raise RuntimeError("adaptive precision did not converge")


# ---------------------------------------------------------------------------
# special functions valid for any magnitude (mpmath's erfc overflows ~1e155)
# ---------------------------------------------------------------------------

ERFC_ASYMPTOTIC_FROM = 10 ** 6


def erfc_(z):
    if z < 0:
        return 2 - erfc_(-z)
    if z > ERFC_ASYMPTOTIC_FROM:
        # erfc z = e^{-z^2}/(z sqrt(pi)) * sum_n (-1)^n (2n-1)!!/(2z^2)^n;
        # for z > 1e6 the terms fall by > 1e12 each, far from the optimal stop.
        z2 = z * z
        eps = mpf(2) ** (-mp.prec - 10)
        s = mpf(1)
        t = mpf(1)
        n = 1
        while True:
            t = -t * (2 * n - 1) / (2 * z2)
            if abs(t) < eps:
                break
            s += t
            n += 1
        return mpmath.exp(-z2) / (z * mpmath.sqrt(mpmath.pi)) * s
    return mpmath.erfc(z)


def erf_(z):
    if abs(z) > ERFC_ASYMPTOTIC_FROM:
        return mpmath.sign(z) * (1 - erfc_(abs(z)))
    return mpmath.erf(z)


def K():
    """sqrt(2/pi) at the current precision."""
    return mpmath.sqrt(2 / mpmath.pi)


def _eps():
    return mpf(2) ** (-mp.prec - 8)


# ---------------------------------------------------------------------------
# exact two-barrier slopes (docs/model.md "initial slopes"), x = 1/psi
# ---------------------------------------------------------------------------
# Large-x forms (x^2 >= switch):   S_tot = K x theta3(0, e^{-2x^2})
#                                  S_pl  = K x theta2(0, e^{-2x^2})
#                                  S_el  = K x theta4(0, e^{-x^2/2})  (= tot - pl, no cancellation)
# Small-x forms (Poisson summed):  S_tot = theta3(0, e^{-pi^2/(2x^2)})
#                                  S_pl  = theta4(0, e^{-pi^2/(2x^2)})
#                                  S_el  = 4 sum_{k odd} e^{-pi^2 k^2/(2x^2)}
# Every form is a sum whose terms fall monotonically; both forms are exact,
# the switch only picks the fast one.  All exponents are formed from psi^2
# (exact for a double psi at >= 107 bits) rather than from a rounded x.

def _series(first, k, step, term, coef, skip_first_check=False):
    """first + sum of coef(k) * term(k) over k, k + step, ... until a term
    falls below eps times the sum (the terms fall monotonically); with
    skip_first_check the first term is always taken (the sum starts at 0)."""
    s, eps, first_term = mpf(first), _eps(), True
    while True:
        t = term(k)
        if not (skip_first_check and first_term) and t < eps * s:
            break
        s += coef(k) * t
        k += step
        first_term = False
    return s


def _even_plus(k):
    return 2 if k % 2 == 0 else -2


def exact_tot_large(psi):
    x2 = 1 / (psi * psi)
    s = _series(1, 1, 1, lambda n: mpmath.exp(-2 * n * n * x2), lambda n: 2)
    return K() / psi * s


def exact_tot_small(psi):
    a = mpmath.pi ** 2 * psi * psi / 2
    return _series(1, 1, 1, lambda k: mpmath.exp(-a * k * k), lambda k: 2)


def exact_pl_large(psi):
    x2 = 1 / (psi * psi)
    s = _series(0, 0, 1, lambda n: mpmath.exp(-(2 * n + 1) ** 2 * x2 / 2), lambda n: 2,
                skip_first_check=True)
    return K() / psi * s


def exact_pl_small(psi):
    a = mpmath.pi ** 2 * psi * psi / 2
    return _series(1, 1, 1, lambda k: mpmath.exp(-a * k * k), _even_plus)


def exact_el_large(psi):
    x2 = 1 / (psi * psi)
    s = _series(1, 1, 1, lambda n: mpmath.exp(-n * n * x2 / 2), _even_plus)
    return K() / psi * s


def exact_el_small(psi):
    a = mpmath.pi ** 2 * psi * psi / 2
    return _series(0, 1, 2, lambda k: mpmath.exp(-a * k * k), lambda k: 4,
                   skip_first_check=True)


def exact_slopes(psi):
    """(S_el, S_pl, S_tot) of the exact model at index psi (mpf, >= 0)."""
    if psi == 0:
        return INF, mpf(0), INF
    x2 = 1 / (psi * psi)
    if x2 >= mpmath.pi / 2:
        tot, pl = exact_tot_large(psi), exact_pl_large(psi)
    else:
        tot, pl = exact_tot_small(psi), exact_pl_small(psi)
    el = exact_el_large(psi) if x2 >= 2 * mpmath.pi else exact_el_small(psi)
    return el, pl, tot


# ---------------------------------------------------------------------------
# closed-form (three Gaussians) slopes, docs/model.md, x = 1/psi
# ---------------------------------------------------------------------------
#   S_tot = K x + x^2/(e^{2x^2}-1) + x^2 erfc(sqrt2 x)/(1-e^{-2x^2})
#   S_pl  = K x e^{-x^2/2} + x^2 erfc(x/sqrt2) coth(x^2)
# written without overflow: x^2/(e^{2x^2}-1) = x^2 e^{-2x^2}/(-expm1(-2x^2)),
# coth(y) = 1 + 2 e^{-2y}/(-expm1(-2y)).

def _closed_tot_pl(psi):
    x = 1 / psi
    x2 = x * x
    d = -mpmath.expm1(-2 * x2)
    e2 = mpmath.exp(-2 * x2)
    tot = K() * x + x2 * e2 / d + x2 * erfc_(mpmath.sqrt(2) * x) / d
    coth = 1 + 2 * e2 / d
    pl = K() * x * mpmath.exp(-x2 / 2) + x2 * erfc_(x / mpmath.sqrt(2)) * coth
    return tot, pl


def closed_slopes(psi):
    """(S_el, S_pl, S_tot) of the closed form; S_el = S_tot - S_pl with the
    digits that the difference loses (about 5 log10(psi)) added first."""
    if psi == 0:
        return INF, mpf(0), INF
    global INNER_MAX_DPS
    extra = 10
    if psi > 1:
        extra += int(5 * mpmath.log10(psi)) + 5
    INNER_MAX_DPS = max(INNER_MAX_DPS, mp.dps + extra)
    with mp.workdps(mp.dps + extra):
        tot, pl = _closed_tot_pl(psi)
        el = tot - pl
    return +el, +pl, +tot


def persson_slope(psi):
    if psi == 0:
        return INF
    return K() / psi


# ---------------------------------------------------------------------------
# finite-load areas, normalized: H = 1, V = psi^2, rho = pbar/H
# ---------------------------------------------------------------------------

def _mass(c, s):
    """Mass of N(c, s^2) on [0, 1]."""
    r = mpmath.sqrt(2) * s
    return (erf_((1 - c) / r) + erf_(c / r)) / 2


def _image_count(s):
    # Gaussian tails beyond (2N-2)/s standard deviations are negligible.
    L = mpmath.sqrt(2 * mpmath.log(10) * (mp.dps + 40))
    return int(mpmath.ceil((s * L + 2) / 2)) + 2


def exact_areas_images(psi, rho, n_images=None):
    """Method of images. A_el = int_0^1 P; A_pl = probability of absorption
    at p = 1, = sum_{m>=0} [erfc((2m+1-rho)/(sqrt2 s)) - erfc((2m+1+rho)/(sqrt2 s))]
    (time integral of the image fluxes; equals rho - int_0^1 p P dp)."""
    s = psi
    N = n_images if n_images is not None else _image_count(s)
    r = mpmath.sqrt(2) * s
    el = mpf(0)
    for n in range(-N, N + 1):
        el += _mass(rho + 2 * n, s) - _mass(-rho + 2 * n, s)
    pl = mpf(0)
    for m in range(0, N + 1):
        pl += erfc_((2 * m + 1 - rho) / r) - erfc_((2 * m + 1 + rho) / r)
    return el, pl, el + pl


def exact_pl_load_balance(psi, rho, n_images):
    """A_pl = rho - int_0^1 p P dp by images (docs/model.md's definition; check only)."""
    s = psi
    phi = lambda u: mpmath.exp(-u * u / 2) / mpmath.sqrt(2 * mpmath.pi)

    def first_moment(c):  # int_0^1 p N(c, s^2)(p) dp
        return c * _mass(c, s) + s * (phi(c / s) - phi((1 - c) / s))

    mom = mpf(0)
    for n in range(-n_images, n_images + 1):
        mom += first_moment(rho + 2 * n) - first_moment(-rho + 2 * n)
    return rho - mom


def exact_areas_sine(psi, rho):
    """Persson's sine series: P = 2 sum_k sin(k pi rho) sin(k pi p) e^{-k^2 pi^2 V/2}."""
    v = psi * psi
    pi = mpmath.pi
    el = mpf(0)
    acc = mpf(0)   # sum_k (-1)^{k+1} sin(k pi rho)/(k pi) E_k, A_pl = rho - 2 acc
    eps = _eps()
    k = 1
    while True:
        E = mpmath.exp(-k * k * pi * pi * v / 2)
        bound = 4 * E / (k * pi)
        if k > 3 and bound < eps * min(abs(el), rho) * mpf(10) ** -5:
            break
        sn = mpmath.sin(k * pi * rho)
        if k % 2 == 1:
            el += 4 * sn * E / (k * pi)
            acc += sn * E / (k * pi)
        else:
            acc -= sn * E / (k * pi)
        k += 1
    pl = rho - 2 * acc
    return el, pl, el + pl


IMAGES_BELOW_PSI = mpf("0.6")


def exact_areas(psi, rho):
    if rho == 1:
        return mpf(0), mpf(1), mpf(1)   # starts on the plastic barrier
    if psi < IMAGES_BELOW_PSI:
        return exact_areas_images(psi, rho)
    return exact_areas_sine(psi, rho)


def closed_abD(psi, rho):
    """a, b of the three-Gaussian solution in normalized form."""
    x2 = 1 / (psi * psi)
    d = -mpmath.expm1(-2 * x2)
    a = -mpmath.expm1(-2 * (1 - rho) * x2) / d
    b = -mpmath.expm1(-2 * rho * x2) / d
    return a, b


def closed_areas(psi, rho):
    """(A_el, A_pl, A_tot) of the closed form, rho = pbar/H, psi = sqrt(V)/H.
    A_tot = ((1+a)/2) erf(rho x/sqrt2) + (b/2)[e^{-2(1-rho)x^2} + erfc((2-rho)x/sqrt2)]
    (docs/model.md's formula with 1 - a = b e^{-2(1-rho)x^2}; all terms >= 0)."""
    x = 1 / psi
    x2 = x * x
    a, b = closed_abD(psi, rho)
    r2 = mpmath.sqrt(2)
    tot = (1 + a) / 2 * erf_(rho * x / r2) + b / 2 * (
        mpmath.exp(-2 * (1 - rho) * x2) + erfc_((2 - rho) * x / r2))
    el = _mass(rho, psi) - a * _mass(-rho, psi) - b * _mass(2 - rho, psi)
    # A_pl = tot - el cancels completely where the plastic area is tiny (both
    # working precisions can then agree on 0). With a = 1 - b e^{-2(1-rho)x^2}
    # it is [(1+b) erfc(alpha) - a erfc(beta)]/2, alpha = (1-rho)x/sqrt2,
    # beta = (1+rho)x/sqrt2, i.e. the positive terms below.
    al, be = (1 - rho) * x / r2, (1 + rho) * x / r2
    pl = (erfc_(al) - erfc_(be) + b * erfc_(al)
          + b * mpmath.exp(-2 * (1 - rho) * x2) * erfc_(be)) / 2
    diff = tot - el
    assert abs(diff - pl) <= mpf(10) ** (-mp.dps // 2) * (abs(tot) + abs(el)), (psi, rho)
    return el, pl, tot


def closed_areas_raw(psi, rho):
    """docs/model.md's formulas verbatim (H = 1, V = psi^2); check only."""
    V = psi * psi

    def P0(u):
        return mpmath.exp(-u * u / (2 * V)) / mpmath.sqrt(2 * mpmath.pi * V)

    D = P0(1 - rho) * P0(rho) - P0(1 + rho) * P0(2 - rho)
    a = P0(1 - rho) * (P0(rho) - P0(2 - rho)) / D
    b = P0(rho) * (P0(1 - rho) - P0(1 + rho)) / D
    r = mpmath.sqrt(2 * V)
    tot = (1 + a) / 2 * mpmath.erf(rho / r) + b / 2 * mpmath.erf((rho - 2) / r) + (1 - a + b) / 2
    el = _mass(rho, psi) - a * _mass(-rho, psi) - b * _mass(2 - rho, psi)
    return a, b, el, tot


# ---------------------------------------------------------------------------
# spectrum, hardness, indices (docs/model.md)
# ---------------------------------------------------------------------------

def _g(lnz, e):
    """g(zeta, e) = (zeta^e - 1)/e, = ln zeta at e = 0."""
    if e == 0:
        return lnz
    return mpmath.expm1(e * lnz) / e


def params_row(h0_over_e, h_rms, zeta, hurst, r_star, q0):
    """All params.csv outputs, at the current precision, from the exact inputs."""
    e_over_h0 = 1 / mpf(h0_over_e)
    h = mpf(h_rms)
    z = mpf(zeta)
    H = mpf(hurst)
    R = mpf(r_star)
    q = mpf(q0)
    pi = mpmath.pi
    Z = h * h * H * q ** (2 * H) / pi
    lnz = mpmath.log(z)
    m0 = (pi * Z / H) * q ** (-2 * H) * (-mpmath.expm1(-2 * H * lnz))
    m2 = pi * Z * q ** (2 - 2 * H) * _g(lnz, 2 - 2 * H)
    m4 = 3 * pi / 4 * Z * q ** (4 - 2 * H) * _g(lnz, 4 - 2 * H)
    r_s = INF if m4 == 0 else mpf(3) / 8 * mpmath.sqrt(pi / m4)
    lambda1 = 2 * pi / (z * q)
    h_act = mpmath.sqrt(m0)
    slope = mpmath.sqrt(2 * m2)
    curv = mpmath.sqrt(8 * m4 / 3)
    r_p_factor = mpf(6) / 5   # R_p = 1.2 R_s
    if R == 0 or r_s == INF:
        hr = mpf(1)
    else:
        hr = mpmath.sqrt(1 + R / (r_p_factor * r_s))
    psi_p = e_over_h0 * mpmath.sqrt(m2 / 2)
    psi_star = psi_p / hr
    psi_gw = mpf(0) if r_s == INF else e_over_h0 * mpmath.sqrt(h_act / r_s)
    if R == 0 or H == 1:
        asym = None
    else:
        e2, e4 = 2 - 2 * H, 4 - 2 * H
        m2i = pi * Z * q ** e2 * z ** e2 / e2
        m4i = 3 * pi / 4 * Z * q ** e4 * z ** e4 / e4
        r_si = mpf(3) / 8 * mpmath.sqrt(pi / m4i)
        asym = e_over_h0 * mpmath.sqrt(m2i / 2) * mpmath.sqrt(r_p_factor * r_si / R)
    out = [Z, m0, m2, m4, r_s, lambda1, h_act, slope, curv, hr,
           psi_gw, psi_p, psi_star, asym]
    out += list(exact_slopes(psi_p)) + list(closed_slopes(psi_p))
    out += list(exact_slopes(psi_star)) + list(closed_slopes(psi_star))
    return out


# ---------------------------------------------------------------------------
# Taylor series of the closed-form elastic slope in x = 1/psi
# ---------------------------------------------------------------------------
# Even parts cancel exactly: x^2/(e^{2y}-1) + x^2/(1-e^{-2y}) = x^2 coth y
# (y = x^2), so with erfc = 1 - erf
#   S_el/K = x(1 - e^{-x^2/2}) - erf(sqrt2 x)/K * f1(x^2) + erf(x/sqrt2)/K * f2(x^2)
#   f1(y) = y/(1 - e^{-2y}),  f2(y) = y coth y,
#   erf(sqrt2 x)/K = 2 sum (-1)^n 2^n x^{2n+1}/(n!(2n+1)),
#   erf(x/sqrt2)/K = sum (-1)^n x^{2n+1}/(2^n n!(2n+1)).
# Everything is a rational power series times K = sqrt(2/pi); radius sqrt(pi).

SERIES_MAX_POWER = 81


def _ser_mul(a, b, n):
    c = [Fraction(0)] * (n + 1)
    for i, ai in enumerate(a):
        if ai == 0:
            continue
        for j in range(0, n + 1 - i):
            if j < len(b) and b[j] != 0:
                c[i + j] += ai * b[j]
    return c


def _ser_inv(a, n):
    inv = [Fraction(0)] * (n + 1)
    inv[0] = 1 / a[0]
    for k in range(1, n + 1):
        s = Fraction(0)
        for j in range(1, k + 1):
            if j < len(a):
                s += a[j] * inv[k - j]
        inv[k] = -s / a[0]
    return inv


def closed_el_series_rational(nmax=SERIES_MAX_POWER):
    """r_k with S_el(x) = sqrt(2/pi) sum_k r_k x^k, k = 0..nmax."""
    n = nmax
    fact = [math.factorial(i) for i in range(2 * n + 3)]
    # series in y up to y^(n//2)
    ny = n // 2 + 1
    one_minus_exp = [Fraction(-(-2) ** (m + 1), fact[m + 1]) for m in range(ny + 1)]  # (1-e^{-2y})/y
    f1y = _ser_inv(one_minus_exp, ny)
    cosh = [Fraction(1, fact[2 * m]) for m in range(ny + 1)]
    sinh_over = [Fraction(1, fact[2 * m + 1]) for m in range(ny + 1)]
    # f2(y) = y coth y = sum y^{2m}/(2m)! / sum y^{2m}/(2m+1)!  (series in y^2)
    # build as series in y
    cosh_y = [Fraction(0)] * (ny + 1)
    sinh_y = [Fraction(0)] * (ny + 1)
    for m in range(ny + 1):
        if 2 * m <= ny:
            cosh_y[2 * m] = cosh[m]
            sinh_y[2 * m] = sinh_over[m]
    f2y = _ser_mul(cosh_y, _ser_inv(sinh_y, ny), ny)
    # to series in x
    f1 = [Fraction(0)] * (n + 1)
    f2 = [Fraction(0)] * (n + 1)
    for m in range(ny + 1):
        if 2 * m <= n:
            f1[2 * m] = f1y[m]
            f2[2 * m] = f2y[m]
    t1 = [Fraction(0)] * (n + 1)   # x (1 - e^{-x^2/2})
    for m in range(1, n):
        if 2 * m + 1 <= n:
            t1[2 * m + 1] = -Fraction((-1) ** m, 2 ** m * fact[m])
    erf2 = [Fraction(0)] * (n + 1)
    erfh = [Fraction(0)] * (n + 1)
    for m in range(n):
        if 2 * m + 1 <= n:
            erf2[2 * m + 1] = Fraction(2 * (-1) ** m * 2 ** m, fact[m] * (2 * m + 1))
            erfh[2 * m + 1] = Fraction((-1) ** m, 2 ** m * fact[m] * (2 * m + 1))
    a = _ser_mul(erf2, f1, n)
    b = _ser_mul(erfh, f2, n)
    return [t1[k] - a[k] + b[k] for k in range(n + 1)]


def closed_el_from_series(r, psi):
    x = 1 / psi
    s = mpf(0)
    for k in range(len(r) - 1, -1, -1):
        s = s * x + mpf(r[k].numerator) / r[k].denominator
    return K() * s


# ---------------------------------------------------------------------------
# self-checks (assertions; the script fails loudly if any is off)
# ---------------------------------------------------------------------------

def rel(a, b):
    if a == b:
        return mpf(0)
    return abs(a - b) / max(abs(a), abs(b))


def check_all(series_r):
    with mp.workdps(80):
        # both exact forms, and mpmath's jtheta, agree to 50 digits
        for x2 in [mpf(1) / 4, mpmath.pi / 4, mpmath.pi / 2, 1, 3, mpmath.pi,
                   2 * mpmath.pi, 4 * mpmath.pi, 12]:
            psi = 1 / mpmath.sqrt(x2)
            x = 1 / psi
            tl, ts = exact_tot_large(psi), exact_tot_small(psi)
            pl_l, pl_s = exact_pl_large(psi), exact_pl_small(psi)
            el_l, el_s = exact_el_large(psi), exact_el_small(psi)
            jt = K() * x * mpmath.jtheta(3, 0, mpmath.exp(-2 * x2))
            jp = K() * x * mpmath.jtheta(2, 0, mpmath.exp(-2 * x2))
            je = K() * x * mpmath.jtheta(4, 0, mpmath.exp(-x2 / 2))
            for u, v in [(tl, ts), (tl, jt), (pl_l, pl_s), (pl_l, jp), (el_l, el_s),
                         (el_l, je), (el_l, tl - pl_l), (el_s, ts - pl_s)]:
                assert rel(u, v) < mpf(10) ** -50, (x2, u, v)
        # own erfc asymptotics against mpmath where both work
        # (exp(-z^2) has condition number 2 z^2: add 2 log10 z digits)
        for z in ["1.0000001e6", "3e6", "1e8", "1e20", "1e100"]:
            with mp.workdps(80 + 2 * int(mpmath.log10(mpf(z)))):
                z = mpf(z)
                assert rel(erfc_(z), mpmath.erfc(z)) < mpf(10) ** -60, z
    with mp.workdps(60):
        # docs/model.md check values at psi = 1 (15 digits given)
        el, pl, tot = exact_slopes(mpf(1))
        cel, cpl, ctot = closed_slopes(mpf(1))
        for got, want in [(el, "0.0287675334233055"), (pl, "0.985616238638923"),
                          (tot, "1.01438377206223"), (cel, "0.106442719176429"),
                          (cpl, "0.900581342322006"), (ctot, "1.00702406149844")]:
            assert rel(got, mpf(want)) < mpf(10) ** -13, (got, want)
        # fig3 at zeta = 128
        row = params_row(1e-2, 2e-8, 128.0, 0.8, 1e-3, 1e5)
        Z, m0, m2, m4, r_s, lam, hact, slp, curv, hr, pgw, pp, pst, asym = row[:14]
        for got, want in [(Z, "1.01859163578813e-8"), (m2, "4.77152360509519e-5"),
                          (m4, "1141038034.3235"), (r_s, "1.96768757629937e-5"),
                          (hr, "6.58413978635223"), (pp, "0.488442606919953"),
                          (pst, "0.0741847261402938"), (pgw, "3.18779778457193")]:
            assert rel(got, mpf(want)) < mpf(10) ** -13, (got, want)
        # closed-form normalized a, b and A_tot against docs/model.md's raw formulas
        for psi in ["0.1", "0.3", "0.5", "1", "2", "5"]:
            for rho in ["1e-6", "0.05", "0.25", "0.5", "0.9", "1"]:
                psi_m, rho_m = mpf(float(psi)), mpf(float(rho))
                with mp.workdps(120):
                    a, b = closed_abD(psi_m, rho_m)
                    ra, rb, rel_, rtot = closed_areas_raw(psi_m, rho_m)
                    el, pl, tot = closed_areas(psi_m, rho_m)
                    assert rel(a, ra) < mpf(10) ** -60 and rel(b, rb) < mpf(10) ** -60
                    assert rel(tot, rtot) < mpf(10) ** -60, (psi, rho, tot, rtot)
        # exact areas: images vs sine series, and flux vs load balance
        for psi in [0.3, 0.5, 0.7, 1.0, 1.5]:
            for rho in [1e-8, 1e-3, 0.1, 0.25, 0.5, 0.75, 0.99]:
                p, r = mpf(psi), mpf(rho)
                with mp.workdps(100):
                    n = _image_count(p) + 4
                    ie, ip, it = exact_areas_images(p, r, n)
                    se, sp, st = exact_areas_sine(p, r)
                    lb = exact_pl_load_balance(p, r, n)
                    assert rel(ie, se) < mpf(10) ** -40, (psi, rho, ie, se)
                    assert rel(ip, sp) < mpf(10) ** -40, (psi, rho, ip, sp)
                    assert rel(ip, lb) < mpf(10) ** -40, (psi, rho, ip, lb)
        # A(pbar)/pbar tends to the slopes (both models)
        rho = mpf(1e-12)
        for psi in [0.1, 0.3, 0.5, 1.0, 2.0, 5.0]:
            p = mpf(psi)
            with mp.workdps(80):
                ea = exact_areas(p, rho)
                es = exact_slopes(p)
                ca = closed_areas(p, rho)
                cs = closed_slopes(p)
                for a_, s_ in zip(ea + ca, es + cs):
                    assert rel(a_ / rho, s_) < mpf(10) ** -9, (psi, a_ / rho, s_)
        # Taylor series of the closed elastic slope against the adaptive difference
        assert all(series_r[k] == 0 for k in range(5)) and series_r[5] != 0
        assert all(series_r[k] == 0 for k in range(0, len(series_r), 2))
        for psi in ["2", "4", "10", "1e3", "1e20"]:
            p = mpf(psi)
            with mp.workdps(120):
                direct = closed_slopes(p)[0]
                ser = closed_el_from_series(series_r, p)
                tol = mpf(10) ** -30 if p >= 4 else mpf(10) ** -18
                assert rel(direct, ser) < tol, (psi, direct, ser)
    try:
        import sympy
    except ImportError:
        sympy = None
    if sympy is not None:
        xs = sympy.symbols("x", positive=True)
        expr = (sympy.sqrt(2 / sympy.pi) * xs * (1 - sympy.exp(-xs ** 2 / 2))
                - xs ** 2 * sympy.erf(sympy.sqrt(2) * xs) / (1 - sympy.exp(-2 * xs ** 2))
                + xs ** 2 * sympy.erf(xs / sympy.sqrt(2)) * sympy.coth(xs ** 2))
        ser = sympy.series(expr, xs, 0, 14).removeO()
        for k in range(14):
            want = sympy.sqrt(2 / sympy.pi) * sympy.Rational(series_r[k].numerator,
                                                             series_r[k].denominator)
            assert sympy.simplify(ser.coeff(xs, k) - want) == 0, (k, ser.coeff(xs, k), want)


# ---------------------------------------------------------------------------
# grids
# ---------------------------------------------------------------------------

def slope_grid():
    pts = {0.0}
    for k in range(-320, 321):                       # 1e-8 .. 1e8, 40 per decade
        pts.add(10.0 ** (k / 40))
    n = 200
    for i in range(n):                               # dense 0.05 .. 30
        pts.add(0.05 + i * (30.0 - 0.05) / (n - 1))
        pts.add(0.05 * (30.0 / 0.05) ** (i / (n - 1)))
    corners = [1.0 / math.sqrt(math.pi / 2), 1.0 / math.sqrt(math.pi),
               1.0 / math.sqrt(2 * math.pi), 1.0, 0.5, 2.0]
    ln10 = math.log(10.0)
    for thr in [300.0, -math.log10(sys.float_info.min), 320.0, 323.3]:
        # exp(-pi^2 psi^2/2) = 10^-thr ; exp(-1/(2 psi^2)) = 10^-thr
        corners.append(math.sqrt(2 * thr * ln10) / math.pi)
        corners.append(1.0 / math.sqrt(2 * thr * ln10))
        # exp(-2 pi^2 psi^2) and exp(-2/psi^2) (the next theta terms)
        corners.append(math.sqrt(thr * ln10 / 2) / math.pi)
        corners.append(1.0 / math.sqrt(thr * ln10 / 2))
    for c in corners:
        pts.add(c)
        pts.add(math.nextafter(c, 0.0))
        pts.add(math.nextafter(c, math.inf))
        for f in (0.999, 0.99, 0.9, 1.001, 1.01, 1.1):
            pts.add(c * f)
    for big in [1e-308, sys.float_info.min, 1e-300, 1e-200, 1e-100, 1e-50, 1e-20,
                1e20, 1e50, 1e100, 1e200, 1e300, 1e308, sys.float_info.max]:
        pts.add(big)
    return sorted(pts)


AREA_PSI = [1e-8, 1e-4, 1e-2, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0,
            10.0, 100.0, 1e4, 1e8]
AREA_RHO = [1e-12, 1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 1.0]


def random_params(rng, n, zeta_special, hurst_special, hurst_max, zeta_lo, hurst_hi, row):
    """n random parameter sets (H up to hurst_max, special zeta and H values
    mixed in), then 40 targeted ones with zeta from 10^zeta_lo to 1e10 and
    psi_p plastic (3..12) or small (1e-3..0.1), where the slopes are
    exponentially small and amplify every error of psi: H0/E is solved (in
    floats) for the target from m2 of row(...), the row then uses that float."""
    rows = []
    for _ in range(n):
        h0e = 10.0 ** rng.uniform(-6.0, 0.0)
        hr = 10.0 ** rng.uniform(-10.0, -3.0)
        z = rng.choice(zeta_special) if rng.random() < 0.12 else 10.0 ** rng.uniform(0.0, 10.0)
        hu = rng.choice(hurst_special) if rng.random() < 0.15 else rng.uniform(0.01, hurst_max)
        r = 0.0 if rng.random() < 0.25 else 10.0 ** rng.uniform(-9.0, -1.0)
        q = 1e5 if rng.random() < 0.15 else 10.0 ** rng.uniform(2.0, 8.0)
        rows.append((h0e, hr, z, hu, r, q))
    for i in range(40):
        z = 10.0 ** rng.uniform(zeta_lo, 10.0)
        hu = rng.uniform(0.3, hurst_hi) if i % 5 else 0.8
        hr = 10.0 ** rng.uniform(-9.0, -6.0)
        q = 10.0 ** rng.uniform(3.0, 7.0) if i % 4 else 1e5
        r = 0.0 if i % 3 == 0 else 10.0 ** rng.uniform(-7.0, -2.0)
        target = 10.0 ** rng.uniform(math.log10(3.0), math.log10(12.0)) if i % 2 == 0 \
            else 10.0 ** rng.uniform(-3.0, -1.0)
        with mp.workdps(30):
            m2 = row(1.0, hr, z, hu, r, q)[2]
            h0e = float(mpmath.sqrt(m2 / 2) / target)
        rows.append((h0e, hr, z, hu, r, q))
    return rows


def params_grid():
    rows = []
    q0, hurst, rst = 1e5, 0.8, 1e-3
    npts = 30
    # fig1: H0/E 1e-4 .. 1e-1, h_rms 20 nm, zeta 128, no size effect
    for i in range(npts):
        rows.append((10.0 ** (-4 + 3 * i / (npts - 1)), 2e-8, 128.0, hurst, 0.0, q0))
    rows.append((1e-2, 2e-8, 128.0, hurst, 0.0, q0))
    rows.append((1e-3, 2e-8, 128.0, hurst, 0.0, q0))
    # fig2 / fig3: zeta 1 .. 1e4, h_rms 20 nm, H0/E 1e-2; fig3 with R* = 1 mm
    for r in (0.0, rst):
        for i in range(npts):
            rows.append((1e-2, 2e-8, 10.0 ** (4 * i / (npts - 1)), hurst, r, q0))
        rows.append((1e-2, 2e-8, 128.0, hurst, r, q0))
    # fig4: zeta 1 .. 1e6, h_rms 600 nm, H0/E 1e-3, R* = 1 mm
    for i in range(npts):
        rows.append((1e-3, 6e-7, 10.0 ** (6 * i / (npts - 1)), hurst, rst, q0))
    rows.append((1e-3, 6e-7, 128.0, hurst, rst, q0))

    rng = random.Random(20240303)
    zeta_special = [1.0, 1.0 + 2.0 ** -40, 1.0 + 1e-10, 2.0, 1e10]
    hurst_special = [1.0, 0.5, 0.01, 0.99, 1.0 - 2.0 ** -30]
    rows += random_params(rng, 600, zeta_special, hurst_special, 1.0, 6.0, 0.95, params_row)
    return rows


# ---------------------------------------------------------------------------
# output
# ---------------------------------------------------------------------------

def header_common(adaptive):
    return [
        "# generator: %s (python3 %s from the repository root)" % (SCRIPT, SCRIPT),
        "# mpmath %s; model: docs/model.md" % mpmath.__version__,
        "# precision: every row is evaluated at D and D+%d decimal digits, D starting at %d"
        % (STEP_DPS, BASE_DPS),
        "#   (plus the digits a known cancellation loses), D raised by %d until every output"
        % STEP_DPS,
        "#   of the row agrees to %d significant digits; printed values come from the D+%d run."
        % (AGREE_DIGITS, STEP_DPS),
        "#   highest working precision reached in this file: %d digits"
        % max(adaptive.max_dps, INNER_MAX_DPS),
        "# inputs: IEEE doubles printed with Python repr (shortest round trip), converted exactly.",
        "# outputs: %d significant digits; 'inf' = +infinity; '0' = exactly zero or |value| < %s"
        % (PRINT_DIGITS, ZERO_BELOW),
        "#   (a value below %s is printed as 0); nan never appears." % ZERO_BELOW,
    ]


def write_file(name, header_lines, csv_header, rows):
    path = os.path.join(OUT_DIR, name)
    with open(path, "w", newline="\n") as f:
        for line in header_lines:
            f.write(line + "\n")
        f.write(csv_header + "\n")
        for r in rows:
            f.write(",".join(r) + "\n")
    print("wrote %s (%d rows)" % (path, len(rows)), file=sys.stderr)


def gen_slopes():
    global INNER_MAX_DPS
    INNER_MAX_DPS = 0
    ad = Adaptive()
    rows = []
    for psi in slope_grid():
        def f(psi=psi):
            p = mpf(psi)
            return list(exact_slopes(p)) + list(closed_slopes(p)) + [persson_slope(p)]
        vals = ad(f)
        rows.append([fmt_in(psi)] + [fmt_out(v) for v in vals])
    hdr = header_common(ad) + [
        "# columns (x = 1/psi; slopes are H (1/A0) dA/dpbar at pbar -> 0):",
        "#   psi: plasticity index sqrt(V)/H",
        "#   exact_elastic, exact_plastic, exact_total: exact two-barrier model (theta series),",
        "#     S_tot = sqrt(2/pi) x sum_n exp(-2 n^2 x^2), S_pl = sqrt(2/pi) x sum_n exp(-(2n+1)^2 x^2/2),",
        "#     S_el = S_tot - S_pl (computed cancellation-free: sqrt(2/pi) x theta4(0,e^{-x^2/2})",
        "#     or 4 sum_{k odd} exp(-pi^2 k^2/(2x^2)))",
        "#   closed_elastic, closed_plastic, closed_total: three-Gaussian closed form (docs/model.md),",
        "#     closed_elastic = closed_total - closed_plastic at raised precision",
        "#   persson_elastic: sqrt(2/pi)/psi",
        "#   psi = 0: exact/closed elastic and total = inf, plastic = 0, persson = inf",
    ]
    write_file("slopes.csv", hdr,
               "psi,exact_elastic,exact_plastic,exact_total,closed_elastic,closed_plastic,"
               "closed_total,persson_elastic", rows)


def gen_areas():
    global INNER_MAX_DPS
    INNER_MAX_DPS = 0
    ad = Adaptive()
    rows = []
    for psi in AREA_PSI:
        for rho in AREA_RHO:
            def f(psi=psi, rho=rho):
                p, r = mpf(psi), mpf(rho)
                return list(exact_areas(p, r)) + list(closed_areas(p, r))
            vals = ad(f)
            rows.append([fmt_in(psi), fmt_in(rho)] + [fmt_out(v) for v in vals])
    hdr = header_common(ad) + [
        "# columns: psi = sqrt(V)/H; rho = pbar/H; areas are A/A0 at mean pressure pbar.",
        "#   exact_*: diffusion in p with variance V from pbar, absorbing at 0 and H;",
        "#     exact_elastic = int_0^H P dp, exact_plastic = (pbar - int_0^H p P dp)/H",
        "#     (= probability of absorption at H), exact_total = sum.  Images for psi < 0.6,",
        "#     sine series otherwise (both checked against each other in the script).",
        "#   closed_*: three-Gaussian closed form (docs/model.md), closed_plastic = total - elastic, summed as positive terms;",
        "#     with x = 1/psi: D' = -expm1(-2x^2), a = -expm1(-2(1-rho)x^2)/D',",
        "#     b = -expm1(-2 rho x^2)/D'.  closed_elastic may be negative (the closed form is",
        "#     not an exact solution); it is printed as computed.",
        "#   rho = 1: exact_elastic = 0, exact_plastic = exact_total = 1.",
    ]
    write_file("areas.csv", hdr,
               "psi,rho,exact_elastic,exact_plastic,exact_total,closed_elastic,closed_plastic,"
               "closed_total", rows)


def gen_params():
    global INNER_MAX_DPS
    INNER_MAX_DPS = 0
    ad = Adaptive()
    rows = []
    for inp in params_grid():
        def f(inp=inp):
            return params_row(*inp)
        vals = ad(f)
        rows.append([fmt_in(v) for v in inp] + [fmt_out(v) for v in vals])
    hdr = header_common(ad) + [
        "# inputs: h0_over_e = H0/E, h_rms [m], zeta = q1/q0, hurst, r_star [m], q0 [1/m].",
        "# outputs (all from the exact inputs in mpmath; decimal constants as exact rationals):",
        "#   z = h_rms^2 hurst q0^(2 hurst)/pi; m0 = (pi z/hurst) q0^(-2hurst) (1 - zeta^(-2hurst));",
        "#   m2 = pi z q0^(2-2hurst) g(zeta,2-2hurst); m4 = (3pi/4) z q0^(4-2hurst) g(zeta,4-2hurst),",
        "#     g(zeta,e) = (zeta^e-1)/e, ln zeta at e = 0;",
        "#   r_s = (3/8) sqrt(pi/m4) (inf at zeta = 1); lambda1 = 2pi/(zeta q0);",
        "#   h_rms_actual = sqrt(m0); rms_slope = sqrt(2 m2); rms_curvature = sqrt(8 m4/3);",
        "#   hardness_ratio = H_y/H0 = sqrt(1 + r_star/(1.2 r_s)) (1 if r_star = 0 or zeta = 1);",
        "#   psi_gw = sqrt(h_rms_actual/r_s)/h0_over_e (0 at zeta = 1);",
        "#   psi_p = sqrt(m2/2)/h0_over_e; psi_star = psi_p/hardness_ratio;",
        "#   psi_star_asym = psi_p_inf sqrt(1.2 r_s_inf/r_star), psi_p_inf and r_s_inf from m2, m4",
        "#     with g replaced by zeta^e/e (eq. 13); empty when r_star = 0 or hurst = 1;",
        "#   exact_{el,pl,tot}_p, closed_{el,pl,tot}_p: slopes (as in slopes.csv) at psi = psi_p;",
        "#   exact_{el,pl,tot}_star, closed_{el,pl,tot}_star: the same at psi = psi_star",
        "#     (at psi = 0: el = tot = inf, pl = 0).",
    ]
    cols = ("h0_over_e,h_rms,zeta,hurst,r_star,q0,z,m0,m2,m4,r_s,lambda1,h_rms_actual,"
            "rms_slope,rms_curvature,hardness_ratio,psi_gw,psi_p,psi_star,psi_star_asym,"
            "exact_el_p,exact_pl_p,exact_tot_p,closed_el_p,closed_pl_p,closed_tot_p,"
            "exact_el_star,exact_pl_star,exact_tot_star,closed_el_star,closed_pl_star,"
            "closed_tot_star")
    write_file("params.csv", hdr, cols, rows)


def gen_series(r):
    path = os.path.join(OUT_DIR, "closed_series.txt")
    lines = [
        "# generator: %s (python3 %s from the repository root)" % (SCRIPT, SCRIPT),
        "# mpmath %s; coefficients are exact rationals (Python fractions) times sqrt(2/pi),"
        % mpmath.__version__,
        "#   printed with 40 significant digits (evaluated at 80 digits).",
        "# Taylor series around x = 0 of the closed-form elastic slope, x = 1/psi:",
        "#   S_el(x) = S_tot(x) - S_pl(x) = sum_k coefficient_k x^k  (docs/model.md three-Gaussian form)",
        "#   = sqrt(2/pi) x (1 - e^{-x^2/2}) - x^2 erf(sqrt2 x)/(1 - e^{-2x^2}) + x^2 erf(x/sqrt2) coth(x^2)",
        "#   (the even parts cancel exactly).  Only odd powers occur and the first is x^5;",
        "#   powers not listed (0..4 and every even power) have coefficient exactly 0.",
        "#   Radius of convergence sqrt(pi) (poles of coth(x^2) and 1/(1 - e^{-2x^2})).",
        "#   Listed through x^%d." % SERIES_MAX_POWER,
        "# exact form: coefficient_k = sqrt(2/pi) * r_k with",
    ]
    for k, c in enumerate(r):
        if c != 0:
            lines.append("#   r_%d = %s" % (k, c))
    lines.append("power,coefficient")
    with mp.workdps(80):
        kk = K()
        for k, c in enumerate(r):
            if c != 0:
                v = kk * mpf(c.numerator) / c.denominator
                lines.append("%d,%s" % (k, mpmath.nstr(v, 40, min_fixed=-4, max_fixed=16)))
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s (%d coefficients)" % (path, sum(1 for c in r if c != 0)), file=sys.stderr)


def main():
    if not os.path.isdir(os.path.join("crates", "rough-model")):
        sys.exit("run from the repository root")
    os.makedirs(OUT_DIR, exist_ok=True)
    mp.dps = BASE_DPS
    r = closed_el_series_rational()
    check_all(r)
    print("self-checks passed", file=sys.stderr)
    gen_series(r)
    gen_slopes()
    gen_areas()
    gen_params()


if __name__ == "__main__":
    main()
