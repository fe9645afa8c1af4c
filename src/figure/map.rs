//! The regime map: the plastic share S_pl/S_tot of the initial slope over
//! two parameters, with the index in use (Ψ* with the size effect, Ψ_P
//! without) per cell for the Ψ = 1 contour.

use std::fmt;

use rough_model::{
    Axis, Curves, Model, Moments, Params, Roughness, Scene, SceneSpec, Slopes, Sweep,
};

use super::series::at;
use crate::snapshot::State;

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
        let zeta_max = roughness.zeta_max();
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
    /// Computes every cell: one sweep of the model per row, the rows
    /// shared among the cores for maps of more than a few thousand cells.
    pub fn compute(spec: &MapSpec) -> RegimeMap {
        let threads = if spec.cols * spec.rows < 4096 {
            1
        } else {
            std::thread::available_parallelism().map_or(1, |n| n.get().min(8))
        };
        let per = spec.rows.div_ceil(threads);
        let parts: Vec<RegimeMap> = if threads == 1 {
            vec![RegimeMap::rows(spec, 0..spec.rows)]
        } else {
            std::thread::scope(|scope| {
                let jobs: Vec<_> = (0..threads)
                    .map(|k| {
                        let lo = (k * per).min(spec.rows);
                        let hi = (lo + per).min(spec.rows);
                        scope.spawn(move || RegimeMap::rows(spec, lo..hi))
                    })
                    .collect();
                jobs.into_iter()
                    // A row computation does not panic; if one did, its
                    // rows are recomputed here.
                    .enumerate()
                    .map(|(k, j)| {
                        j.join().unwrap_or_else(|_| {
                            let lo = (k * per).min(spec.rows);
                            RegimeMap::rows(spec, lo..(lo + per).min(spec.rows))
                        })
                    })
                    .collect()
            })
        };
        let mut parts = parts.into_iter();
        let mut m = parts.next().unwrap_or_else(|| RegimeMap::rows(spec, 0..0));
        for p in parts {
            m.psi.extend(p.psi);
            m.elastic.extend(p.elastic);
            m.plastic.extend(p.plastic);
            m.total.extend(p.total);
            m.share.extend(p.share);
        }
        m
    }

    /// Rows `rows` of the map (a partial map: only those rows' cells).
    fn rows(spec: &MapSpec, rows: std::ops::Range<usize>) -> RegimeMap {
        let n = spec.cols * rows.len();
        let mut m = RegimeMap {
            spec: spec.clone(),
            psi: Vec::with_capacity(n),
            elastic: Vec::with_capacity(n),
            plastic: Vec::with_capacity(n),
            total: Vec::with_capacity(n),
            share: Vec::with_capacity(n),
        };
        let curves = Curves {
            persson_elastic: false,
            ..Curves::ALL
        };
        for row in rows {
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
            for col in 0..spec.cols {
                let get = |v: &Vec<f64>| v.get(col).copied().unwrap_or(f64::NAN);
                let sl = Slopes {
                    elastic: get(&s.elastic),
                    plastic: get(&s.plastic),
                    total: get(&s.total),
                };
                m.psi.push(get(&s.psi));
                m.elastic.push(sl.elastic);
                m.plastic.push(sl.plastic);
                m.total.push(sl.total);
                m.share.push(sl.plastic_share());
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
mod tests {
    use super::*;

    fn fig(name: &str) -> State {
        crate::presets::load(name).unwrap()
    }

    #[test]
    fn grid_ends_and_axes() {
        let s = fig("fig2");
        let spec = MapSpec::of(&s, (5, 4), None).unwrap();
        assert_eq!(spec.y.axis(), Axis::H0OverE);
        assert_eq!(spec.x_at(0), 1.0);
        assert_eq!(spec.x_at(4), 1e4);
        assert_eq!(spec.x_at(2), 100.0);
        assert_eq!(spec.y_at(0), 1e-4);
        assert_eq!(spec.y_at(3), 1e-1);
        assert_eq!(spec.y_at(1), 1e-3);
        let (fx, fy) = spec.position();
        assert!((fx - 128f64.ln() / 1e4f64.ln()).abs() < 1e-15);
        assert!((fy - 2.0 / 3.0).abs() < 1e-15);
        assert_eq!(spec.next_y(), Axis::HRms);
    }

    #[test]
    fn refuses_bad_grids_and_the_swept_axis() {
        let s = fig("fig2");
        for g in [(1, 5), (5, 1), (0, 0), (10_001, 2), (2000, 1001)] {
            let e = MapSpec::of(&s, g, None).unwrap_err();
            assert!(e.to_string().contains("out of range"), "{e}");
        }
        let e = MapSpec::of(&s, (5, 5), Some(Axis::Zeta)).unwrap_err();
        assert_eq!(
            e.to_string(),
            "map y axis zeta is the swept parameter: choose another of \
             h0-over-e, h-rms, hurst, r-star"
        );
    }

    #[test]
    fn cache_recomputes_only_when_the_map_changes() {
        let mut s = fig("fig2");
        let mut cache = MapCache::new();
        let spec = |s: &State| MapSpec::of(s, (20, 10), None).unwrap();
        let first = cache.get(&spec(&s)).clone();
        assert_eq!(cache.computes(), 1);
        // Moving the marker along either axis keeps the map.
        s.params = s.params.with(Axis::Zeta, 500.0).unwrap();
        s.params = s.params.with(Axis::H0OverE, 0.02).unwrap();
        let again = cache.get(&spec(&s));
        assert_eq!(again.share, first.share);
        assert_eq!(again.spec.base.zeta(), 500.0);
        assert_eq!(cache.computes(), 1);
        // What the map depends on recomputes it.
        s.size_effect = true;
        cache.get(&spec(&s));
        assert_eq!(cache.computes(), 2);
        s.params = s.params.with(Axis::HRms, 1e-7).unwrap();
        cache.get(&spec(&s));
        assert_eq!(cache.computes(), 3);
        s.model = s.model.other();
        cache.get(&spec(&s));
        assert_eq!(cache.computes(), 4);
    }

    #[test]
    fn contour_lies_where_psi_crosses_one() {
        let s = fig("fig2");
        let m = RegimeMap::compute(&MapSpec::of(&s, (30, 20), None).unwrap());
        let mut on = 0;
        for row in 0..20 {
            for col in 0..30 {
                let (right, up) = m.contour_edges(col, row);
                let here = m.psi_at(col, row) >= 1.0;
                if right {
                    assert_ne!(here, m.psi_at(col + 1, row) >= 1.0);
                }
                if up {
                    assert_ne!(here, m.psi_at(col, row + 1) >= 1.0);
                }
                on += usize::from(m.on_contour(col, row));
            }
        }
        // ψ grows down the map (softer) and across (finer): one crossing per column.
        assert!(on >= 30, "{on}");
        for col in 0..30 {
            assert!(m.psi_at(col, 0) > 1.0 && m.psi_at(col, 19) < 1.0);
        }
    }

    #[test]
    fn rows_shared_among_threads_give_the_same_map() {
        let s = fig("fig4");
        let spec = MapSpec::of(&s, (100, 61), None).unwrap();
        let whole = RegimeMap::compute(&spec);
        assert_eq!(whole, RegimeMap::rows(&spec, 0..61));
        assert_eq!(whole.share.len(), 6100);
    }

    #[test]
    fn size_effect_shrinks_the_plastic_region() {
        let mut s = fig("fig2");
        let plastic = |s: &State| {
            let m = RegimeMap::compute(&MapSpec::of(s, (40, 20), None).unwrap());
            m.share.iter().filter(|&&v| v > 0.5).count()
        };
        let without = plastic(&s);
        s.size_effect = true;
        let with = plastic(&s);
        assert!(with < without, "{with} !< {without}");
        assert!(without > 0);
    }
}
