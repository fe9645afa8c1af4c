//! Heights on a regular grid as an instrument's file holds them (x3p,
//! Gwyddion's .gwy): sizes in metres, undefined points as NaN, and the
//! step from them to the moment table.

use crate::error::{Failure, Problem};
use crate::formats::readers::assumed::Assumed;
use crate::measured::{Kind, Options};
use crate::spectrum::compute::{self, Computed};

/// Heights on a regular grid, read from a binary file.
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    /// Points along x (columns).
    pub nx: usize,
    /// Points along y (rows); 1 for a profile.
    pub ny: usize,
    /// The size along x in metres: nx times the spacing.
    pub lx: f64,
    /// The size along y in metres (ny times the spacing; a profile's is 0).
    pub ly: f64,
    /// Heights in metres, row after row (x fastest); an undefined point
    /// (masked, invalid, NaN or an infinity in the file) is `f64::NAN`.
    pub z: Vec<f64>,
    /// What the reader assumed, one line each (they go to
    /// [`crate::Measured::notes`]).
    pub notes: Vec<String>,
    /// The file's format for people: "x3p", "Digital Surf .sur".
    pub format: &'static str,
    /// Units the file does not give (`--height-unit`, `--lateral-unit`
    /// then say them); the default where it gives every unit.
    pub assumed: Assumed,
}

impl Grid {
    /// An instrument file's map (a profile where `ny` is 1: its `ly` is 0):
    /// `nx × ny` heights `z` over `lx × ly` metres, with `notes` and, where
    /// `z` holds undefined points, a note counting them as the file calls
    /// them (`what`: "points not measured").
    pub(crate) fn of_file(
        format: &'static str,
        (nx, ny): (usize, usize),
        (lx, ly): (f64, f64),
        z: Vec<f64>,
        mut notes: Vec<String>,
        what: &str,
    ) -> Grid {
        let undefined = z.iter().filter(|v| v.is_nan()).count();
        if undefined > 0 {
            notes.push(format!("{undefined} {what} read as undefined"));
        }
        Grid {
            nx,
            ny,
            lx,
            ly: if ny == 1 { 0.0 } else { ly },
            z,
            notes,
            format,
            assumed: Default::default(),
        }
    }

    /// A profile (one row) rather than a map.
    pub fn is_profile(&self) -> bool {
        self.ny == 1
    }

    /// How many points are undefined.
    pub fn undefined(&self) -> usize {
        self.z.iter().filter(|v| v.is_nan()).count()
    }

    /// What the grid is, for [`crate::Measured::kind`].
    pub fn kind(&self) -> Kind {
        if self.is_profile() {
            Kind::Line {
                n: self.nx,
                l: self.lx,
            }
        } else {
            Kind::Map {
                nx: self.nx,
                ny: self.ny,
                lx: self.lx,
                ly: self.ly,
            }
        }
    }
}

/// The moment table and spectrum of `g`'s heights; `g.notes` move to
/// `notes`.
pub(crate) fn compute(
    mut g: Grid,
    opts: &Options,
    notes: &mut Vec<String>,
) -> Result<(Kind, Computed), Failure> {
    notes.append(&mut g.notes);
    let format = g.format;
    notes.extend(crate::formats::readers::assumed::apply(
        g.assumed,
        format,
        &mut g.z,
        (&mut g.lx, &mut g.ly),
        opts,
    )?);
    if let Some(p) = opts.pixel_size {
        return Err((
            None,
            Problem::Option(format!(
                "--pixel-size {} does not apply: the file gives its size",
                crate::lengths::typed_length(p)
            )),
        ));
    }
    let kind = g.kind();
    let few = |axis, got| Err((None, Problem::TooFew { axis, got }));
    if g.is_profile() && g.nx < 4 {
        return few("the line", g.nx);
    }
    if !g.is_profile() && g.nx < 4 {
        return few("x", g.nx);
    }
    if !g.is_profile() && g.ny < 4 {
        return few("y", g.ny);
    }
    // Undefined points (NaN) are filled by the map pipeline.
    if let (Some(direction), false) = (opts.direction, g.is_profile()) {
        let c = crate::spectrum::profiles::profiles(
            g.z,
            (g.nx, g.ny),
            (g.lx, g.ly),
            (opts.periodic, opts.detrend_mode()),
            direction,
        )
        .map_err(|p| (None, p))?;
        let kind = Kind::Profiles {
            direction,
            nx: g.nx,
            ny: g.ny,
            lx: g.lx,
            ly: g.ly,
        };
        return Ok((kind, c));
    }
    let c = if g.is_profile() {
        compute::line(g.z, g.lx, opts.periodic, opts.detrend_mode())
    } else {
        compute::map(
            g.z,
            (g.nx, g.ny),
            (g.lx, g.ly),
            opts.periodic,
            opts.detrend_mode(),
        )
    }
    .map_err(|p| (None, p))?;
    Ok((kind, c))
}
