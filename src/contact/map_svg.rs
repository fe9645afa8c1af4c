//! The contact map as SVG: the periodic cell seen from the half-space, one
//! node a square, out of contact white, elastic grey, at the hardness blue
//! (the paper's plastic colour). Consecutive nodes of a row in the same
//! state are one rectangle, so the file grows with the contact's outline,
//! not with N².

use std::fmt::Write as _;

use super::scene::Node;

/// Side of the map in the picture, px.
const SIDE: f64 = 600.0;
const MARGIN: f64 = 20.0;
const TOP: f64 = 60.0;
const ELASTIC: &str = "#8c8c8c";
const PLASTIC: &str = "#0000ff";

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// `map` (n × n, row-major, row 0 at the top) under `title`, with a legend
/// line `note`.
pub fn map_svg(map: &[Node], n: usize, title: &str, note: &str) -> String {
    let cell = SIDE / n.max(1) as f64;
    let (w, h) = (SIDE + 2.0 * MARGIN, SIDE + TOP + MARGIN + 30.0);
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" shape-rendering="crispEdges">"#
    );
    let _ = write!(
        s,
        r#"<rect x="0" y="0" width="{w}" height="{h}" fill="white"/>"#
    );
    let _ = write!(
        s,
        r#"<text x="{MARGIN}" y="26" font-family="sans-serif" font-size="16">{}</text>"#,
        escape(title)
    );
    let _ = write!(
        s,
        r#"<text x="{MARGIN}" y="46" font-family="sans-serif" font-size="13">{}</text>"#,
        escape(note)
    );
    let _ = write!(
        s,
        r#"<rect x="{MARGIN}" y="{TOP}" width="{SIDE}" height="{SIDE}" fill="white" stroke="black"/>"#
    );
    if map.len() == n * n {
        for y in 0..n {
            let row = &map[y * n..(y + 1) * n];
            let mut x = 0;
            while x < n {
                let k = row[x];
                let run = row[x..].iter().take_while(|v| **v == k).count();
                let fill = match k {
                    Node::Out => None,
                    Node::Elastic => Some(ELASTIC),
                    Node::Plastic => Some(PLASTIC),
                };
                if let Some(fill) = fill {
                    let _ = write!(
                        s,
                        r#"<rect x="{:.3}" y="{:.3}" width="{:.3}" height="{:.3}" fill="{fill}"/>"#,
                        MARGIN + x as f64 * cell,
                        TOP + y as f64 * cell,
                        run as f64 * cell,
                        cell
                    );
                }
                x += run;
            }
        }
    }
    let ly = TOP + SIDE + 22.0;
    let _ = write!(
        s,
        r#"<rect x="{MARGIN}" y="{}" width="14" height="14" fill="{ELASTIC}"/><text x="{}" y="{ly}" font-family="sans-serif" font-size="13">elastic (0 &lt; p &lt; H)</text>"#,
        ly - 12.0,
        MARGIN + 20.0
    );
    let _ = write!(
        s,
        r#"<rect x="{}" y="{}" width="14" height="14" fill="{PLASTIC}"/><text x="{}" y="{ly}" font-family="sans-serif" font-size="13">at the hardness (p = H)</text>"#,
        MARGIN + 180.0,
        ly - 12.0,
        MARGIN + 200.0
    );
    s.push_str("</svg>\n");
    s
}

/// The title and legend line of a map of the scene `name` on an n² grid.
pub fn caption(
    name: &str,
    n: usize,
    seed: Option<u64>,
    p_over_h: f64,
    area: f64,
    plastic: f64,
) -> (String, String) {
    let share = if area > 0.0 { plastic / area } else { 0.0 };
    let (what, cell) = match seed {
        Some(seed) => (format!("seed {seed}"), "the periodic cell of side 2π/q0"),
        None => (
            "measured map".to_string(),
            "the map's solved square (its crop: export --view contact)",
        ),
    };
    (
        format!(
            "{name}: contact map at p̄ = {} H, {n}×{n}, {what}",
            crate::physical::print::load_text(p_over_h)
        ),
        format!(
            "A/A0 = {:.4} %, {:.1} % of it at the hardness; {cell}",
            100.0 * area,
            100.0 * share
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_of_a_row_are_one_rectangle() {
        use Node::{Elastic as E, Out as O, Plastic as P};
        let map = [O, E, E, P, O, O, O, O, E, E, E, E, O, O, O, O];
        let svg = map_svg(&map, 4, "t <1>", "n");
        // Background, frame, 3 runs, 2 legend swatches.
        assert_eq!(svg.matches("<rect").count(), 2 + 3 + 2, "{svg}");
        assert!(svg.contains("t &lt;1&gt;"));
        assert!(
            svg.contains(
                r##"x="170.000" y="60.000" width="300.000" height="150.000" fill="#8c8c8c""##
            ),
            "{svg}"
        );
        assert!(
            svg.contains(
                r##"x="470.000" y="60.000" width="150.000" height="150.000" fill="#0000ff""##
            ),
            "{svg}"
        );
        assert!(
            svg.contains(
                r##"x="20.000" y="360.000" width="600.000" height="150.000" fill="#8c8c8c""##
            ),
            "{svg}"
        );
    }
}
