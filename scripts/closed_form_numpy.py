#!/usr/bin/env python3
"""The paper's Figure 2 as a NumPy/SciPy user would compute it: the peer that
`scripts/bench_export.sh` times `roughtui export --preset fig2` against.

    python3 scripts/closed_form_numpy.py [--points N] > fig2.csv

Prints the same columns as `roughtui export --preset fig2 --points N`
(without its `#` lines naming the scene):
zeta,psi,h_use_over_h0,elastic,plastic,total,persson_elastic, with the
closed-form slopes (Ciavarella 2024, Appendix A) on the asymptotic moments
(eq. 10), zeta swept log-uniformly from 1 to 1e4, no size effect. Numbers are
printed with 17 significant digits (they read back to the same doubles).

Written as a researcher would: vectorised over the sweep, scipy.special.erfc,
the paper's formulas as printed. It is not a reference: the elastic slope is
the difference S_tot - S_pl, which loses digits for small 1/psi (the
committed mpmath scripts are the reference).
"""

import argparse
import sys

import numpy as np
from scipy.special import erfc

# Figure 2's parameters (presets/fig2.ron).
H0_OVER_E = 1e-2
H_RMS = 1.9816636488030044e-8  # m
HURST = 0.8
Q0 = 1e5  # 1/m
ZETA_FROM, ZETA_TO = 1.0, 1e4

HEADER = "zeta,psi,h_use_over_h0,elastic,plastic,total,persson_elastic"


def psi_p(zeta):
    """Persson's index sqrt(V)/H0 with the asymptotic moments (eq. 10, 11)."""
    z = H_RMS**2 * HURST * Q0 ** (2 * HURST) / np.pi
    e2 = 2 - 2 * HURST
    m2 = np.pi * z * Q0**e2 * zeta**e2 / e2
    return np.sqrt(m2 / 2) / H0_OVER_E


def closed_form_slopes(psi):
    """Initial slopes (elastic, plastic, total) of the three-Gaussian closed form."""
    x = 1 / psi
    u = x**2
    total = (np.sqrt(2 / np.pi) * x
             + u / (np.exp(2 * u) - 1)
             + u * erfc(np.sqrt(2) * x) / (1 - np.exp(-2 * u)))
    plastic = (np.sqrt(2 / np.pi) * x * np.exp(-u / 2)
               + u * erfc(x / np.sqrt(2)) / np.tanh(u))
    return total - plastic, plastic, total


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=200)
    args = parser.parse_args()
    zeta = np.logspace(np.log10(ZETA_FROM), np.log10(ZETA_TO), args.points)
    psi = psi_p(zeta)
    elastic, plastic, total = closed_form_slopes(psi)
    persson = np.sqrt(2 / np.pi) / psi
    table = np.column_stack([zeta, psi, np.ones_like(psi), elastic, plastic, total, persson])
    np.savetxt(sys.stdout, table, delimiter=",", header=HEADER, comments="", fmt="%.17g")


if __name__ == "__main__":
    main()
