//! The regime map: the plastic share S_pl/S_tot of the initial slope over
//! two parameters, with the index in use (Ψ* with the size effect, Ψ_P
//! without) per cell for the Ψ = 1 contour.

use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use rough_model::{
    slopes, Axis, Curves, Dd, Model, Moments, Params, Roughness, Scene, SceneSpec, Slopes, Sweep,
};

use super::series::at;
use crate::scene::State;

/// `export --view map`'s default grid, cells across × up.
pub const DEFAULT_GRID: (usize, usize) = (50, 30);

/// Most cells along one side of a map.
pub const MAX_SIDE: usize = 10_000;

/// Most cells in a map (e.g. 2000 × 1000).
pub const MAX_CELLS: usize = 2_000_000;

/// What a regime map depends on.
#[derive(Clone, Debug, PartialEq)]
pub struct MapSpec {
    /// The current parameters: the map overrides its two axes; the values
    /// held here for them only place the current-point marker.
    pub base: Params,
    /// Across: the state's sweep.
    pub x: Sweep,
    /// Up: [`MapSpec::y_range`] of the chosen axis.
    pub y: Sweep,
    /// Cells across (≥ 2; the sweep's ends are the first and last columns).
    pub cols: usize,
    /// Cells up (≥ 2; the range's ends are the first and last rows).
    pub rows: usize,
    pub size_effect: bool,
    pub model: Model,
    pub moments: Moments,
    /// The power law or a measured surface's table.
    pub roughness: Roughness,
}

/// Why a map request was refused.
#[derive(Clone, Debug, PartialEq)]
pub enum MapError {
    /// A side below 2 or above [`MAX_SIDE`], or more than [`MAX_CELLS`].
    Grid { cols: usize, rows: usize },
    /// The y axis is the swept parameter itself.
    SameAxis(Axis),
    /// The y axis is h_rms or H on a measured surface, which fixes them.
    NotAParameter(Axis),
}

impl fmt::Display for MapError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MapError::Grid { cols, rows } => write!(
                f,
                "map grid {cols}x{rows} is out of range: each side must be 2 to {MAX_SIDE} \
                 cells and the map at most {MAX_CELLS} cells"
            ),
            MapError::SameAxis(a) => write!(
                f,
                "map y axis {} is the swept parameter: choose another of {}",
                axis_arg(*a),
                Axis::ALL
                    .iter()
                    .filter(|b| *b != a)
                    .map(|b| axis_arg(*b))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            MapError::NotAParameter(a) => write!(
                f,
                "map y axis {} is not a parameter of a measured surface (the data fixes it): \
                 choose another of h0-over-e, zeta, r-star",
                axis_arg(*a)
            ),
        }
    }
}

impl std::error::Error for MapError {}

/// The axis's name as the command line takes it (`h0-over-e`, `zeta` …).
pub fn axis_arg(a: Axis) -> &'static str {
    match a {
        Axis::H0OverE => "h0-over-e",
        Axis::HRms => "h-rms",
        Axis::Zeta => "zeta",
        Axis::Hurst => "hurst",
        Axis::RStar => "r-star",
    }
}

impl MapSpec {
    /// The map of `state` on a `cols × rows` grid with `y` up (default
    /// [`MapSpec::default_y`]).
    pub fn of(state: &State, grid: (usize, usize), y: Option<Axis>) -> Result<MapSpec, MapError> {
        let (cols, rows) = grid;
        let side = 2..=MAX_SIDE;
        if !side.contains(&cols) || !side.contains(&rows) || cols * rows > MAX_CELLS {
            return Err(MapError::Grid { cols, rows });
        }
        let y_axis = y.unwrap_or(MapSpec::default_y(state.sweep.axis()));
        if y_axis == state.sweep.axis() {
            return Err(MapError::SameAxis(y_axis));
        }
        let roughness = state.roughness();
        if !roughness.is_parameter(y_axis) {
            return Err(MapError::NotAParameter(y_axis));
        }
        Ok(MapSpec {
            base: state.params,
            x: state.sweep,
            y: MapSpec::y_range_of(y_axis, &roughness),
            cols,
            rows,
            size_effect: state.size_effect,
            model: state.model,
            moments: state.moments,
            roughness,
        })
    }

    /// H0/E, or ζ when H0/E is the swept parameter.
    pub fn default_y(swept: Axis) -> Axis {
        if swept == Axis::H0OverE {
            Axis::Zeta
        } else {
            Axis::H0OverE
        }
    }

    /// The range the map spans up `axis`: H0/E 1e-4…1e-1, ζ 1…1e6, h_rms
    /// 1 nm…10 µm, H 0.1…0.95, R* 1 µm…100 mm.
    pub fn y_range(axis: Axis) -> Sweep {
        let (a, b) = match axis {
            Axis::H0OverE => (1e-4, 1e-1),
            Axis::Zeta => (1.0, 1e6),
            Axis::HRms => (1e-9, 1e-5),
            Axis::Hurst => (0.1, 0.95),
            Axis::RStar => (1e-6, 1e-1),
        };
        // Both ends lie inside every axis's domain.
        Sweep::new(axis, a, b).expect("map ranges are valid sweeps")
    }

    /// [`MapSpec::y_range`] for `roughness`: ζ up to the largest the data
    /// holds on a measured surface.
    pub fn y_range_of(axis: Axis, roughness: &Roughness) -> Sweep {
        let zeta_max = crate::physical::clean(roughness.zeta_max());
        if axis == Axis::Zeta && zeta_max < 1e6 && zeta_max > 1.0 {
            if let Ok(s) = Sweep::new(axis, 1.0, zeta_max) {
                return s;
            }
        }
        MapSpec::y_range(axis)
    }

    /// The next y axis after the current one, skipping the swept parameter
    /// (the explorer's key for another y axis).
    pub fn next_y(&self) -> Axis {
        let all = Axis::ALL;
        let mut i = all.iter().position(|&a| a == self.y.axis()).unwrap_or(0);
        loop {
            i = (i + 1) % all.len();
            if all[i] != self.x.axis() && self.roughness.is_parameter(all[i]) {
                return all[i];
            }
        }
    }

    /// The swept value of column `col` (0 = the sweep's start).
    pub fn x_at(&self, col: usize) -> f64 {
        self.x.at(col as f64 / (self.cols - 1) as f64)
    }

    /// The y value of row `row` (0 = the range's bottom).
    pub fn y_at(&self, row: usize) -> f64 {
        self.y.at(row as f64 / (self.rows - 1) as f64)
    }

    /// Where the current parameters lie, as fractions of the map's width
    /// and height (outside [0, 1] when off the map).
    pub fn position(&self) -> (f64, f64) {
        (
            fraction(&self.x, self.base.get(self.x.axis())),
            fraction(&self.y, self.base.get(self.y.axis())),
        )
    }

    /// The spec with the current values of its two axes set aside: two
    /// specs with equal keys have equal maps.
    fn key(&self) -> MapSpec {
        let b = at(&self.base, self.x.axis(), self.x.from());
        MapSpec {
            base: at(&b, self.y.axis(), self.y.from()),
            ..self.clone()
        }
    }
}

/// Where `v` lies along `s`, 0 at its start and 1 at its end (log on log axes).
pub fn fraction(s: &Sweep, v: f64) -> f64 {
    if s.axis().is_log() {
        (v.ln() - s.from().ln()) / (s.to().ln() - s.from().ln())
    } else {
        (v - s.from()) / (s.to() - s.from())
    }
}

/// A computed map: row-major, row 0 at the bottom of the y range.
#[derive(Clone, Debug, PartialEq)]
pub struct RegimeMap {
    pub spec: MapSpec,
    /// The index in use per cell.
    pub psi: Vec<f64>,
    /// The initial slopes per cell.
    pub elastic: Vec<f64>,
    pub plastic: Vec<f64>,
    pub total: Vec<f64>,
    /// S_pl/S_tot per cell, in [0, 1].
    pub share: Vec<f64>,
}

impl RegimeMap {
    /// Computes every cell: one sweep of the model per row. Maps of more
    /// than a few thousand cells share their rows among the cores, handed
    /// out in bands of [`BAND`] rows as threads ask for work, so that a
    /// thread the OS sets aside (the machine is shared) holds up at most
    /// one band; each band is written in place.
    pub fn compute(spec: &MapSpec) -> RegimeMap {
        let n = spec.cols * spec.rows;
        let mut m = RegimeMap {
            spec: spec.clone(),
            psi: vec![0.0; n],
            elastic: vec![0.0; n],
            plastic: vec![0.0; n],
            total: vec![0.0; n],
            share: vec![0.0; n],
        };
        let threads = if n < 4096 {
            1
        } else {
            std::thread::available_parallelism().map_or(1, |n| n.get().min(8))
        };
        let scaled = scaled_psi(spec);
        let scaled = scaled.as_deref();
        let band = BAND * spec.cols;
        let bands = spec.rows.div_ceil(BAND);
        let done: Vec<AtomicBool> = (0..bands).map(|_| AtomicBool::new(false)).collect();
        {
            let queue = Mutex::new(
                m.psi
                    .chunks_mut(band)
                    .zip(m.elastic.chunks_mut(band))
                    .zip(m.plastic.chunks_mut(band))
                    .zip(m.total.chunks_mut(band))
                    .zip(m.share.chunks_mut(band))
                    .enumerate(),
            );
            let work = || loop {
                let next = queue.lock().unwrap_or_else(|e| e.into_inner()).next();
                let Some((b, ((((psi, el), pl), tot), share))) = next else {
                    return;
                };
                let rows = b * BAND..((b + 1) * BAND).min(spec.rows);
                fill_rows(spec, rows, scaled, [psi, el, pl, tot, share]);
                done[b].store(true, Ordering::Release);
            };
            if threads == 1 {
                work();
            } else {
                std::thread::scope(|scope| {
                    let helpers: Vec<_> = (1..threads).map(|_| scope.spawn(work)).collect();
                    work();
                    for h in helpers {
                        // A band's computation does not panic; if one did,
                        // its rows are recomputed below.
                        let _ = h.join();
                    }
                });
            }
        }
        for (b, d) in done.iter().enumerate() {
            if !d.load(Ordering::Acquire) {
                let (lo, hi) = (b * band, ((b + 1) * band).min(n));
                let rows = b * BAND..((b + 1) * BAND).min(spec.rows);
                let RegimeMap {
                    psi,
                    elastic,
                    plastic,
                    total,
                    share,
                    ..
                } = &mut m;
                fill_rows(
                    spec,
                    rows,
                    scaled,
                    [
                        &mut psi[lo..hi],
                        &mut elastic[lo..hi],
                        &mut plastic[lo..hi],
                        &mut total[lo..hi],
                        &mut share[lo..hi],
                    ],
                );
            }
        }
        m
    }

    fn index(&self, col: usize, row: usize) -> usize {
        row * self.spec.cols + col
    }

    /// S_pl/S_tot at a cell.
    pub fn share_at(&self, col: usize, row: usize) -> f64 {
        self.share[self.index(col, row)]
    }

    /// The index in use at a cell.
    pub fn psi_at(&self, col: usize, row: usize) -> f64 {
        self.psi[self.index(col, row)]
    }

    /// Whether the Ψ = 1 contour passes between this cell and its right
    /// neighbour (`.0`) or its upper neighbour (`.1`).
    pub fn contour_edges(&self, col: usize, row: usize) -> (bool, bool) {
        let above = |v: f64| v >= 1.0;
        let here = above(self.psi_at(col, row));
        let right = col + 1 < self.spec.cols && above(self.psi_at(col + 1, row)) != here;
        let up = row + 1 < self.spec.rows && above(self.psi_at(col, row + 1)) != here;
        (right, up)
    }

    /// Whether the Ψ = 1 contour touches this cell (on any of its sides).
    pub fn on_contour(&self, col: usize, row: usize) -> bool {
        let (r, u) = self.contour_edges(col, row);
        r || u
            || (col > 0 && self.contour_edges(col - 1, row).0)
            || (row > 0 && self.contour_edges(col, row - 1).1)
    }
}

/// Rows handed to a thread at a time by [`RegimeMap::compute`] (60 rows:
/// 15 bands).
const BAND: usize = 4;

/// Rows `rows` of the map into `out` (ψ, elastic, plastic, total, share;
/// each `cols × rows.len()` cells, row-major). With `scaled`, the ψ of row
/// 0 (see [`scaled_psi`]), each row's ψ is that row's scaled; otherwise each
/// row is a sweep of the model of its own.
fn fill_rows(
    spec: &MapSpec,
    rows: std::ops::Range<usize>,
    scaled: Option<&[Dd]>,
    out: [&mut [f64]; 5],
) {
    let [psi, elastic, plastic, total, share] = out;
    let curves = Curves {
        persson_elastic: false,
        ..Curves::ALL
    };
    for (k, row) in rows.enumerate() {
        let cells = k * spec.cols..(k + 1) * spec.cols;
        if let Some(psi0) = scaled {
            // ψ(y) = ψ(y₀)·(y₀/y) in double-double (the product's
            // lo·lo term is below 1e-32 relative).
            let ratio = Dd::from_f64(spec.y_at(row)).recip().mul_f64(spec.y_at(0));
            for (c, &p0) in psi0.iter().enumerate() {
                let hi = ratio.mul_f64(p0.hi);
                let p = Dd::sum(hi.hi, hi.lo + ratio.hi * p0.lo);
                let sl = slopes(spec.model, p);
                let i = cells.start + c;
                psi[i] = p.to_f64();
                elastic[i] = sl.elastic;
                plastic[i] = sl.plastic;
                total[i] = sl.total;
                share[i] = sl.plastic_share();
            }
            continue;
        }
        let scene_spec = SceneSpec {
            base: at(&spec.base, spec.y.axis(), spec.y_at(row)),
            sweep: spec.x,
            size_effect: spec.size_effect,
            model: spec.model,
            moments: spec.moments,
            roughness: spec.roughness.clone(),
            curves,
            points: spec.cols,
        };
        // Only fewer than two points fail, which MapSpec::of refuses.
        let s = Scene::compute(&scene_spec).unwrap_or_default();
        let put = |to: &mut [f64], from: &[f64]| {
            for (t, f) in to
                .iter_mut()
                .zip(from.iter().chain(std::iter::repeat(&f64::NAN)))
            {
                *t = *f;
            }
        };
        put(&mut psi[cells.clone()], &s.psi);
        put(&mut elastic[cells.clone()], &s.elastic);
        put(&mut plastic[cells.clone()], &s.plastic);
        put(&mut total[cells.clone()], &s.total);
        for (c, sh) in share[cells].iter_mut().enumerate() {
            *sh = Slopes {
                elastic: elastic[k * spec.cols + c],
                plastic: plastic[k * spec.cols + c],
                total: total[k * spec.cols + c],
            }
            .plastic_share();
        }
    }
}

/// The ψ of row 0 when the map's rows differ only in H0/E: the model's ψ
/// is inversely proportional to H0/E (Ψ_P = h_rms q0 √(H m2/2)/(H0/E), and
/// H_y/H0 does not involve H0/E; the same for a measured surface's
/// moments), so the other rows are this one scaled and
/// the map costs one row of ψ plus the slopes of each cell. Row 0 is
/// computed point by point ([`Roughness::psi_in_use`], double-double), so that the
/// scaled rows keep ψ's low part (the slopes amplify ψ's rounding up to
/// ~1/ψ² where ψ is small). `None` (each row its own sweep) for another y
/// axis, or where a ψ of row 0 other than 0 (ζ = 1 with truncated moments)
/// lies so near the ends of f64 that scaling could leave them.
fn scaled_psi(spec: &MapSpec) -> Option<Vec<Dd>> {
    if spec.y.axis() != Axis::H0OverE {
        return None;
    }
    let base = at(&spec.base, Axis::H0OverE, spec.y_at(0));
    let psi: Vec<Dd> = (0..spec.cols)
        .map(|c| {
            spec.roughness
                .psi_in_use(
                    &at(&base, spec.x.axis(), spec.x_at(c)),
                    spec.size_effect,
                    spec.moments,
                )
                .0
        })
        .collect();
    psi.iter()
        .all(|p| p.hi == 0.0 || (1e-290..1e290).contains(&p.hi))
        .then_some(psi)
}

/// The last map computed, recomputed only when its spec changes in a way
/// that changes the map (moving the current point along either map axis
/// does not).
#[derive(Clone, Debug, Default)]
pub struct MapCache {
    map: Option<RegimeMap>,
    key: Option<MapSpec>,
    computes: u64,
}

impl MapCache {
    pub fn new() -> MapCache {
        MapCache::default()
    }

    /// The map of `spec`, from the cache when nothing it depends on changed.
    /// The returned map's `spec` is `spec` (so its marker is current).
    pub fn get(&mut self, spec: &MapSpec) -> &RegimeMap {
        let key = spec.key();
        let fresh = self.key.as_ref() == Some(&key) && self.map.is_some();
        if !fresh {
            self.computes += 1;
            self.key = Some(key);
            self.map = Some(RegimeMap::compute(spec));
        }
        let map = self.map.get_or_insert_with(|| RegimeMap::compute(spec));
        map.spec = spec.clone();
        map
    }

    /// The cached map, if any, without computing.
    pub fn peek(&self) -> Option<&RegimeMap> {
        self.map.as_ref()
    }

    /// How many times a map was computed (for tests and the bench).
    pub fn computes(&self) -> u64 {
        self.computes
    }
}

#[cfg(test)]
#[path = "map_tests.rs"]
mod tests;
