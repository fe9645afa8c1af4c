//! A researcher's measured map as the contact simulation solves it.
//!
//! The heights are the map's as `rough-surface` keeps them for this
//! ([`rough_surface::Heights`]: undefined points filled, the mean or the
//! plane removed, no window). The solver's FFT operators take a square grid
//! whose side is a power of two, so a map that is not one is **cropped**:
//! the centred square of side c = the largest power of two ≤ min(nx, ny)
//! (nothing is padded, no height is invented). Wavevectors |q| ≤ ζ q0 are
//! kept (q0 = 2π/max(Lx, Ly), the cutoff the indices use), and the square
//! is Fourier-resampled to N = the power of two ≥ 8 ζ c/max(nx, ny) (eight
//! nodes per shortest wavelength, at least [`MIN_GRID`]) when that is
//! smaller than c; N ≤ [`MAX_GRID`]. A map read with `--periodic` whose
//! grid is such a square already is solved with the periodic kernel; every
//! other map (or crop) on the free-boundary variant (zero-padded 2N × 2N,
//! Love's coefficients).
//!
//! The scene's key names the map by its file's SHA-256 and a hash of how it
//! was read; the heights themselves are found in a process-wide registry of
//! the surfaces loaded (weak references: a surface nobody holds is freed).

use std::collections::hash_map::DefaultHasher;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::{Arc, Mutex, OnceLock, Weak};

use anyhow::{anyhow, bail};
use rough_contact::{resample, Boundary, Contact};
use rough_surface::Heights;

use super::engine::Waker;
use super::MIN_GRID;

/// Largest grid side a measured map is solved on (a free boundary's padded
/// grid is four times as large).
pub const MAX_GRID: usize = 1024;
use crate::scene::State;

/// SHA-256 of the file and a hash of the reading options.
pub type SurfaceId = ([u8; 32], u64);

/// Every loaded copy of each surface (explorers that read the same file
/// each hold their own): a solve finds any one still alive.
type Registry = Mutex<HashMap<SurfaceId, Vec<Weak<Heights>>>>;

fn registry() -> &'static Registry {
    static R: OnceLock<Registry> = OnceLock::new();
    R.get_or_init(Registry::default)
}

/// The map of a measured scene, why not if it has none, and its id
/// (registered so that [`build`] finds its heights). The explorer reads a
/// surface without its heights ([`rough_surface::read`]); the first solve
/// reads the file again with them ([`rough_surface::read_heights`],
/// checking that it is the file the scene was computed on) and the last
/// [`KEPT`] surfaces read so stay in memory.
pub fn heights_of(state: &State) -> anyhow::Result<Option<(SurfaceId, Arc<Heights>)>> {
    let Some(src) = &state.surface else {
        return Ok(None);
    };
    if !matches!(src.measured.kind, rough_surface::Kind::Map { .. }) {
        bail!(
            "the contact simulation needs heights on a grid: {} is {}, which has none \
             (line scans, profiles read with --direction and PSD tables cannot be solved)",
            src.path.display(),
            match src.measured.kind {
                rough_surface::Kind::Line { .. } => "a line scan",
                rough_surface::Kind::Profiles { .. } => "a map read as profiles",
                _ => "a PSD table",
            }
        );
    }
    let id = surface_id(src);
    let h = match &src.measured.heights {
        Some(h) => Arc::clone(h),
        None => kept(id, src)?,
    };
    let mut reg = registry().lock().unwrap_or_else(|e| e.into_inner());
    reg.values_mut()
        .for_each(|v| v.retain(|w| w.strong_count() > 0));
    reg.retain(|_, v| !v.is_empty());
    let copies = reg.entry(id).or_default();
    if !copies
        .iter()
        .any(|w| std::ptr::eq(w.as_ptr(), Arc::as_ptr(&h)))
    {
        copies.push(Arc::downgrade(&h));
    }
    Ok(Some((id, h)))
}

/// Surfaces whose heights were read for a solve and stay in memory.
pub const KEPT: usize = 2;

/// The id of `src`'s surface: its file's SHA-256 and a hash of how it was
/// read.
fn surface_id(src: &crate::surface::SurfaceSource) -> SurfaceId {
    let mut sha = [0u8; 32];
    let hex = src.measured.sha256.as_bytes();
    for (i, b) in sha.iter_mut().enumerate() {
        let digit = |k: usize| {
            hex.get(k)
                .and_then(|c| (*c as char).to_digit(16))
                .unwrap_or(0)
        };
        *b = (digit(2 * i) * 16 + digit(2 * i + 1)) as u8;
    }
    let mut hasher = DefaultHasher::new();
    format!("{:?}", src.options).hash(&mut hasher);
    (sha, hasher.finish())
}

type Kept = Mutex<Vec<(SurfaceId, Arc<Heights>)>>;

fn kept_list() -> &'static Kept {
    static K: OnceLock<Kept> = OnceLock::new();
    K.get_or_init(Kept::default)
}

/// The heights of surface `id` if a read keeps them.
fn cached(id: SurfaceId) -> Option<Arc<Heights>> {
    kept_list()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .iter()
        .find(|(i, _)| *i == id)
        .map(|(_, h)| Arc::clone(h))
}

/// The heights of surface `id`: kept from an earlier read, or read again
/// from `src`'s file (which must still be the file the scene was computed
/// on).
fn kept(id: SurfaceId, src: &crate::surface::SurfaceSource) -> anyhow::Result<Arc<Heights>> {
    if let Some(h) = cached(id) {
        return Ok(h);
    }
    let m = rough_surface::read_heights(&src.path, &src.options)?;
    if m.sha256 != src.measured.sha256 {
        bail!(
            "{} changed since it was read: load it again for the contact simulation",
            src.path.display()
        );
    }
    let h = m
        .heights
        .ok_or_else(|| anyhow!("{}: no heights on a grid", src.path.display()))?;
    let mut k = kept_list().lock().unwrap_or_else(|e| e.into_inner());
    k.retain(|(i, _)| *i != id);
    k.push((id, Arc::clone(&h)));
    if k.len() > KEPT {
        k.remove(0);
    }
    Ok(h)
}

/// Where the heights of a scene's map are, for a view that must not wait
/// on the file ([`fetch`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Fetch {
    /// In memory (or the scene needs none): [`heights_of`] returns at once.
    Ready,
    /// Being read on a thread of their own; the waker is called when done.
    Reading,
    /// The last read failed, and why (tried again after [`RETRY`]).
    Failed(String),
}

/// How long a failed read is reported before the file is tried again.
pub const RETRY: std::time::Duration = std::time::Duration::from_secs(2);

enum Read {
    Running(Vec<Waker>),
    Failed(String, std::time::Instant),
}

/// [`heights_of`] without waiting: the heights of `state`'s map if in
/// memory; else their read is started on a thread (one per surface,
/// however many explorers ask) and `wake` called when it ends. A 4096² map
/// takes about a second to read: the explorer (and, under `serve`, the
/// other sessions on the same worker) go on meanwhile.
pub fn fetch(state: &State, wake: &Waker) -> Fetch {
    type Reads = Mutex<HashMap<SurfaceId, Read>>;
    static R: OnceLock<Reads> = OnceLock::new();
    let Some(src) = &state.surface else {
        return Fetch::Ready;
    };
    if src.measured.heights.is_some()
        || !matches!(src.measured.kind, rough_surface::Kind::Map { .. })
    {
        return Fetch::Ready;
    }
    let id = surface_id(src);
    if cached(id).is_some() {
        return Fetch::Ready;
    }
    let reads = R.get_or_init(Reads::default);
    let mut r = reads.lock().unwrap_or_else(|e| e.into_inner());
    match r.get_mut(&id) {
        Some(Read::Running(wakers)) => {
            if !wakers.iter().any(|w| Arc::ptr_eq(w, wake)) {
                wakers.push(Arc::clone(wake));
            }
            return Fetch::Reading;
        }
        Some(Read::Failed(why, at)) if at.elapsed() < RETRY => return Fetch::Failed(why.clone()),
        _ => {}
    }
    r.insert(id, Read::Running(vec![Arc::clone(wake)]));
    let src = src.clone();
    let started = std::thread::Builder::new()
        .name("heights".into())
        .spawn(move || {
            let done = kept(id, &src);
            let mut r = reads.lock().unwrap_or_else(|e| e.into_inner());
            let wakers = match r.remove(&id) {
                Some(Read::Running(w)) => w,
                _ => vec![],
            };
            if let Err(e) = done {
                r.insert(
                    id,
                    Read::Failed(format!("{e:#}"), std::time::Instant::now()),
                );
            }
            drop(r);
            for w in wakers {
                w();
            }
        });
    if let Err(e) = started {
        let why = format!("cannot start a thread to read the heights: {e}");
        r.insert(id, Read::Failed(why.clone(), std::time::Instant::now()));
        return Fetch::Failed(why);
    }
    Fetch::Reading
}

/// How a map is cut and sampled for the solver.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plan {
    /// Side of the centred square cropped from the map, in points.
    pub crop: usize,
    /// Side of the solver's grid.
    pub n: usize,
    /// Side of the square, m.
    pub length: f64,
    pub boundary: Boundary,
}

/// The plan for `h` with cutoff `q_cut` (1/m).
pub fn plan(h: &Heights, q_cut: f64) -> anyhow::Result<Plan> {
    let (dx, dy) = (h.lx / h.nx as f64, h.ly / h.ny as f64);
    if (dx - dy).abs() > 1e-6 * dx.max(dy) {
        bail!(
            "the map's pixels are {dx:e} m × {dy:e} m: the contact solver takes square pixels \
             only (--pixel-size sets both)"
        );
    }
    let crop = 1usize << h.nx.min(h.ny).ilog2();
    if crop < MIN_GRID {
        bail!(
            "the map is {} × {} points: the contact simulation needs a square of at least \
             {MIN_GRID} × {MIN_GRID}",
            h.nx,
            h.ny
        );
    }
    let length = crop as f64 * dx;
    if q_cut * (1.0 + 1e-9) < std::f64::consts::TAU / length {
        bail!(
            "ζ = {:.3} keeps no wavelength shorter than the solved {crop} × {crop} square's \
             side: the contact simulation needs ζ ≥ {:.3} on this map",
            q_cut * h.lx.max(h.ly) / std::f64::consts::TAU,
            lowest_zeta(h)
        );
    }
    let need = (8.0 * q_cut * length / std::f64::consts::TAU).ceil();
    let n = if need > crop as f64 {
        crop
    } else {
        (need as usize).next_power_of_two().clamp(MIN_GRID, crop)
    };
    if n > MAX_GRID {
        bail!(
            "ζ = {:.3} on this {crop} × {crop} square needs a grid of {} nodes a side (8 per \
             shortest wavelength, or the data's own); the contact simulation solves up to \
             {MAX_GRID}: lower ζ to compare",
            q_cut * h.lx.max(h.ly) / std::f64::consts::TAU,
            need.min(crop as f64)
        );
    }
    let periodic = h.periodic && h.nx == crop && h.ny == crop;
    Ok(Plan {
        crop,
        n,
        length,
        boundary: if periodic {
            Boundary::Periodic
        } else {
            Boundary::Free
        },
    })
}

/// The smallest ζ that keeps a mode of the solved square: max(Lx, Ly)
/// over the square's side.
pub fn lowest_zeta(h: &Heights) -> f64 {
    let crop = 1usize << h.nx.min(h.ny).max(1).ilog2();
    h.lx.max(h.ly) / (crop as f64 * h.lx / h.nx as f64)
}

/// The map's crop filtered to q ≤ `q_cut` on the plan's grid (metres).
pub fn solver_heights(h: &Heights, p: &Plan, q_cut: f64) -> anyhow::Result<Vec<f64>> {
    let (x0, y0) = ((h.nx - p.crop) / 2, (h.ny - p.crop) / 2);
    let mut sq = Vec::with_capacity(p.crop * p.crop);
    for row in h.z.chunks_exact(h.nx).skip(y0).take(p.crop) {
        sq.extend_from_slice(&row[x0..x0 + p.crop]);
    }
    Ok(resample(&sq, p.crop, p.length, q_cut, p.n)?)
}

/// The surface `id` with cutoff `q_cut`, ready to be loaded (E* = 1).
pub fn build(id: &SurfaceId, q_cut: f64) -> anyhow::Result<Contact> {
    let h = registry()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .get(id)
        .and_then(|v| v.iter().find_map(Weak::upgrade))
        .ok_or_else(|| anyhow!("the measured surface is no longer loaded"))?;
    let p = plan(&h, q_cut)?;
    let z = solver_heights(&h, &p, q_cut)?;
    Ok(Contact::new(z, p.n, p.length, 1.0, p.boundary)?)
}

/// One line on how the map is solved, for the CSV's parameter lines.
pub fn describe(h: &Heights, p: &Plan) -> String {
    let crop = if p.crop == h.nx && p.crop == h.ny {
        format!("{} × {} map", h.nx, h.ny)
    } else {
        format!(
            "{} × {} map cropped to its centred {c} × {c}",
            h.nx,
            h.ny,
            c = p.crop
        )
    };
    let grid = if p.n == p.crop {
        String::new()
    } else {
        format!(", resampled to {n} × {n}", n = p.n)
    };
    let side = match p.boundary {
        Boundary::Periodic => "periodic",
        Boundary::Free => "free-boundary (zero-padded 2N × 2N)",
    };
    format!("{side}, measured {crop}{grid}, side {} m", p.length)
}
