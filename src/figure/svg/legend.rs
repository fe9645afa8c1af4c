//! The pictures' legend: it lists what is drawn and nothing else, and it
//! never covers data. Every line a view draws is recorded here (in drawn
//! coordinates) as it is drawn; the legend box then goes to the first
//! place inside the plot where no recorded line passes (the corners, then
//! the middles of the edges), or, where there is none, right of the plot,
//! which the view then draws narrower ([`Legend::room`]). A label longer
//! than [`MAX_CHARS`] goes on as many rows as it needs, so that the box
//! never takes more than a third of the page from the plot.

use plotters::prelude::*;

pub(crate) use super::entry::{Entry, Sample};
use super::{plot_err, Area, Chart};

/// Pixels per character of a legend label (plotters writes its 14-point
/// font as 11.3 px; 0.62 em bounds a sans-serif's common glyphs).
const CHAR_W: f64 = 7.0;
const ROW_H: i32 = 17;
const PAD: i32 = 6;
const SAMPLE_W: i32 = 22;
/// Distance from the plot's edges.
const INSET: i32 = 8;
/// Characters a legend row holds at most: longer labels are wrapped at
/// spaces (a box of at most 18 + 22 + 37 × 7 = 299 px, a third of the
/// page).
pub(crate) const MAX_CHARS: usize = 37;

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

    /// Each entry's label in rows of at most [`MAX_CHARS`] characters.
    fn rows(&self) -> Vec<Vec<String>> {
        self.entries
            .iter()
            .map(|e| super::wrap::wrap(&e.label, MAX_CHARS))
            .collect()
    }

    /// The box's size in pixels.
    pub fn size(&self) -> (i32, i32) {
        let rows = self.rows();
        let chars = rows
            .iter()
            .flatten()
            .map(|l| l.chars().count())
            .max()
            .unwrap_or(0);
        let n: usize = rows.iter().map(|r| r.len().max(1)).sum();
        let w = PAD * 3 + SAMPLE_W + (chars as f64 * CHAR_W).ceil() as i32;
        let h = PAD * 2 + ROW_H * n as i32;
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
        // A phone's page lists the legend under the picture.
        if self.entries.is_empty() || super::phone::keep(&self.entries) {
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
        let mut row = 0;
        for (e, lines) in self.entries.iter().zip(self.rows()) {
            let y = by + PAD + ROW_H * row + ROW_H / 2;
            row += lines.len().max(1) as i32;
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
            for (k, l) in lines.into_iter().enumerate() {
                let font = ("sans-serif", 14).into_font();
                let at = (ex + PAD, y - 7 + ROW_H * k as i32);
                root.draw(&Text::new(l, at, font)).map_err(plot_err)?;
            }
        }
        Ok(Placed::Inside)
    }

    /// The first candidate place (top left pixel) for a `(w, h)` box in the
    /// plot `(xr, yr)` that no recorded line enters: the corners, the
    /// middles of the edges, then every place on an 4-px grid, those
    /// nearest an edge first.
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
        let taken = Taken::of(
            self.paths
                .iter()
                .map(|p| p.iter().map(|q| c.backend_coord(q)).collect()),
            (xr.start - 4, yr.start - 4),
            (xr.end + 4, yr.end + 4),
        );
        let dots: Vec<((i32, i32), i32)> = self
            .dots
            .iter()
            .map(|(q, r)| (c.backend_coord(q), *r))
            .collect();
        let named = [
            (l, t),
            (r, t),
            (l, b),
            (r, b),
            (cx, t),
            (cx, b),
            (l, cy),
            (r, cy),
        ];
        let mut grid: Vec<(i32, i32)> = (t..=b)
            .step_by(4)
            .flat_map(|y| (l..=r).step_by(4).map(move |x| (x, y)))
            .collect();
        grid.sort_by_key(|&(x, y)| ((x - l).min(r - x).min(y - t).min(b - y), y, x));
        named.into_iter().chain(grid).find(|&(x0, y0)| {
            let clear = (x0 - 2, y0 - 2, x0 + w + 2, y0 + h + 2);
            !taken.any(clear)
                && !dots.iter().any(|&((x, y), r)| {
                    x + r >= clear.0 && x - r <= clear.2 && y + r >= clear.1 && y - r <= clear.3
                })
        })
    }
}

/// The pixels that drawn lines pass, as a summed-area table over a box of
/// the picture: whether a box holds any is one look-up.
struct Taken {
    origin: (i32, i32),
    w: usize,
    h: usize,
    /// sum[(y) * (w + 1) + x]: pixels taken left of x and above y.
    sum: Vec<u32>,
}

impl Taken {
    /// The pixels of `paths` (pixels; their segments sampled every pixel)
    /// inside the box from `lo` to `hi`.
    fn of(paths: impl Iterator<Item = Vec<(i32, i32)>>, lo: (i32, i32), hi: (i32, i32)) -> Taken {
        let w = (hi.0 - lo.0).max(0) as usize + 1;
        let h = (hi.1 - lo.1).max(0) as usize + 1;
        let mut grid = vec![0u32; w * h];
        let mut mark = |x: f64, y: f64| {
            let (x, y) = (x.round() as i32 - lo.0, y.round() as i32 - lo.1);
            if x >= 0 && y >= 0 && (x as usize) < w && (y as usize) < h {
                grid[y as usize * w + x as usize] = 1;
            }
        };
        for p in paths {
            if p.len() == 1 {
                mark(f64::from(p[0].0), f64::from(p[0].1));
            }
            for s in p.windows(2) {
                let (a, b) = (s[0], s[1]);
                let (dx, dy) = (f64::from(b.0 - a.0), f64::from(b.1 - a.1));
                // Segments far outside the box (a curve's off-chart tail)
                // are not sampled pixel by pixel.
                let n = dx.abs().max(dy.abs()).ceil().clamp(1.0, 1e5) as usize;
                for k in 0..=n {
                    let t = k as f64 / n as f64;
                    mark(f64::from(a.0) + dx * t, f64::from(a.1) + dy * t);
                }
            }
        }
        let mut sum = vec![0u32; (w + 1) * (h + 1)];
        for y in 0..h {
            for x in 0..w {
                sum[(y + 1) * (w + 1) + x + 1] =
                    grid[y * w + x] + sum[y * (w + 1) + x + 1] + sum[(y + 1) * (w + 1) + x]
                        - sum[y * (w + 1) + x];
            }
        }
        Taken {
            origin: lo,
            w,
            h,
            sum,
        }
    }

    /// Whether any pixel of the box `(x0, y0, x1, y1)` (inclusive) is taken.
    fn any(&self, (x0, y0, x1, y1): (i32, i32, i32, i32)) -> bool {
        let clip = |v: i32, o: i32, n: usize| (v - o).clamp(0, n as i32) as usize;
        let (a, b) = (
            clip(x0, self.origin.0, self.w),
            clip(x1 + 1, self.origin.0, self.w),
        );
        let (c, d) = (
            clip(y0, self.origin.1, self.h),
            clip(y1 + 1, self.origin.1, self.h),
        );
        let s = |x: usize, y: usize| self.sum[y * (self.w + 1) + x];
        s(b, d) + s(a, c) > s(a, d) + s(b, c)
    }
}

#[cfg(test)]
mod tests {
    use super::Taken;

    #[test]
    fn a_box_is_taken_where_a_line_passes() {
        let t = Taken::of(
            [vec![(0, 15), (30, 15)], vec![(5, 40)]].into_iter(),
            (0, 0),
            (50, 50),
        );
        assert!(t.any((10, 10, 20, 20)));
        assert!(!t.any((10, 16, 20, 30)));
        assert!(t.any((5, 40, 5, 40)));
        assert!(!t.any((6, 30, 50, 50)));
        // Outside the table: nothing taken.
        assert!(!t.any((60, 60, 70, 70)));
    }
}
