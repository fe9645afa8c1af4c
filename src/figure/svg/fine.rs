//! Curves with sub-pixel coordinates. plotters maps data to whole pixels
//! (its backend coordinates are integers), so a straight power law drawn
//! through it shows kinks where the rounding steps and a slowly rising
//! curve becomes a staircase. Every curve is drawn through plotters as
//! usual (so that its place in the document, its colour and its width are
//! plotters' own) and its exact coordinates are recorded beside the
//! rounded ones; when the picture is finished, [`apply`] puts the exact
//! coordinates (two decimals, 1/100 px) into those polylines. Fonts,
//! ticks and everything else are untouched.

use std::cell::RefCell;
use std::fmt::Write as _;

use plotters::prelude::*;

use super::{plot_err, Area, Chart};

thread_local! {
    /// The polylines of the picture being drawn, in drawing order: the
    /// rounded `points` attribute plotters writes and the exact one.
    static FINE: RefCell<Vec<(String, String)>> = const { RefCell::new(Vec::new()) };
    /// What replaces each placeholder rectangle, in drawing order.
    static RAW: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
}

/// The fill of a placeholder rectangle: a colour no picture uses.
const PLACEHOLDER: RGBColor = RGBColor(1, 2, 3);

/// Forgets what an earlier drawing recorded (a picture drawn again).
pub(super) fn start() {
    FINE.with(|f| f.borrow_mut().clear());
    RAW.with(|f| f.borrow_mut().clear());
}

/// Draws a placeholder over `corners` (pixels of `area`) that [`apply`]
/// replaces by `content`, SVG elements in the document's coordinates:
/// shapes plotters would round to whole pixels (a contact map's nodes,
/// smaller than a pixel on a fine grid).
pub(super) fn raw(area: &Area, corners: [(i32, i32); 2], content: String) -> anyhow::Result<()> {
    RAW.with(|f| f.borrow_mut().push(content));
    area.draw(&Rectangle::new(corners, PLACEHOLDER.filled()))
        .map_err(plot_err)
}

/// The exact backend coordinates of drawn point `(u, v)` on `c`: plotters'
/// own linear map (its pixel range, its logical range) without the floor.
pub(super) fn exact(c: &Chart, (u, v): (f64, f64)) -> (f64, f64) {
    let (xr, yr) = c.plotting_area().get_pixel_range();
    let (xs, ys) = (c.x_range(), c.y_range());
    // plotters maps x onto [start, end − 1] and y onto [end − 1, start].
    let (x0, x1) = (f64::from(xr.start), f64::from(xr.end - 1));
    let (y0, y1) = (f64::from(yr.end - 1), f64::from(yr.start));
    let t = |w: f64, r: &std::ops::Range<f64>| {
        if r.end == r.start {
            0.5
        } else {
            (w - r.start) / (r.end - r.start)
        }
    };
    (x0 + (x1 - x0) * t(u, &xs), y0 + (y1 - y0) * t(v, &ys))
}

/// Draws the polyline `pts` (drawn coordinates) on `c` with `style`, its
/// exact coordinates recorded for [`apply`].
pub(super) fn path(c: &mut Chart, pts: Vec<(f64, f64)>, style: ShapeStyle) -> anyhow::Result<()> {
    let mut rounded = String::new();
    let mut fine = String::new();
    for p in &pts {
        let (x, y) = c.backend_coord(p);
        let (fx, fy) = exact(c, *p);
        // Where the exact point is not within a pixel of plotters' (a
        // point far off the chart), plotters' stays.
        let (fx, fy) = if (fx - f64::from(x)).abs() <= 1.0 && (fy - f64::from(y)).abs() <= 1.0 {
            (fx, fy)
        } else {
            (f64::from(x), f64::from(y))
        };
        let _ = write!(rounded, "{x},{y} ");
        let _ = write!(fine, "{},{} ", decimals(fx), decimals(fy));
    }
    FINE.with(|f| f.borrow_mut().push((rounded, fine.trim_end().to_string())));
    c.draw_series(std::iter::once(PathElement::new(pts, style)))
        .map_err(plot_err)?;
    Ok(())
}

/// `v` with at most two decimals, trailing zeros dropped.
fn decimals(v: f64) -> String {
    let s = format!("{v:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

/// `svg` with the recorded polylines' points made exact: one pass over the
/// document, matching the recorded polylines in drawing order (a polyline
/// that was not recorded, a legend sample or a guide, stays as it is).
pub(super) fn apply(svg: &str) -> String {
    let recorded = FINE.with(|f| std::mem::take(&mut *f.borrow_mut()));
    let mut out = String::with_capacity(svg.len() + svg.len() / 4);
    let mut rest = svg;
    let mut next = recorded.iter().peekable();
    const KEY: &str = " points=\"";
    while let Some(at) = rest.find(KEY) {
        let start = at + KEY.len();
        let Some(len) = rest[start..].find('"') else {
            break;
        };
        out.push_str(&rest[..start]);
        let points = &rest[start..start + len];
        match next.peek() {
            Some((rounded, fine)) if rounded == points => {
                out.push_str(fine);
                next.next();
            }
            _ => out.push_str(points),
        }
        rest = &rest[start + len..];
    }
    out.push_str(rest);
    let fill = format!(
        "fill=\"#{:02X}{:02X}{:02X}\"",
        PLACEHOLDER.0, PLACEHOLDER.1, PLACEHOLDER.2
    );
    for content in RAW.with(|f| std::mem::take(&mut *f.borrow_mut())) {
        let Some(at) = out.find(&fill) else { break };
        let start = out[..at].rfind("<rect").unwrap_or(at);
        let end = out[at..].find("/>").map_or(at, |e| at + e + 2);
        out.replace_range(start..end, &content);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::decimals;

    #[test]
    fn two_decimals_trimmed() {
        assert_eq!(decimals(12.0), "12");
        assert_eq!(decimals(12.345), "12.35");
        assert_eq!(decimals(12.5), "12.5");
        assert_eq!(decimals(-0.001), "0");
    }
}
