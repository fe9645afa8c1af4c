"""ε = 2h′ and d_rep = 4h′/h″ (eq. 16–17) at the fig2 and fig4 presets'
own parameters, and fig2's Ψ_P on the truncated spectrum, from the asymptotic moments written out again in mpmath
(gen_asymptotic.py). tests/tui_update.rs compares the explorer's readout with
these numbers.

    python3 scripts/readout_reference.py
"""

import mpmath
from mpmath import mp

from gen_asymptotic import H_RMS_PAPER, params_row_asymptotic

mp.dps = 40

PRESETS = {
    # name: (h0_over_e, h_rms, zeta, hurst, r_star, q0)
    "fig2": (0.01, H_RMS_PAPER, 128.0, 0.8, 1e-3, 1e5),
    "fig4": (0.001, 600e-9, 1e4, 0.8, 1e-3, 1e5),
}


def main():
    for name, p in PRESETS.items():
        row = params_row_asymptotic(*p)
        slope, curv = row[7], row[8]
        eps = 2 * slope
        d_rep = 4 * slope / curv
        print(f"{name}: epsilon {mpmath.nstr(eps, 17)}  d_rep {mpmath.nstr(d_rep, 17)} m")
    # fig2's Ψ_P on the truncated spectrum (what the `a` key switches to):
    # m2 = πZ q0^(2−2H) (ζ^(2−2H) − 1)/(2−2H).
    h0_over_e, h, z, hurst, _, q = (mpmath.mpf(v) for v in PRESETS["fig2"])
    big_z = h * h * hurst * q ** (2 * hurst) / mpmath.pi
    e = 2 - 2 * hurst
    m2 = mpmath.pi * big_z * q**e * (z**e - 1) / e
    print(f"fig2 truncated: psi_p {mpmath.nstr(mpmath.sqrt(m2 / 2) / h0_over_e, 17)}")


if __name__ == "__main__":
    main()
