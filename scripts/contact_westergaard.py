#!/usr/bin/env python3
"""Westergaard's periodic wavy contact, the analytic reference of rough-contact.

Rigid surface h = D cos(2 pi x / lam) on an elastic half-space (E*), purely
elastic, mean pressure pm; p* = pi E* D / lam. Contact half-width a with
sin^2(pi a / lam) = pm / p*; contact fraction 2a/lam = (2/pi) asin(sqrt(pm/p*));
pressure p(x) = 2 pm cos(pi x/lam) sqrt(sin^2(pi a/lam) - sin^2(pi x/lam)) / sin^2(pi a/lam)
for |x| < a (Johnson, Contact Mechanics, 13.2).

Writes crates/rough-contact/tests/data/westergaard.csv: for lam = 1, D = 0.01,
E* = 1 and each load, the contact fraction and the pressure at the nodes
x_i = i/256, i = 0..255, all to 17 significant digits (mpmath, 40 digits).

Run: python3 scripts/contact_westergaard.py
"""
import os
from mpmath import mp, mpf, pi, asin, sqrt, sin, cos

mp.dps = 40
E, D, LAM, N = mpf(1), mpf("0.01"), mpf(1), 256
PSTAR = pi * E * D / LAM
OUT = os.path.join(os.path.dirname(__file__), "..", "crates", "rough-contact", "tests", "data", "westergaard.csv")

with open(OUT, "w") as f:
    f.write("# Westergaard, h = D cos(2 pi x/lam), lam = 1, D = 0.01, E* = 1, p* = pi E* D/lam\n")
    f.write("# columns: p_over_pstar, contact_fraction, then p(x_i) at x_i = i/%d, i = 0..%d\n" % (N, N - 1))
    for r in ["0.001", "0.01", "0.1", "0.3", "0.6", "0.9", "0.99"]:
        pm = mpf(r) * PSTAR
        s2 = pm / PSTAR
        frac = 2 / pi * asin(sqrt(s2))
        a = frac * LAM / 2
        row = [mp.nstr(mpf(r), 17), mp.nstr(frac, 17)]
        for i in range(N):
            x = mpf(i) / N * LAM
            if x > LAM / 2:
                x -= LAM
            if abs(x) < a:
                p = 2 * pm * cos(pi * x / LAM) * sqrt(s2 - sin(pi * x / LAM) ** 2) / s2
            else:
                p = mpf(0)
            row.append(mp.nstr(p, 17))
        f.write(",".join(row) + "\n")
