//! The contact simulation's pictures (`export --view contact|contact-sweep`)
//! in the style of every other picture: the scene under the chart and in
//! `<desc>`, powers of ten on the log axes, the points whole inside the
//! axes, the legend where nothing is drawn, the hardness named H0 or H_y.
//! The numbers come from the simulation (`crate::contact`, through
//! export): this module only draws them.

use plotters::prelude::*;

use super::plot::{self, Mark, Series};
use super::{render, under, Scale, Stroke, ELASTIC, PLASTIC, TOTAL};
use crate::physical::short_number;
use crate::scene::State;

/// The contact view's numbers as its picture draws them.
#[derive(Clone, Debug, Default)]
pub struct ContactLoads {
    /// The solved surface in words: "1024 × 1024 nodes, seed 1".
    pub surface: String,
    /// The index in use (Ψ* with the size effect, Ψ_P without), at which
    /// the theory's areas are computed.
    pub psi: f64,
    /// The loads p̄/H_use.
    pub p_over_h: Vec<f64>,
    /// The simulated A/A0 at each load: total, elastic, plastic.
    pub area: [Vec<f64>; 3],
    /// Their standard deviations over several surfaces, where there are
    /// several.
    pub sd: Option<[Vec<f64>; 3]>,
    /// The theory's areas (total, elastic, plastic) at `theory_p`.
    pub theory_p: Vec<f64>,
    pub theory: [Vec<f64>; 3],
    /// Each asperity capped at its own hardness (`--hardness asperity`)
    /// instead of one cap.
    pub per_asperity: bool,
}

/// The ζ sweep's numbers as its picture draws them.
#[derive(Clone, Debug, Default)]
pub struct ContactSweep {
    /// The solved surfaces in words: "seed 1, 8 nodes per shortest
    /// wavelength".
    pub surface: String,
    /// The load of every point: p̄/H0 (`load_in_h0`), or p̄/H_use at
    /// each ζ.
    pub load: f64,
    pub load_in_h0: bool,
    /// Where the hardness applies, in words ("H_y(R_s) at every node", "each
    /// node its summit's H_y"), for the caption.
    pub hardness: String,
    pub zeta: Vec<f64>,
    /// The simulated plastic share A_pl/A, ± `sd` where given.
    pub share: Vec<f64>,
    pub sd: Option<Vec<f64>>,
    /// The theory's plastic share at `theory_zeta`.
    pub theory_zeta: Vec<f64>,
    pub theory_share: Vec<f64>,
}

/// The index in use by its name: "Ψ_P = 0.4901".
fn psi_text(state: &State, psi: f64) -> String {
    let name = state.index_name();
    format!("{name} = {}", short_number(psi))
}

/// What the contact view spans, in full (its pictures' `<desc>` and its
/// CSV's `#` lines): "contact = p_over_h = pbar/H0 from 0.001 to 1, 13
/// loads (log-spaced)".
pub fn contact_span(state: &State, loads: &[f64]) -> String {
    let full = |v: f64| crate::physical::csv_number::format(v);
    format!(
        "contact = p_over_h = pbar/{} from {} to {}, {} loads (log-spaced)",
        state.hardness_name(),
        full(loads.first().copied().unwrap_or(f64::NAN)),
        full(loads.last().copied().unwrap_or(f64::NAN)),
        loads.len()
    )
}

/// What the ζ sweep spans, in full: its load fixed over H0 (the same at
/// every ζ, `in_h0`) or over the hardness in use at each ζ.
pub fn sweep_span(state: &State, load: f64, in_h0: bool) -> String {
    let at = crate::physical::csv_number::format(load);
    let load = if in_h0 {
        format!("at p_over_h0 = pbar/H0 = {at} (the same load at every zeta)")
    } else {
        format!(
            "at p_over_h = pbar/{} = {at} (the hardness in use at each zeta)",
            state.hardness_name()
        )
    };
    format!(
        "contact-sweep = zeta = 1, 2, 4, …, 128 (a measured map: those it resolves), each on \
         its own grid, {load}"
    )
}

/// The simulation's points: x, the three parts' means and their sds.
type Points<'a> = (&'a [f64], &'a [Vec<f64>; 3], Option<&'a [Vec<f64>; 3]>);

/// The three parts of a contact picture (total, elastic, plastic in some
/// order): their names and colours.
struct Parts {
    names: [&'static str; 3],
    colours: [RGBColor; 3],
}

impl Parts {
    /// The theory's curves of the parts, `y[k]` at `x`, as lines.
    fn theory<'a>(&self, x: &'a [f64], y: &'a [Vec<f64>; 3]) -> Vec<Series<'a>> {
        (0..3)
            .map(|k| Series {
                label: format!("{}: theory", self.names[k]),
                colour: self.colours[k],
                mark: Mark::Line(Stroke::Solid),
                x,
                y: &y[k],
                sd: None,
            })
            .collect()
    }

    /// The simulation's points of the parts (`y[k]` at `x`, ± `sd[k]`
    /// where given) as dots, in `dots`' order of (part, radius); `note(k)`
    /// ends part k's label.
    fn points<'a>(
        &self,
        (x, y, sd): Points<'a>,
        dots: [(usize, u32); 3],
        note: impl Fn(usize) -> &'static str,
    ) -> Vec<Series<'a>> {
        let sd_words = if sd.is_some() { " (mean ± sd)" } else { "" };
        dots.into_iter()
            .map(|(k, r)| Series {
                label: format!("{}: simulation{sd_words}{}", self.names[k], note(k)),
                colour: self.colours[k],
                mark: Mark::Dots(r),
                x,
                y: &y[k],
                sd: sd.map(|s| &s[k][..]),
            })
            .collect()
    }
}

/// A/A0 against p̄/H_use, both log: the simulation's points beside the
/// theory's curves.
pub fn render_contact(state: &State, d: &ContactLoads) -> anyhow::Result<String> {
    let h = state.hardness_name();
    let sim = d.area.iter().flatten();
    // The floor: the least simulated area or theoretical total; the
    // theory's elastic and plastic parts are cut there.
    let (lo, hi) = super::positive_span(sim.chain(&d.theory[0]));
    let (plo, phi) = super::positive_span(d.p_over_h.iter().chain(&d.theory_p));
    let x = Scale::padded(true, plo, phi, 0.03, format!("load p̄/{h}"));
    let y = Scale::padded(true, lo, hi, 0.03, "contact area A/A0".into());
    let parts = Parts {
        names: ["total", "elastic", "plastic"],
        colours: [TOTAL, ELASTIC, PLASTIC],
    };
    let mut series = parts.theory(&d.theory_p, &d.theory);
    // The total's dots larger, under the elastic ones: where the two
    // coincide (light loads) both show.
    let dots = [(0, 5), (1, 3), (2, 3)];
    series.extend(parts.points((&d.p_over_h, &d.area, d.sd.as_ref()), dots, |_| ""));
    let what = "contact area against the load";
    let title = super::title(state, what);
    let draw = |area: &super::Area, room| plot::draw(area, &title, (&x, &y), &series, room);
    let short = format!(
        "p̄/{h} {} … {} · {}",
        short_number(plo),
        short_number(phi),
        d.surface
    );
    let cap = if d.per_asperity {
        "each asperity's pressure capped at its own hardness H0 √(1 + R*/(1.2 R)), R its \
         curvature radius; loads beyond what the asperities carry are not solved"
            .to_string()
    } else {
        format!("the pressure capped at {h}")
    };
    let caption = format!(
        "Contact area against the load over the hardness in use {h}: the boundary-element \
         simulation of the scene's surface (points: an elastic–perfectly-plastic half-space, \
         {cap}) beside the theory's finite-load areas (lines, the {} model at {}).",
        state.model.label(),
        psi_text(state, d.psi)
    );
    let lines = under(state, Some(short), &caption);
    let mut desc = crate::figure::scene_text::full_lines_of(
        state,
        "contact",
        contact_span(state, &d.p_over_h),
    );
    desc.push(format!("simulation = {}", d.surface));
    render(&draw, &lines, &format!("{} — {what}", state.name), &desc)
}

/// The plastic share of the contact area against ζ at one load: the
/// simulation's points beside the theory's line.
pub fn render_contact_sweep(state: &State, d: &ContactSweep) -> anyhow::Result<String> {
    let h = state.hardness_name();
    let (zlo, zhi) = super::positive_span(d.zeta.iter().chain(&d.theory_zeta));
    let x = Scale::padded(true, zlo, zhi, 0.03, "ζ = q1/q0".into());
    let y = Scale::padded(false, 0.0, 1.0, 0.04, "plastic share A_pl/A".into());
    let sd_words = if d.sd.is_some() { " (mean ± sd)" } else { "" };
    let series = [
        Series {
            label: "theory".into(),
            colour: PLASTIC,
            mark: Mark::Line(Stroke::Solid),
            x: &d.theory_zeta,
            y: &d.theory_share,
            sd: None,
        },
        Series {
            label: format!("simulation{sd_words}"),
            colour: PLASTIC,
            mark: Mark::Dots(5),
            x: &d.zeta,
            y: &d.share,
            sd: d.sd.as_deref(),
        },
    ];
    let load = short_number(d.load);
    let unit = if d.load_in_h0 { "H0" } else { h };
    let what = format!("plastic share against ζ at p̄ = {load} {unit}");
    let title = super::title(state, &what);
    let draw = |area: &super::Area, room| plot::draw(area, &title, (&x, &y), &series, room);
    let short = format!(
        "ζ {} … {} at p̄ = {load} {unit} · {}",
        short_number(zlo),
        short_number(zhi),
        d.surface
    );
    let hy = match (d.load_in_h0, state.size_effect) {
        (true, true) => {
            " (the same load at every ζ; H_y, the size-dependent hardness, grows with ζ)"
        }
        (true, false) => " (the same load at every ζ)",
        (false, true) => " (H_y the size-dependent hardness at each ζ: a load that grows with it)",
        (false, false) => "",
    };
    let caption = format!(
        "Plastic share of the contact area against the magnification ζ at p̄ = {load} \
         {unit}{hy}, a finite load (secants, not initial slopes): the boundary-element \
         simulation (points, each ζ on its own grid of at least 8 nodes per shortest \
         wavelength; the pressure capped at {}) beside the theory's finite-load areas at the \
         same load (line, the {} model).",
        d.hardness,
        state.model.label()
    );
    let lines = under(state, Some(short), &caption);
    let mut desc = crate::figure::scene_text::full_lines_of(
        state,
        "contact-sweep",
        sweep_span(state, d.load, d.load_in_h0),
    );
    desc.push(format!("simulation = {}", d.surface));
    render(&draw, &lines, &format!("{} — {what}", state.name), &desc)
}

/// The simulated initial slopes against ζ as their picture draws them.
#[derive(Clone, Debug, Default)]
pub struct ContactSlopes {
    /// The solved surfaces in words.
    pub surface: String,
    /// Where the hardness applies, in words.
    pub hardness: String,
    pub zeta: Vec<f64>,
    /// The simulated slopes (elastic, plastic, total), mean ± sd.
    pub slope: [Vec<f64>; 3],
    pub sd: Option<[Vec<f64>; 3]>,
    /// The theory's slopes (elastic, plastic, total) and Persson's elastic
    /// one at `theory_zeta`.
    pub theory_zeta: Vec<f64>,
    pub theory: [Vec<f64>; 3],
    pub persson: Vec<f64>,
}

/// The paper's figure (initial slopes against ζ, log–log) with the
/// simulation's points.
pub fn render_contact_slopes(state: &State, d: &ContactSlopes) -> anyhow::Result<String> {
    let h = state.hardness_name();
    let (zlo, zhi) = super::positive_span(d.zeta.iter().chain(&d.theory_zeta));
    let x = Scale::padded(true, zlo, zhi, 0.03, "ζ = q1/q0".into());
    let sim = d.slope.iter().flatten();
    let (_, hi) = super::positive_span(sim.clone().chain(&d.theory[0]).chain(&d.theory[2]));
    // The floor: four decades under the top, or the least point above it.
    let (lo, _) = super::positive_span(
        sim.chain(d.theory.iter().flatten())
            .filter(|v| **v >= hi * 1e-4),
    );
    let y = Scale::padded(true, lo, hi, 0.04, format!("initial slope {h}·dA/(A0·dp̄)"));
    let parts = Parts {
        names: ["elastic", "plastic", "total"],
        colours: [ELASTIC, PLASTIC, TOTAL],
    };
    let mut series = parts.theory(&d.theory_zeta, &d.theory);
    let psi = state.index_name();
    series.push(Series {
        label: format!("Persson elastic √(2/π)/{psi}"),
        colour: super::PERSSON,
        mark: Mark::Line(Stroke::Dashed),
        x: &d.theory_zeta,
        y: &d.persson,
        sd: None,
    });
    let none = |k: usize| {
        if d.slope[k].iter().any(|v| *v > 0.0) {
            ""
        } else {
            ", 0 everywhere: not on a log axis"
        }
    };
    let dots = [(2, 5), (0, 3), (1, 3)];
    series.extend(parts.points((&d.zeta, &d.slope, d.sd.as_ref()), dots, none));
    let what = "initial slopes against ζ, theory and simulation";
    let title = super::title(state, what);
    let draw = |area: &super::Area, room| plot::draw(area, &title, (&x, &y), &series, room);
    let short = format!(
        "ζ {} … {} · {}",
        short_number(zlo),
        short_number(zhi),
        d.surface
    );
    let caption = format!(
        "Initial slopes {h}·dA/(A0·dp̄) against ζ, the paper's quantity: the theory's (lines, \
         the {} model at {psi}) and the boundary-element simulation's (points, ζ ≤ 128: each \
         seed's areas at five light loads p̄/(E* h′) = 0.5 … 8·10⁻³ fitted by A = s·x + c·x² \
         through the origin over the four lightest, s the slope; the pressure capped at {}). \
         A plastic slope of 0 has no place on the log axis.",
        state.model.label(),
        d.hardness
    );
    let lines = under(state, Some(short), &caption);
    let mut desc = crate::figure::scene_text::full_lines_of(
        state,
        "contact-slopes",
        format!(
            "contact-slopes = zeta = {} (simulated), theory from {} to {}",
            d.zeta
                .iter()
                .map(|z| short_number(*z))
                .collect::<Vec<_>>()
                .join(", "),
            short_number(zlo),
            short_number(zhi)
        ),
    );
    desc.push(format!("simulation = {}", d.surface));
    render(&draw, &lines, &format!("{} — {what}", state.name), &desc)
}

/// The colours of the map's nodes: out of contact white, elastic grey,
/// at the hardness the paper's plastic blue.
pub(super) const NODE_ELASTIC: RGBColor = RGBColor(140, 140, 140);
