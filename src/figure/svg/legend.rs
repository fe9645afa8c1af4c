//! The pictures' legend: it lists what is drawn and nothing else, and it
//! never covers data. Every line a view draws is recorded here (in drawn
//! coordinates) as it is drawn; the legend box then goes to the first
//! place inside the plot where no recorded line passes (the corners, the
//! middles of the edges, then a grid over the plot), or, where there is
//! none, right of the plot,
//! which the view then draws narrower ([`Legend::room`]).

use plotters::prelude::*;

use super::{plot_err, Area, Chart};

/// Pixels per character of a legend label (plotters writes its 14-point
/// font as 11.3 px; 0.62 em bounds a sans-serif's common glyphs).
const CHAR_W: f64 = 7.0;
const ROW_H: i32 = 17;
const PAD: i32 = 6;
const SAMPLE_W: i32 = 22;
/// Distance from the plot's edges.
const INSET: i32 = 8;

/// How a legend entry's sample is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Sample {
    Solid(u32),
    Dashed,
    /// A filled dot of this radius (a simulation's points).
    Dot(u32),
}

#[derive(Clone, Debug)]
pub(crate) struct Entry {
    pub label: String,
    pub colour: RGBColor,
    pub sample: Sample,
}

/// What a view drew: its legend entries and every line, to keep the
/// legend off them.
#[derive(Clone, Debug, Default)]
pub(crate) struct Legend {
    pub entries: Vec<Entry>,
    /// Drawn coordinates (log10 on log axes) of every line drawn.
    pub paths: Vec<Vec<(f64, f64)>>,
    /// Drawn coordinates of every dot drawn, with its radius in pixels.
    pub dots: Vec<((f64, f64), i32)>,
}

/// Where the legend went.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Placed {
    Inside,
    /// No place inside the plot is free: the view is drawn again with
    /// this many pixels kept right of the plot for the legend.
    NoRoom(u32),
}

impl Legend {
    pub fn add(&mut self, label: impl Into<String>, colour: RGBColor, sample: Sample) {
        self.entries.push(Entry {
            label: label.into(),
            colour,
            sample,
        });
    }

    /// The box's size in pixels.
    pub fn size(&self) -> (i32, i32) {
        let chars = self
            .entries
            .iter()
            .map(|e| e.label.chars().count())
            .max()
            .unwrap_or(0);
        let w = PAD * 3 + SAMPLE_W + (chars as f64 * CHAR_W).ceil() as i32;
        let h = PAD * 2 + ROW_H * self.entries.len() as i32;
        (w, h)
    }

    /// The width kept right of the plot for a legend outside it.
    pub fn room(&self) -> u32 {
        (self.size().0 + 2 * INSET) as u32
    }

    /// Places and draws the legend: inside the plot where no line passes,
    /// else outside it when `outside` (the plot was drawn narrower for it),
    /// else nothing is drawn and [`Placed::NoRoom`] says how much room it
    /// needs.
    pub fn draw(&self, area: &Area, c: &Chart, outside: bool) -> anyhow::Result<Placed> {
        if self.entries.is_empty() {
            return Ok(Placed::Inside);
        }
        let (xr, yr) = c.plotting_area().get_pixel_range();
        let (w, h) = self.size();
        let at = if outside {
            Some((xr.end + INSET, yr.start))
        } else {
            self.free_place(c, (xr, yr), (w, h))
        };
        let Some((x0, y0)) = at else {
            return Ok(Placed::NoRoom(self.room()));
        };
        // `area` draws relative to its own corner.
        let (ox, oy) = area.get_base_pixel();
        let root = area;
        let (bx, by) = (x0 - ox, y0 - oy);
        root.draw(&Rectangle::new(
            [(bx, by), (bx + w, by + h)],
            WHITE.mix(0.9).filled(),
        ))
        .map_err(plot_err)?;
        root.draw(&Rectangle::new([(bx, by), (bx + w, by + h)], BLACK))
            .map_err(plot_err)?;
        for (k, e) in self.entries.iter().enumerate() {
            let y = by + PAD + ROW_H * k as i32 + ROW_H / 2;
            let (sx, ex) = (bx + PAD, bx + PAD + SAMPLE_W);
            match e.sample {
                Sample::Solid(width) => root
                    .draw(&PathElement::new(
                        vec![(sx, y), (ex, y)],
                        e.colour.stroke_width(width),
                    ))
                    .map_err(plot_err)?,
                // Dashed by the viewer, as the curve is.
                Sample::Dashed => root
                    .draw(&PathElement::new(
                        vec![(sx, y), (ex, y)],
                        e.colour.stroke_width(2),
                    ))
                    .map_err(plot_err)?,
                Sample::Dot(r) => root
                    .draw(&Circle::new(((sx + ex) / 2, y), r, e.colour.filled()))
                    .map_err(plot_err)?,
            }
            let font = ("sans-serif", 14).into_font();
            root.draw(&Text::new(e.label.clone(), (ex + PAD, y - 7), font))
                .map_err(plot_err)?;
        }
        Ok(Placed::Inside)
    }

    /// The first candidate place (top left pixel) for a `(w, h)` box in the
    /// plot `(xr, yr)` that no recorded line enters.
    fn free_place(
        &self,
        c: &Chart,
        (xr, yr): (std::ops::Range<i32>, std::ops::Range<i32>),
        (w, h): (i32, i32),
    ) -> Option<(i32, i32)> {
        let (l, r) = (xr.start + INSET, xr.end - INSET - w);
        let (t, b) = (yr.start + INSET, yr.end - INSET - h);
        if r < l || b < t {
            return None;
        }
        let (cx, cy) = ((l + r) / 2, (t + b) / 2);
        let pixels: Vec<Vec<(i32, i32)>> = self
            .paths
            .iter()
            .map(|p| p.iter().map(|q| c.backend_coord(q)).collect())
            .collect();
        let dots: Vec<((i32, i32), i32)> = self
            .dots
            .iter()
            .map(|(q, r)| (c.backend_coord(q), *r))
            .collect();
        // The corners and the middles of the edges first, then anywhere on
        // a 7 × 7 grid over the plot, from the top (a load view whose
        // curves fill every corner still has its middle free).
        let grid =
            (0..7).flat_map(|j| (0..7).map(move |i| (l + (r - l) * i / 6, t + (b - t) * j / 6)));
        [
            (l, t),
            (r, t),
            (l, b),
            (r, b),
            (cx, t),
            (cx, b),
            (l, cy),
            (r, cy),
        ]
        .into_iter()
        .chain(grid)
        .find(|&(x0, y0)| {
            let clear = (x0 - 2, y0 - 2, x0 + w + 2, y0 + h + 2);
            !pixels.iter().any(|p| enters(p, clear))
                && !dots.iter().any(|&((x, y), r)| {
                    x + r >= clear.0 && x - r <= clear.2 && y + r >= clear.1 && y - r <= clear.3
                })
        })
    }
}

/// Whether the polyline `p` (pixels) passes through the box
/// `(x0, y0, x1, y1)`: its points, and its segments sampled every pixel.
pub(crate) fn enters(p: &[(i32, i32)], (x0, y0, x1, y1): (i32, i32, i32, i32)) -> bool {
    let inside = |x: f64, y: f64| {
        x >= f64::from(x0) && x <= f64::from(x1) && y >= f64::from(y0) && y <= f64::from(y1)
    };
    if p.len() == 1 {
        return inside(f64::from(p[0].0), f64::from(p[0].1));
    }
    p.windows(2).any(|s| {
        let (a, b) = (s[0], s[1]);
        let (dx, dy) = (f64::from(b.0 - a.0), f64::from(b.1 - a.1));
        let n = dx.abs().max(dy.abs()).ceil().max(1.0) as usize;
        (0..=n).any(|k| {
            let t = k as f64 / n as f64;
            inside(f64::from(a.0) + dx * t, f64::from(a.1) + dy * t)
        })
    })
}

#[cfg(test)]
mod tests {
    use super::enters;

    #[test]
    fn a_segment_through_the_box_enters_it() {
        let b = (10, 10, 20, 20);
        assert!(enters(&[(0, 15), (30, 15)], b));
        assert!(!enters(&[(0, 0), (30, 0)], b));
        assert!(enters(&[(15, 15)], b));
        assert!(!enters(&[(0, 30), (30, 25)], b));
    }
}
