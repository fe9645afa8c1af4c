//! The contact view's readout: the simulation and the theory at the chosen
//! load (the load plot), or at the largest ζ solved (`b`, `i`), each
//! number with its spread over the seeds, in the longest form that fits.

use ratatui::text::Span;

use crate::contact::Stat;
use crate::physical::print::{fmt_num, load_text};
use crate::tui::contact::{load_value, ContactPane, Plot};
use crate::tui::glyphs::Glyphs;

/// `v` (a fraction) in per cent with three significant digits.
pub fn pct(v: f64) -> String {
    let p = v * 100.0;
    if !p.is_finite() {
        "—".into()
    } else if p == 0.0 {
        "0".into()
    } else if p >= 10.0 {
        format!("{p:.1}")
    } else if p >= 1.0 {
        format!("{p:.2}")
    } else {
        fmt_num(p)
    }
}

/// A mean and its spread in per cent, the spread to the mean's last
/// digit ("2.10 ± 0.10"; "0.0312 ± 0.0040").
pub fn pct_pm(mean: f64, sd: f64) -> String {
    let m = pct(mean);
    let decimals = m.split_once('.').map_or(0, |(_, d)| d.len());
    if !sd.is_finite() {
        return m;
    }
    format!("{m} ± {:.*}", decimals, 100.0 * sd)
}

/// A plastic share in per cent: whole from 10 %, one decimal below ("0"
/// exactly none, "<0.1" a trace).
pub fn share_pct(plastic: f64, total: f64) -> String {
    if total <= 0.0 {
        return "—".into();
    }
    let s = 100.0 * plastic / total;
    if s == 0.0 {
        "0".into()
    } else if s < 0.05 {
        "<0.1".into()
    } else if s >= 9.95 {
        format!("{s:.0}")
    } else {
        format!("{s:.1}")
    }
}

/// A share (a fraction) over the seeds in per cent, with its sd where
/// there are several: "8.2 ± 2.3", "0.31 ± 0.12", "0".
pub fn share_pm(st: &Stat) -> String {
    let m = 100.0 * st.mean;
    let digits = if m == 0.0 || m >= 9.95 {
        if m == 0.0 {
            return if st.n > 1 && st.sd > 0.0 {
                format!("0 ± {}", fmt_num(100.0 * st.sd))
            } else {
                "0".into()
            };
        }
        0
    } else if m >= 0.995 {
        1
    } else {
        2
    };
    if st.n > 1 && st.sd.is_finite() {
        format!("{m:.digits$} ± {:.digits$}", 100.0 * st.sd)
    } else {
        format!("{m:.digits$}")
    }
}

/// A slope over the seeds: "2.50 ± 0.26".
fn slope_pm(st: &Stat) -> String {
    let v = |x: f64| {
        if x == 0.0 {
            "0".to_string()
        } else {
            fmt_num(x)
        }
    };
    if st.n > 1 && st.sd.is_finite() {
        format!("{} ± {}", v(st.mean), v(st.sd))
    } else {
        v(st.mean)
    }
}

/// The readout: one line, the longest form that fits `width`, or where
/// none does (an 80-column screen leaves the panel 46) two, the
/// simulation's and the theory's, so that nothing is cut. `h` names the
/// load's unit (H0, H_y, or H_y(R_s) under a per-node hardness: H alone is
/// the Hurst exponent). The flag: the line is an error.
pub fn readout(pane: &ContactPane, width: usize, g: Glyphs, h: &str) -> (Vec<String>, bool) {
    if pane.plot == Plot::Slopes {
        return fit(slopes_forms(pane), width, g, false);
    }
    let at = load_text(load_value(pane.load));
    let theory = pane
        .theory
        .at_load
        .map(|a| (pct(a.total), share_pct(a.plastic, a.total)));
    let sim = match pane.chosen() {
        _ if pane.why_not.is_some() => Err("-".into()),
        // Over the seeds solved so far: mean ± sample standard deviation,
        // the plastic share each seed's own.
        Some(Ok(_)) => match (pane.at_load(pane.load), pane.share_at_load(pane.load)) {
            (Some([a, _, _]), Some(s)) if a.n > 1 => Ok((pct_pm(a.mean, a.sd), share_pm(&s))),
            (Some([a, _, p]), _) => Ok((pct(a.mean), share_pct(p.mean, a.mean))),
            _ => Err(String::new()),
        },
        Some(Err(e)) => Err(e.clone()),
        None => Err(String::new()),
    };
    let th_full = match &theory {
        Some((a, s)) => format!("theory: {a} %, {s} % plastic"),
        None => "theory: —".into(),
    };
    let th_short = match &theory {
        Some((a, s)) => format!("th. {a}% {s}%pl"),
        None => "th. —".into(),
    };
    // Under a per-node hardness the load's unit is not the cap: the
    // longest forms name the caps in use.
    let caps = match pane.sampling.hardness {
        crate::contact::Hardness::Global => None,
        crate::contact::Hardness::Asperity => Some("each asperity's H_y"),
        crate::contact::Hardness::Summit => Some("each summit's H_y"),
    };
    let (forms, split): (Vec<String>, Vec<String>) = match &sim {
        Ok((a, s)) => (
            caps.into_iter()
                .flat_map(|c| {
                    [
                        format!(
                            "simulation at p̄ = {at} {h}, caps {c}: contact {a} %, {s} % at \
                             its cap · {th_full}"
                        ),
                        format!("p̄ = {at} {h}, caps {c}: sim {a} %, {s} % at its cap · {th_full}"),
                    ]
                })
                .chain([
                    format!("simulation at p̄ = {at} {h}: contact {a} %, {s} % plastic · {th_full}"),
                    format!("p̄ = {at} {h}: sim {a} %, {s} % plastic · {th_full}"),
                    format!(
                        "{at} {h}: sim {}% {}%pl · {th_short}",
                        a.replace(" ± ", "±"),
                        s.replace(" ± ", "±")
                    ),
                ])
                .collect(),
            vec![
                format!("p̄ = {at} {h} · sim {a} %, {s} % plastic"),
                format!(
                    "p̄ = {at} {h} · sim {}%, {}% pl",
                    a.replace(" ± ", "±"),
                    s.replace(" ± ", "±")
                ),
                format!(
                    "{at} {h} · sim {}%, {}% pl",
                    a.replace(" ± ", "±"),
                    s.replace(" ± ", "±")
                ),
            ],
        ),
        Err(e) if e.is_empty() => (
            vec![
                format!("simulation at p̄ = {at} {h}: solving… · {th_full}"),
                format!("{at} {h}: sim … · {th_short}"),
            ],
            vec![format!("p̄ = {at} {h} · sim solving…")],
        ),
        Err(e) if e == "-" => (
            vec![
                format!("at p̄ = {at} {h}: no simulation · {th_full}"),
                format!("{at} {h}: no sim. · {th_short}"),
            ],
            vec![format!("p̄ = {at} {h} · no simulation")],
        ),
        Err(e) => (vec![format!("at p̄ = {at} {h}: {e}")], vec![]),
    };
    let error = matches!(sim, Err(ref e) if !e.is_empty() && e != "-");
    let text = |f: &String| g.text(f).into_owned();
    let fits = |s: &String| Span::raw(s.as_str()).width() <= width;
    let first = |forms: &[String]| forms.iter().map(text).find(|s| fits(s));
    // The caps named on one line, else on the first of two, before a
    // line that leaves them to the title.
    let named = caps.map_or(0, |_| 2).min(forms.len());
    if let Some(line) = first(&forms[..named]) {
        return (vec![line], error);
    }
    if let (Some(c), Ok((a, s))) = (caps, &sim) {
        let pair = [
            format!("p̄ = {at} {h}, caps {c}: sim {a} %, {s} % at its cap"),
            format!("p̄ = {at} {h}, caps {c}: {a} %, {s} % at cap"),
        ];
        if let (Some(a), Some(b)) = (first(&pair), first(&[th_full.clone(), th_short.clone()])) {
            return (vec![a, b], error);
        }
    }
    if let Some(line) = first(&forms[named..]) {
        return (vec![line], error);
    }
    if let (Some(a), Some(b)) = (first(&split), first(&[th_full.clone(), th_short.clone()])) {
        return (vec![a, b], error);
    }
    // Nothing fits (a very narrow panel): the shortest, cut by the screen.
    let last = forms.last().map(text).unwrap_or_default();
    (vec![last], error)
}

/// The first of `forms` that fits `width` (a pair of lines if the last
/// form is two), else the shortest, cut.
fn fit(forms: Vec<Vec<String>>, width: usize, g: Glyphs, error: bool) -> (Vec<String>, bool) {
    let text = |f: &String| g.text(f).into_owned();
    let fits = |s: &String| Span::raw(s.as_str()).width() <= width;
    for f in &forms {
        let lines: Vec<String> = f.iter().map(text).collect();
        if lines.iter().all(fits) {
            return (lines, error);
        }
    }
    let last = forms
        .last()
        .and_then(|f| f.first())
        .map(text)
        .unwrap_or_default();
    (vec![last], error)
}

/// The `i` plot's readout: the slopes at the largest ζ solved, the
/// simulation's (mean ± sd over the seeds, its plastic share) beside the
/// theory's.
fn slopes_forms(pane: &ContactPane) -> Vec<Vec<String>> {
    if let Some(why) = &pane.why_not {
        return vec![vec![format!("no simulation: {why}")]];
    }
    let at = (0..pane.zetas.len())
        .rev()
        .find_map(|k| pane.slopes_at(k).map(|s| (k, s)));
    let Some((k, [_, pl, tot])) = at else {
        return vec![vec!["initial slopes: solving the light loads…".into()]];
    };
    let z = crate::physical::print::fmt_short(rough_model::Axis::Zeta, pane.zetas[k]);
    let share = |p: f64, t: f64| {
        if t > 0.0 {
            share_pct(p, t)
        } else {
            "—".into()
        }
    };
    let sim_share = share(pl.mean, tot.mean);
    let th = pane
        .theory
        .curves
        .first()
        .zip(pane.theory.curves.get(2))
        .and_then(|(t, p)| {
            let x = pane.zetas[k].log10();
            let near = |c: &Vec<(f64, f64)>| {
                c.iter()
                    .min_by(|a, b| (a.0 - x).abs().total_cmp(&(b.0 - x).abs()))
                    .map(|p| 10f64.powf(p.1))
            };
            Some((near(t)?, near(p).unwrap_or(0.0)))
        });
    let th_text = match th {
        Some((t, p)) => format!(
            "theory {}, plastic {} ({} %)",
            fmt_num(t),
            fmt_num(p),
            share(p, t)
        ),
        None => "theory —".into(),
    };
    let sim = format!(
        "sim total {}, plastic {} ({sim_share} %)",
        slope_pm(&tot),
        slope_pm(&pl)
    );
    vec![
        vec![format!("initial slopes at ζ = {z}: {sim} · {th_text}")],
        vec![format!("ζ = {z}: {sim} · {th_text}")],
        vec![format!("slopes at ζ = {z}: {sim}"), th_text.clone()],
        vec![
            format!("ζ {z}: sim {} ({sim_share}%pl)", slope_pm(&tot)),
            th_text,
        ],
    ]
}

/// The row under the load plot's readout: κ at the lightest load (`h` its
/// unit), A/A0 over p̄/(E* h′) with its spread over the seeds, beside
/// Persson's √(8/π), and the theory's split; the longest form that fits.
pub fn kappa_row(
    pane: &ContactPane,
    model: rough_model::Model,
    (width, h): (usize, &str),
    g: Glyphs,
) -> Option<String> {
    let kappa = match pane.kappa() {
        Some(k) if k.n > 1 && k.sd.is_finite() => format!("{:.2} ± {:.2}", k.mean, k.sd),
        Some(k) => format!("{:.2}", k.mean),
        None => "…".into(),
    };
    let persson = crate::contact::PERSSON_KAPPA;
    let (split, short) = match model {
        rough_model::Model::ClosedForm => {
            ("the closed form's image solution (App. A)", "App. A image")
        }
        rough_model::Model::Exact => ("the exact two-barrier solution", "exact"),
    };
    let at = load_text(load_value(0));
    let forms = [
        format!(
            "κ = A/A0 ÷ p̄/(E* h′) at p̄ = {at} {h}: {kappa} (Persson √(8/π) = {persson:.2}) · \
             theory's split: elastic = {split}'s mass on [0, H]"
        ),
        format!(
            "κ at p̄ = {at} {h}: {kappa} (Persson √(8/π) = {persson:.2}) · theory's split: {split}"
        ),
        format!("κ at p̄ = {at} {h}: {kappa} (Persson √(8/π) = {persson:.2}) · split: {short}"),
        format!("κ at {at} {h}: {kappa} (Persson {persson:.2}) · split: {short}"),
        format!("κ({at}) {kappa} (Persson {persson:.2}) · {short}"),
        format!("κ({at}) {kappa} (Persson {persson:.2})"),
    ];
    let text = |f: &String| g.text(f).into_owned();
    forms
        .iter()
        .map(text)
        .find(|s| Span::raw(s.as_str()).width() <= width)
}

/// The `b` plot's row over its chart: each set's plastic share (mean ± sd
/// over the seeds in) at the largest ζ every set has solved, so that
/// differences of a tenth of a per cent read as numbers; the longest form
/// that fits `width`.
pub fn share_row(pane: &ContactPane, width: usize, g: Glyphs) -> String {
    let n = pane.seeds_asked();
    let over = if n > 1 {
        format!("mean ± sd of {n} seeds")
    } else {
        "one seed".to_string()
    };
    let at = (0..pane.zetas.len()).rev().find_map(|k| {
        let shares: Option<Vec<Stat>> = (0..pane.sets.len())
            .map(|set| pane.share_at(set, k))
            .collect();
        shares.map(|s| (k, s))
    });
    let mut forms = vec![];
    if let Some((k, shares)) = at {
        // The seeds in at that ζ (the fewest over the sets).
        let over = match shares.iter().map(|s| s.n).min().unwrap_or(0) {
            1 => "one seed so far".to_string(),
            m if m < n => format!("mean ± sd of {m} of {n} seeds"),
            m => format!("mean ± sd of {m} seeds"),
        };
        let z = crate::physical::print::fmt_short(rough_model::Axis::Zeta, pane.zetas[k]);
        let each: Vec<String> = pane
            .sets
            .iter()
            .zip(&shares)
            .map(|(set, st)| format!("{} {} %", super::charts::set_name(set), share_pm(st)))
            .collect();
        let each = each.join(" · ");
        forms.push(format!(
            "plastic share at ζ = {z} ({over}, of the area at the load, not an initial \
             slope): {each} · b: vs load"
        ));
        forms.push(format!("at ζ = {z}, {over}: {each} · b: vs load"));
        forms.push(format!("ζ = {z}: {each}"));
    }
    forms.push(format!(
        "simulation: {over}, the share of the area at the load (not an initial slope) · b: vs \
         load"
    ));
    forms.push(format!("simulation: {over} at the load · b: vs load"));
    forms.push(format!("{over} · b: vs load"));
    let text = |f: &String| g.text(f).into_owned();
    forms
        .iter()
        .map(text)
        .find(|s| Span::raw(s.as_str()).width() <= width)
        .unwrap_or_default()
}
