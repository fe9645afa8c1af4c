#!/usr/bin/env python3
"""Hertz's sphere, the analytic reference of rough-contact's free boundary.

A rigid paraboloid h = -r^2/(2R) pressed with load P on an elastic half-space
(E*), purely elastic: a^3 = 3 P R / (4 E*), p(r) = p0 sqrt(1 - r^2/a^2),
p0 = 3 P / (2 pi a^2) (Johnson, Contact Mechanics, 4.2).

The crate solves it on a non-periodic 128 x 128 window of side L = 1 centred
on the apex (node 64, 64), R = 1, E* = 1, P = p_mean L^2. Writes
crates/rough-contact/tests/data/hertz.csv: per load, p_mean, a, p0 and the
pressure at the nodes of the centre row (x_i = (i - 64)/128), 17 digits
(mpmath, 40 digits).

Run: python3 scripts/contact_hertz.py
"""
import os
from mpmath import mp, mpf, pi, sqrt, cbrt

mp.dps = 40
N, L, R, E = 128, mpf(1), mpf(1), mpf(1)
OUT = os.path.join(os.path.dirname(__file__), "..", "crates", "rough-contact", "tests", "data", "hertz.csv")
with open(OUT, "w") as f:
    f.write("# Hertz, h = -r^2/(2R), R = 1, E* = 1, window L = 1 on %d x %d nodes, apex at node (64, 64)\n" % (N, N))
    f.write("# columns: p_mean, a, p0, then p at x_i = (i - 64)/%d on the centre row, i = 0..%d\n" % (N, N - 1))
    for a_target in ["0.1", "0.2", "0.3"]:
        a = mpf(a_target)
        P = 4 * E * a**3 / (3 * R)
        p0 = 3 * P / (2 * pi * a**2)
        row = [mp.nstr(P / L**2, 17), mp.nstr(a, 17), mp.nstr(p0, 17)]
        for i in range(N):
            x = mpf(i - N // 2) / N * L
            row.append(mp.nstr(p0 * sqrt(1 - (x / a) ** 2) if abs(x) < a else mpf(0), 17))
        f.write(",".join(row) + "\n")
