//! The contact view's map: the solved surface's nodes drawn on the
//! terminal's points, each block's shares dithered (not its most loaded
//! node), with its legend and scale.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::{ELASTIC, PLASTIC};
use crate::contact::scene::Node;
use crate::tui::theme::Theme;

/// The map's legend in `area` (one row), the hardness named `h`, with its
/// scale where it fits.
pub(super) fn map_legend(t: &Theme, h: &str, scale: &str, area: Rect, buf: &mut Buffer) {
    let (e, p) = node_look(t, Node::Elastic, Node::Plastic);
    let mut spans = vec![
        Span::styled(e.0, e.1),
        Span::raw(" elastic "),
        Span::styled(p.0, p.1),
        Span::raw(format!(" at {h}")),
    ];
    let tail = t.glyphs.text(&format!(" · {scale}")).into_owned();
    let used: usize = spans.iter().map(Span::width).sum();
    if !scale.is_empty() && used + Span::raw(tail.as_str()).width() <= usize::from(area.width) {
        spans.push(Span::styled(tail, t.dim));
    }
    Line::from(spans).render(area, buf);
}

/// A one-point swatch of each of two node kinds (legend).
fn node_look(t: &Theme, a: Node, b: Node) -> ((&'static str, Style), (&'static str, Style)) {
    let one = |k: Node| -> (&'static str, Style) {
        if t.color {
            let c = if k == Node::Plastic { PLASTIC } else { ELASTIC };
            if t.glyphs.ascii_only() {
                (" ", Style::new().bg(c))
            } else {
                ("█", Style::new().fg(c))
            }
        } else {
            (plain_char(t, k), Style::new())
        }
    };
    (one(a), one(b))
}

/// A node's character without colour.
fn plain_char(t: &Theme, k: Node) -> &'static str {
    match (k, t.glyphs.ascii_only()) {
        (Node::Out, _) => " ",
        (Node::Elastic, true) => "o",
        (Node::Plastic, true) => "#",
        (Node::Elastic, false) => "░",
        (Node::Plastic, false) => "█",
    }
}

/// The map drawn on `cols` × `rows` points: each point stands for a block
/// of nodes and shows one kind, chosen by error diffusion (Floyd–Steinberg)
/// of the blocks' shares of out-of-contact, elastic and plastic nodes, so
/// that the drawn shares follow the map's (a block a quarter in contact is
/// drawn in contact one point in four, not every time as the most loaded
/// node would have it). Row-major, `rows` × `cols`.
pub fn dithered(map: &[Node], n: usize, cols: usize, rows: usize) -> Vec<Node> {
    if n == 0 || cols == 0 || rows == 0 || map.len() != n * n {
        return vec![];
    }
    let span = |i: usize, of: usize| (i * n / of, ((i + 1) * n / of).max(i * n / of + 1).min(n));
    // Each point's shares of the three kinds, then the error carried over.
    let mut want = vec![[0.0f64; 3]; cols * rows];
    for r in 0..rows {
        let (y0, y1) = span(r, rows);
        for c in 0..cols {
            let (x0, x1) = span(c, cols);
            let mut count = [0usize; 3];
            for y in y0..y1 {
                for &v in &map[y * n + x0..y * n + x1] {
                    count[v as usize] += 1;
                }
            }
            let total = ((y1 - y0) * (x1 - x0)) as f64;
            want[r * cols + c] = count.map(|k| k as f64 / total);
        }
    }
    let mut out = vec![Node::Out; cols * rows];
    // Rows alternate direction (serpentine); the weights of neighbours off
    // the picture go to those on it, so that no share is lost at the edges.
    for r in 0..rows {
        let forward = r % 2 == 0;
        for step in 0..cols {
            let c = if forward { step } else { cols - 1 - step };
            let i = r * cols + c;
            let w = want[i];
            let k = (0..3).max_by(|&a, &b| w[a].total_cmp(&w[b])).unwrap_or(0);
            out[i] = [Node::Out, Node::Elastic, Node::Plastic][k];
            let mut err = w;
            err[k] -= 1.0;
            let ahead = if forward { c + 1 < cols } else { c > 0 };
            let next = |c: usize| if forward { c + 1 } else { c - 1 };
            let back = |c: usize| {
                if forward {
                    c.checked_sub(1)
                } else {
                    (c + 1 < cols).then_some(c + 1)
                }
            };
            let mut to: Vec<(usize, f64)> = vec![];
            if ahead {
                to.push((r * cols + next(c), 7.0));
            }
            if r + 1 < rows {
                if let Some(b) = back(c) {
                    to.push(((r + 1) * cols + b, 3.0));
                }
                to.push(((r + 1) * cols + c, 5.0));
                if ahead {
                    to.push(((r + 1) * cols + next(c), 1.0));
                }
            }
            let total: f64 = to.iter().map(|t| t.1).sum();
            for (j, f) in to {
                for (a, e) in want[j].iter_mut().zip(err) {
                    *a += f / total * e;
                }
            }
        }
    }
    out
}

/// How many nodes a point of a `side`-point-wide map of an `n`-node grid
/// stands for, in words ("1 point = 4 × 4 nodes").
pub fn map_scale(n: usize, side: usize) -> String {
    if side == 0 || n == 0 {
        return String::new();
    }
    let k = n as f64 / side as f64;
    if k <= 1.0 {
        "1 point = 1 node".into()
    } else if k.fract() == 0.0 {
        format!("1 point = {k:.0} × {k:.0} nodes")
    } else {
        format!("1 point ≈ {k:.1} × {k:.1} nodes")
    }
}

/// The whole periodic cell, dithered ([`dithered`]): half blocks (two
/// points a cell) in colour, one character a cell without colour or in
/// ASCII.
pub(super) fn draw_map(t: &Theme, map: &[Node], n: usize, area: Rect, buf: &mut Buffer) {
    if n == 0 || map.len() != n * n || area.width == 0 || area.height == 0 {
        return;
    }
    let side = usize::from(area.width);
    let rows = usize::from(area.height);
    let colour = |k: Node| match k {
        Node::Out => Color::Reset,
        Node::Elastic => ELASTIC,
        Node::Plastic => PLASTIC,
    };
    let half = t.color && !t.glyphs.ascii_only();
    let points = dithered(map, n, side, if half { 2 * rows } else { rows });
    for r in 0..rows {
        for c in 0..side {
            let cell = &mut buf[(area.x + c as u16, area.y + r as u16)];
            if !half {
                let k = points[r * side + c];
                if t.color {
                    cell.set_symbol(" ").set_style(Style::new().bg(colour(k)));
                } else {
                    cell.set_symbol(plain_char(t, k));
                }
                continue;
            }
            let (up, low) = (points[2 * r * side + c], points[(2 * r + 1) * side + c]);
            match (up, low) {
                (Node::Out, Node::Out) => {
                    cell.set_symbol(" ");
                }
                (Node::Out, l) => {
                    cell.set_symbol("▄").set_style(Style::new().fg(colour(l)));
                }
                (u, Node::Out) => {
                    cell.set_symbol("▀").set_style(Style::new().fg(colour(u)));
                }
                (u, l) => {
                    cell.set_symbol("▀")
                        .set_style(Style::new().fg(colour(u)).bg(colour(l)));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_dithered_map_keeps_the_shares() {
        // A 64² map, about 7 % in contact in small scattered patches, 1 % of
        // it at the hardness, drawn on 16² points: the most loaded node of
        // each 4 × 4 block would draw far more contact.
        let n = 64;
        let map: Vec<Node> = (0..n * n)
            .map(|i| {
                let v = (i * 2654435761usize) % 1000;
                if v < 10 {
                    Node::Plastic
                } else if v < 70 {
                    Node::Elastic
                } else {
                    Node::Out
                }
            })
            .collect();
        let share =
            |m: &[Node], k: Node| m.iter().filter(|v| **v == k).count() as f64 / m.len() as f64;
        let d = dithered(&map, n, 16, 16);
        assert_eq!(d.len(), 256);
        for k in [Node::Elastic, Node::Plastic] {
            assert!(
                (share(&d, k) - share(&map, k)).abs() <= 2.0 / 256.0,
                "{k:?}: {} drawn, {} in the map",
                share(&d, k),
                share(&map, k)
            );
        }
        assert_eq!(map_scale(64, 16), "1 point = 4 × 4 nodes");
        assert_eq!(map_scale(1024, 40), "1 point ≈ 25.6 × 25.6 nodes");
    }
}
