#!/usr/bin/env python3
"""High-precision reference data for the index, map and load views of
`roughtui export`.

Run from the repository root:

    python3 scripts/gen_views.py

It rewrites, deterministically, in crates/rough-study/data/:

    views_indices.csv  psi_gw, psi_p, psi_star, eq. 13, H_y/H0 along a sweep
    views_map.csv      psi in use, slopes and plastic share over a 2-D grid
    views_load.csv     areas A/A0 against pbar/H at one parameter set
    views_quoted.csv   numbers the README and the help quote (Psi_P at zeta = 128
                       on both moments, fig2's share at zeta = 1000 on both
                       readings of the elastic area, the closed form's dip)
    views_claims.csv   where the plastic share crosses 1/2, where the index in
                       use crosses 1 and where the total slope has a minimum
                       along a preset's sweep (the live claims)

Each file names its cases in comment lines `# case N: ARGS`: N is the `case`
column, ARGS the arguments of `roughtui export` that produce the same
rows (the test runs them). The export names its grid columns after the
parameters (`zeta`, `h0_over_e`, ...) and starts with `#` lines naming the
scene; since one file here holds cases over different parameters, its grid
columns are `x` (across) and `y` (up), and tests/views_reference.rs pairs
them with the export's first columns. The spectrum, indices, slopes and areas are those
of scripts/gen_reference.py (truncated moments) and scripts/gen_asymptotic.py
(the paper's eq. 10), imported from them, with their adaptive precision
driver and number format; grids are rebuilt here from the contract of the
export (log-spaced on log axes, both ends included, whole decades exact).
"""

import math
import os
import sys

import mpmath
from mpmath import mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_reference as ref  # noqa: E402
import gen_asymptotic as asy  # noqa: E402

SCRIPT = "scripts/gen_views.py"
OUT_DIR = os.path.join("crates", "rough-study", "data")

H_PAPER = asy.H_RMS_PAPER
FIG2 = dict(h0_over_e=0.01, h_rms=H_PAPER, zeta=128.0, hurst=0.8, r_star=0.001, q0=1e5)
FIG4 = dict(h0_over_e=0.001, h_rms=6e-7, zeta=1e4, hurst=0.8, r_star=0.001, q0=1e5)
ORDER = ("h0_over_e", "h_rms", "zeta", "hurst", "r_star", "q0")
LOG_AXES = ("h0_over_e", "h_rms", "zeta", "r_star")

# (args, params, sweep (axis, from, to), model, moments, size effect)
PRESETS = {
    "fig1": (FIG2, ("h0_over_e", 1e-4, 1e-1), "closed", "asymptotic", False),
    "fig2": (FIG2, ("zeta", 1.0, 1e4), "closed", "asymptotic", False),
    "fig3": (FIG2, ("zeta", 1.0, 1e4), "closed", "asymptotic", True),
    "fig4": (FIG4, ("zeta", 1.0, 1e6), "closed", "asymptotic", True),
}


def case(preset, model=None, moments=None, size_effect=None, sweep=None):
    """A preset with the export's overrides applied: (args, settings)."""
    params, sw, mo, mom, se = PRESETS[preset]
    args = ["--preset", preset]
    if model is not None:
        args += ["--model", "closed-form" if model == "closed" else model]
        mo = model
    if moments is not None:
        args += ["--moments", moments]
        mom = moments
    if size_effect is not None:
        args += ["--size-effect", "on" if size_effect else "off"]
        se = size_effect
    if sweep is not None:
        args += ["--sweep", "%s:%r:%r" % (sweep[0].replace("_", "-"), sweep[1], sweep[2])]
        sw = sweep
    return args, dict(params=dict(params), sweep=sw, model=mo, moments=mom, size_effect=se)


def decade(v):
    """k when v is the double nearest 10^k."""
    if v <= 0:
        return None
    k = round(math.log10(v))
    return k if float("1e%d" % k) == v else None


def grid(axis, a, b, n):
    """The export's n points from a to b: log-spaced on log axes, ends exact,
    whole decades exact between decade ends."""
    out = []
    da, db = decade(a), decade(b)
    for i in range(n):
        t = i / (n - 1)
        if i == 0:
            out.append(a)
        elif i == n - 1:
            out.append(b)
        elif axis in LOG_AXES:
            if da is not None and db is not None:
                d = da + (db - da) * t
                if abs(d - round(d)) < 1e-9:
                    out.append(float("1e%d" % round(d)))
                    continue
            out.append(math.exp(math.log(a) + (math.log(b) - math.log(a)) * t))
        else:
            out.append(a + (b - a) * t)
    return out


def indices_row(p, moments):
    """[psi_gw, psi_p, psi_star, psi_star_asymptotic, hardness_ratio]."""
    args = [p[k] for k in ORDER]
    r = asy.params_row_asymptotic(*args) if moments == "asymptotic" else ref.params_row(*args)
    # params rows: ..., hardness_ratio (9), psi_gw, psi_p, psi_star, asym (13)
    return [r[10], r[11], r[12], r[13], r[9]]


def psi_in_use(p, moments, size_effect):
    _, psi_p, psi_star, _, _ = indices_row(p, moments)
    return psi_star if size_effect else psi_p


def slopes(model, psi):
    return ref.exact_slopes(psi) if model == "exact" else ref.closed_slopes(psi)


def map_cell(p, s):
    psi = psi_in_use(p, s["moments"], s["size_effect"])
    el, pl, tot = slopes(s["model"], psi)
    share = mpf(0) if mpmath.isinf(tot) else pl / tot
    return [psi, el, pl, tot, share]


def load_row(psi, model, rho):
    if rho == 0:
        return [mpf(0)] * 3
    r = mpf(rho)
    return list(ref.exact_areas(psi, r) if model == "exact" else ref.closed_areas(psi, r))


MAP_Y = {"h0_over_e": (1e-4, 1e-1), "zeta": (1.0, 1e6), "h_rms": (1e-9, 1e-5),
         "hurst": (0.1, 0.95), "r_star": (1e-6, 1e-1)}

INDEX_CASES = [
    case("fig2"),
    case("fig4"),
    case("fig3", model="exact", moments="truncated"),
    case("fig1", moments="truncated"),
    case("fig2", sweep=("hurst", 0.3, 0.9)),
]
MAP_CASES = [
    (case("fig2"), None),
    (case("fig4"), None),
    (case("fig2", model="exact", moments="truncated", size_effect=True), "h_rms"),
    (case("fig1"), None),
]
LOAD_CASES = [
    case("fig2"),
    case("fig4"),
    case("fig2", model="exact"),
    case("fig3", model="exact", moments="truncated"),
]
INDEX_POINTS, LOAD_POINTS, MAP_GRID = 41, 41, (12, 7)


def header(ad, cases, columns_doc):
    lines = [h.replace(ref.SCRIPT, SCRIPT) for h in ref.header_common(ad)]
    lines += columns_doc
    for k, c in enumerate(cases):
        lines.append("# case %d: %s" % (k, " ".join(c)))
    return lines


def write(name, lines, cols, rows):
    ref.OUT_DIR = OUT_DIR
    ref.write_file(name, lines, cols, rows)


def write_view(name, ad, names, doc, cols, rows):
    """A view's table: the common header, its column notes, its cases."""
    write(name, header(ad, names, doc), cols, rows)


def gen_indices():
    ad = ref.Adaptive()
    rows, names = [], []
    for k, (args, s) in enumerate(INDEX_CASES):
        names.append(args + ["--view", "indices", "--points", str(INDEX_POINTS)])
        axis, a, b = s["sweep"]
        for x in grid(axis, a, b, INDEX_POINTS):
            p = dict(s["params"], **{axis: x})
            vals = ad(lambda p=p: indices_row(p, s["moments"]))
            rows.append([str(k), ref.fmt_in(x)] + [ref.fmt_out(v) for v in vals])
    doc = [
        "# columns: case; x = the swept value; then as in params.csv (gen_reference.py,",
        "#   gen_asymptotic.py) under the case's moments: psi_gw, psi_p, psi_star,",
        "#   psi_star_asymptotic (eq. 13, empty when r_star = 0), hardness_ratio = H_y/H0.",
    ]
    write_view("views_indices.csv", ad, names, doc,
               "case,x,psi_gw,psi_p,psi_star,psi_star_asymptotic,hardness_ratio", rows)


def gen_map():
    ad = ref.Adaptive()
    rows, names = [], []
    cols, nrows = MAP_GRID
    for k, ((args, s), y_axis) in enumerate(MAP_CASES):
        x_axis, xa, xb = s["sweep"]
        if y_axis is None:
            y_axis = "zeta" if x_axis == "h0_over_e" else "h0_over_e"
        extra = ["--map-y", y_axis.replace("_", "-")] if y_axis != "h0_over_e" else []
        names.append(args + ["--view", "map", "--grid", "%dx%d" % MAP_GRID] + extra)
        ya, yb = MAP_Y[y_axis]
        for y in grid(y_axis, ya, yb, nrows):
            for x in grid(x_axis, xa, xb, cols):
                p = dict(s["params"], **{y_axis: y})
                p[x_axis] = x
                vals = ad(lambda p=p: map_cell(p, s))
                rows.append([str(k), ref.fmt_in(x), ref.fmt_in(y)]
                            + [ref.fmt_out(v) for v in vals])
    doc = [
        "# columns: case; x = the swept value, y = the map's y value (rows from the",
        "#   bottom, x fastest); psi = the index in use (psi_star with the size effect,",
        "#   psi_p without); elastic, plastic, total = the case's model's initial slopes",
        "#   at psi (slopes.csv's formulas); plastic_share = plastic/total (0 where total = inf).",
    ]
    write_view("views_map.csv", ad, names, doc,
               "case,x,y,psi,elastic,plastic,total,plastic_share", rows)


def gen_load():
    ad = ref.Adaptive()
    rows, names = [], []
    for k, (args, s) in enumerate(LOAD_CASES):
        names.append(args + ["--view", "load", "--points", str(LOAD_POINTS)])
        p = s["params"]
        for i in range(LOAD_POINTS):
            rho = 1.0 if i == LOAD_POINTS - 1 else i / (LOAD_POINTS - 1)

            def f(rho=rho):
                psi = psi_in_use(p, s["moments"], s["size_effect"])
                return load_row(psi, s["model"], rho)
            vals = ad(f)
            rows.append([str(k), ref.fmt_in(rho)] + [ref.fmt_out(v) for v in vals])
    doc = [
        "# columns: case; load = pbar/H (H the hardness in use); elastic, plastic, total =",
        "#   A/A0 of the case's model (areas.csv's formulas) at the index in use of the",
        "#   case's parameters; 0 at load 0.",
    ]
    write_view("views_load.csv", ad, names, doc, "case,load,elastic,plastic,total", rows)


CLAIM_CASES = [
    case("fig1"),
    case("fig2"),
    case("fig3"),
    case("fig4"),
    # fig3 on the truncated moments: the curve starts at infinity (psi = 0 at
    # zeta = 1) and turns later
    case("fig3", moments="truncated"),
    # the exact model: fig1's shallow minimum of the closed form is gone
    case("fig1", model="exact"),
]
CLAIM_SAMPLES = 256


def claim_roots(s):
    """[(kind, rising, at, value)]: kind 0 = plastic share crosses 1/2, kind 1 =
    the index in use crosses 1 (value = the level), kind 2 = a local minimum of
    the total slope (value = the slope there). Brackets from 256 samples of the
    sweep; each crossing by bisection in ln x, each minimum as the root of
    d S_tot / d ln x (mpmath.diff), also by bisection."""
    axis, a, b = s["sweep"]
    assert axis in LOG_AXES

    def at(x):
        return dict(s["params"], **{axis: x})

    def share(x):
        psi = psi_in_use(at(x), s["moments"], s["size_effect"])
        el, pl, tot = slopes(s["model"], psi)
        return (mpf(0) if mpmath.isinf(tot) else pl / tot) - mpf(1) / 2

    def index(x):
        return psi_in_use(at(x), s["moments"], s["size_effect"]) - 1

    def total(x):
        psi = psi_in_use(at(x), s["moments"], s["size_effect"])
        return slopes(s["model"], psi)[2]

    def bisect(g, lo, hi):
        neg_lo = g(lo) < 0
        assert (g(hi) < 0) != neg_lo
        for _ in range(400):
            mid = (lo + hi) / 2
            if (g(mid) < 0) == neg_lo:
                lo = mid
            else:
                hi = mid
            if hi - lo < mpf(10) ** -40:
                break
        return (lo + hi) / 2

    out = []
    xs = grid(axis, a, b, CLAIM_SAMPLES)
    for kind, level, f in ((0, mpf(1) / 2, share), (1, mpf(1), index)):
        vs = [f(mpf(x)) for x in xs]
        for i in range(len(xs) - 1):
            if (vs[i] < 0) == (vs[i + 1] < 0):
                continue
            u = bisect(lambda u: f(mpmath.exp(u)), mpmath.log(xs[i]), mpmath.log(xs[i + 1]))
            out.append((kind, 1 if vs[i] < 0 else 0, mpmath.exp(u), level))
    vs = [total(mpf(x)) for x in xs]
    for i in range(1, len(xs) - 1):
        if not (vs[i - 1] > vs[i] <= vs[i + 1]):
            continue
        slope = lambda u: mpmath.diff(lambda w: total(mpmath.exp(w)), u)  # noqa: E731
        u = bisect(slope, mpmath.log(xs[i - 1]), mpmath.log(xs[i + 1]))
        out.append((2, 0, mpmath.exp(u), total(mpmath.exp(u))))
    return out


def gen_claims():
    rows, names = [], []
    for k, (args, s) in enumerate(CLAIM_CASES):
        names.append(args)
        with mpmath.workdps(60):
            roots = claim_roots(s)
        with mpmath.workdps(100):
            again = claim_roots(s)
        assert len(roots) == len(again)
        for (kind, rising, x, v), (_, _, y, w) in zip(roots, again):
            assert abs(x / y - 1) < mpf(10) ** -30, (args, x, y)
            assert abs(v / w - 1) < mpf(10) ** -30, (args, v, w)
            rows.append([str(k), str(kind), str(rising), ref.fmt_out(y), ref.fmt_out(w)])
    lines = [
        "# generator: %s (python3 %s from the repository root)" % (SCRIPT, SCRIPT),
        "# mpmath %s; model: docs/model.md" % mpmath.__version__,
        "# precision: each root by bisection in ln x to 1e-40 at 60 and at 100 digits,",
        "#   the two agreeing to 1e-30; printed from the 100-digit run, 25 digits.",
        "# columns: case (the export arguments below: a preset with its own model, moments",
        "#   and size effect, or overrides); kind 0 = the plastic share S_pl/S_tot crosses",
        "#   1/2, kind 1 = the index in use (psi_star with the size effect, psi_p without)",
        "#   crosses 1, kind 2 = the total slope S_tot (normalized by the hardness in use) has",
        "#   a local minimum: the root of d S_tot / d ln x (mpmath.diff); rising = 1 when",
        "#   the quantity rises through the level (0 for a minimum); at = the swept value",
        "#   there; value = the level (1/2, 1) or the total slope at the minimum. Crossings",
        "#   and minima are bracketed by 256 log-spaced samples of the sweep (ends included).",
    ]
    for k, c in enumerate(names):
        lines.append("# case %d: %s" % (k, " ".join(c)))
    write("views_claims.csv", lines, "case,kind,rising,at,value", rows)


def quoted_values():
    """[(what, x, value)]: the numbers the README and the help quote."""
    fig2 = lambda z, moments: indices_row(dict(FIG2, zeta=z), moments)[1]  # noqa: E731
    out = [
        ("psi_p of fig2 at zeta = 128, asymptotic moments", 128, fig2(128.0, "asymptotic")),
        ("psi_p of fig2 at zeta = 128, truncated moments", 128, fig2(128.0, "truncated")),
    ]
    psi = fig2(1000.0, "asymptotic")
    el, pl, tot = ref.closed_slopes(psi)
    out.append(("fig2's plastic share S_pl/S_tot at zeta = 1000 (closed form, asymptotic)",
                1000, pl / tot))
    out.append(("the same with Persson's elastic slope: (S_tot - S_P)/S_tot", 1000,
                (tot - ref.persson_slope(psi)) / tot))
    # the closed form's total slope dips below 1: the root of dS_tot/dpsi
    d = lambda u: mpmath.diff(lambda w: ref.closed_slopes(mpmath.exp(w))[2], u)  # noqa: E731
    lo, hi = mpmath.log(mpf("1.2")), mpmath.log(mpf("1.7"))
    assert d(lo) < 0 < d(hi)
    for _ in range(400):
        mid = (lo + hi) / 2
        if d(mid) < 0:
            lo = mid
        else:
            hi = mid
        if hi - lo < mpf(10) ** -40:
            break
    dip = mpmath.exp((lo + hi) / 2)
    out.append(("psi where the closed form's total slope is least", 0, dip))
    out.append(("the closed form's least total slope", 0, ref.closed_slopes(dip)[2]))
    return out


def gen_quoted():
    with mpmath.workdps(60):
        rows = quoted_values()
    with mpmath.workdps(100):
        again = quoted_values()
    lines = [
        "# generator: %s (python3 %s from the repository root)" % (SCRIPT, SCRIPT),
        "# mpmath %s; model: docs/model.md" % mpmath.__version__,
        "# precision: at 60 and at 100 digits, the two agreeing to 1e-30 (roots by",
        "#   bisection to 1e-40 in ln psi); printed from the 100-digit run, 25 digits.",
        "# columns: id (below), x = the swept value it is at (0: none), value.",
    ]
    out = []
    for k, ((what, x, v), (_, _, w)) in enumerate(zip(rows, again)):
        assert abs(v / w - 1) < mpf(10) ** -30, (what, v, w)
        lines.append("# id %d: %s" % (k, what))
        out.append([str(k), str(x), ref.fmt_out(w)])
    write("views_quoted.csv", lines, "id,x,value", out)


def check():
    """The grid rule against hand values, and one index against docs/model.md."""
    assert grid("zeta", 1.0, 1e4, 5) == [1.0, 10.0, 100.0, 1000.0, 1e4]
    assert grid("hurst", 0.1, 0.9, 3)[1] == 0.5
    with mpmath.workdps(60):
        psi_p = indices_row(dict(FIG2, zeta=128.0), "asymptotic")[1]
        assert abs(psi_p / mpf("0.522964172217328") - 1) < mpf(10) ** -14, psi_p


def main():
    mpmath.mp.dps = ref.BASE_DPS
    check()
    gen_indices()
    gen_map()
    gen_load()
    gen_claims()
    gen_quoted()


if __name__ == "__main__":
    main()
