//! The numbers behind the indices, as data (`export --view moments`): per
//! cutoff ζ the band's upper wavevector q1 = ζ q0 and shortest wavelength
//! λ1 = 2π/q1, the profile moments m0, m2, m4 and what the model makes of
//! them — h_rms = √m0, h′ = √(2 m2), h″ = √(8 m4/3) and the summits' radius
//! R_s — on a measured surface (moments summed from its data, "from the PSD
//! up to ζ") or on the paper's power law (the state's moments convention);
//! and, as comment lines, the real-space Sq and Sdq (Rq and RΔq) and the
//! Hurst fit, or the power law's own parameters.

use rough_model::Axis;

use crate::scene::State;

/// The moments at `points` cutoffs ζ, log-spaced over the sweep when it is
/// over ζ, else from 1 to the state's ζ.
#[derive(Clone, Debug, PartialEq)]
pub struct MomentSeries {
    pub zeta: Vec<f64>,
    pub q1: Vec<f64>,
    pub lambda1: Vec<f64>,
    pub m0: Vec<f64>,
    pub m2: Vec<f64>,
    pub m4: Vec<f64>,
    pub h_rms: Vec<f64>,
    pub h_prime: Vec<f64>,
    pub h_dprime: Vec<f64>,
    pub r_s: Vec<f64>,
}

impl MomentSeries {
    pub fn of(state: &State, points: usize) -> anyhow::Result<MomentSeries> {
        let s = &state.sweep;
        let (from, to) = if s.axis() == Axis::Zeta {
            (s.from(), s.to())
        } else {
            (1.0, state.params.zeta())
        };
        let n = points.max(2);
        let roughness = state.roughness();
        let mut out = MomentSeries {
            zeta: Vec::with_capacity(n),
            q1: Vec::with_capacity(n),
            lambda1: Vec::with_capacity(n),
            m0: Vec::with_capacity(n),
            m2: Vec::with_capacity(n),
            m4: Vec::with_capacity(n),
            h_rms: Vec::with_capacity(n),
            h_prime: Vec::with_capacity(n),
            h_dprime: Vec::with_capacity(n),
            r_s: Vec::with_capacity(n),
        };
        for i in 0..n {
            let f = i as f64 / (n - 1) as f64;
            let z = if i == n - 1 {
                to
            } else {
                from * (to / from).powf(f)
            };
            let p = state
                .params
                .with(Axis::Zeta, z)
                .map_err(|e| anyhow::anyhow!("ζ = {z}: {e}"))?;
            let sp = roughness.surface(&p, state.moments).spectrum;
            out.zeta.push(z);
            out.q1.push(z * p.q0());
            out.lambda1.push(sp.lambda1);
            out.m0.push(sp.m0);
            out.m2.push(sp.m2);
            out.m4.push(sp.m4);
            out.h_rms.push(sp.h_rms_actual);
            out.h_prime.push(sp.rms_slope);
            out.h_dprime.push(sp.rms_curvature);
            out.r_s.push(sp.r_s);
        }
        Ok(out)
    }

    pub fn len(&self) -> usize {
        self.zeta.len()
    }

    pub fn is_empty(&self) -> bool {
        self.zeta.is_empty()
    }
}

/// What stands beside the moments, one line each (without `# `): the
/// real-space numbers and the Hurst fit of a measured surface, or the
/// paper's power law's parameters.
pub fn moment_comments(state: &State) -> Vec<String> {
    // Every digit: these are data (the shortest text that reads back).
    let n = |v: f64| format!("{v:?}");
    let mut out = vec![
        "columns: zeta (1), q1 (1/m), lambda1 (m), m0 (m^2), m2 (1), m4 (1/m^2), h_rms (m), \
         h_prime (1), h_dprime (1/m), r_s (m)"
            .to_string(),
    ];
    let Some(src) = &state.surface else {
        let p = &state.params;
        out.push(format!(
            "the paper's power law: H = {}, h_rms = {} m, q0 = {} /m, {} moments",
            n(p.hurst()),
            n(p.h_rms()),
            n(p.q0()),
            state.moments.label()
        ));
        return out;
    };
    out.push(
        "h_rms, h_prime, h_dprime: from the PSD up to zeta (after the detrend and window)"
            .to_string(),
    );
    if let Some(r) = src.measured.real {
        let (a, b) = r.names();
        out.push(format!(
            "{a} = {} m, {b} = {} (real space, after the detrend, no window)",
            n(r.rms_height),
            n(r.rms_slope)
        ));
        let [sa, ssk, sku, sz] = r.amplitude_names();
        let p = r.amplitude;
        out.push(format!(
            "{sa} = {} m, {ssk} = {}, {sku} = {}, {sz} = {} m (the same heights)",
            n(p.mean_abs),
            n(p.skewness),
            n(p.kurtosis),
            n(p.range)
        ));
    }
    match src.fit() {
        Some(f) => {
            let verdict = f.verdict().words().unwrap_or("self-affine over this band");
            let how = if src.fit_band.is_some() {
                "set"
            } else {
                "found from the data"
            };
            out.push(format!(
                "fit: H = {}, standard error {}, band {}…{} /m ({how}; {} points, \
                 rms {} decades unweighted, {} weighted by modes): {verdict}",
                n(f.hurst),
                n(f.hurst_se),
                n(f.q_lo),
                n(f.q_hi),
                f.points,
                n(f.rms_decades_unweighted),
                n(f.rms_decades)
            ));
            if let Some((_, h)) = crate::surface::fit_amplitude(&f) {
                out.push(format!("h_rms of the fitted power law = {} m", n(h)));
            }
        }
        None => out.push("fit: none (too few spectrum points in the fit band)".into()),
    }
    out
}
