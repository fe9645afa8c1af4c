//! A picture read back from its SVG as geometry: its texts with the boxes
//! they take (estimated from the font size: 0.6 em a character bounds a
//! sans-serif's digits and letters), its polylines and circles in pixels,
//! the legend box, the plot's frame; so that tests measure what a person
//! looks at (overlaps, spans, labels), not only that the file parses.

use super::cli::stdout;

/// A text of the picture and the box it takes, in pixels.
#[derive(Clone, Debug)]
pub struct Text {
    pub text: String,
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
    pub size: f64,
    /// Drawn turned (the y axis' description).
    pub turned: bool,
}

impl Text {
    pub fn overlaps(&self, o: &Text) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }
}

/// A stroked line: its colour, width and points.
#[derive(Clone, Debug)]
pub struct Line {
    pub stroke: String,
    pub width: f64,
    pub dashed: bool,
    pub points: Vec<(f64, f64)>,
}

#[derive(Clone, Debug)]
pub struct Dot {
    pub x: f64,
    pub y: f64,
    pub r: f64,
    pub fill: String,
}

pub struct Picture {
    pub svg: String,
    pub width: f64,
    pub height: f64,
    pub texts: Vec<Text>,
    pub lines: Vec<Line>,
    pub dots: Vec<Dot>,
    /// Rectangles (x0, y0, x1, y1, fill, opacity).
    pub rects: Vec<(f64, f64, f64, f64, String, String)>,
    pub desc: String,
    pub title: String,
}

fn num(n: &roxmltree::Node, a: &str) -> f64 {
    n.attribute(a)
        .unwrap_or_else(|| panic!("no {a} in {n:?}"))
        .parse()
        .unwrap()
}

pub fn points(p: &str) -> Vec<(f64, f64)> {
    p.split_whitespace()
        .map(|xy| {
            let (x, y) = xy.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

impl Picture {
    /// `roughtui export --format svg ARGS…`, read back.
    pub fn export(args: &[&str]) -> Picture {
        Picture::parse(&stdout(
            &[&["export", "--format", "svg"][..], args].concat(),
        ))
    }

    pub fn parse(svg: &str) -> Picture {
        let doc = roxmltree::Document::parse(svg).unwrap();
        let root = doc.root_element();
        let mut p = Picture {
            svg: svg.to_string(),
            width: num(&root, "width"),
            height: num(&root, "height"),
            texts: vec![],
            lines: vec![],
            dots: vec![],
            rects: vec![],
            desc: String::new(),
            title: String::new(),
        };
        for n in doc.descendants().filter(|n| n.is_element()) {
            match n.tag_name().name() {
                "desc" => p.desc = n.text().unwrap_or("").to_string(),
                "title" => p.title = n.text().unwrap_or("").to_string(),
                "text" => {
                    let t = n.text().unwrap_or("").trim().to_string();
                    if t.is_empty() {
                        continue;
                    }
                    let size = num(&n, "font-size");
                    let w = t.chars().count() as f64 * 0.6 * size;
                    let (x, y) = (num(&n, "x"), num(&n, "y"));
                    let x0 = match n.attribute("text-anchor") {
                        Some("middle") => x - w / 2.0,
                        Some("end") => x - w,
                        _ => x,
                    };
                    // The box from the cap height to the descenders:
                    // 0.95 em, the line's own height less its leading.
                    let h = 0.95 * size;
                    let top = match n.attribute("dy") {
                        Some("0.76em") => y,
                        Some("0.5ex") => y - h / 2.0,
                        Some("-0.5ex") => y - h,
                        // No dy: y is the baseline.
                        _ => y - 0.76 * size,
                    };
                    let turned = n.attribute("transform").is_some();
                    let (x0, y0, x1, y1) = if turned {
                        // Turned a quarter about (x, y): the box stands.
                        (x - size, y - w / 2.0, x, y + w / 2.0)
                    } else {
                        (x0, top, x0 + w, top + h)
                    };
                    p.texts.push(Text {
                        text: t,
                        x0,
                        y0,
                        x1,
                        y1,
                        size,
                        turned,
                    });
                }
                "polyline" | "line" | "path" => {
                    let pts = match n.tag_name().name() {
                        "polyline" => points(n.attribute("points").unwrap()),
                        "line" => vec![
                            (num(&n, "x1"), num(&n, "y1")),
                            (num(&n, "x2"), num(&n, "y2")),
                        ],
                        _ => continue,
                    };
                    p.lines.push(Line {
                        stroke: n.attribute("stroke").unwrap_or("").to_string(),
                        width: n
                            .attribute("stroke-width")
                            .and_then(|w| w.parse().ok())
                            .unwrap_or(1.0),
                        dashed: n.attribute("stroke-dasharray").is_some(),
                        points: pts,
                    });
                }
                "circle" => p.dots.push(Dot {
                    x: num(&n, "cx"),
                    y: num(&n, "cy"),
                    r: num(&n, "r"),
                    fill: n.attribute("fill").unwrap_or("").to_string(),
                }),
                "rect" => {
                    let (x, y) = (num(&n, "x"), num(&n, "y"));
                    p.rects.push((
                        x,
                        y,
                        x + num(&n, "width"),
                        y + num(&n, "height"),
                        n.attribute("fill").unwrap_or("").to_string(),
                        n.attribute("opacity").unwrap_or("").to_string(),
                    ));
                }
                _ => {}
            }
        }
        p
    }

    /// The texts equal to `t`.
    pub fn text(&self, t: &str) -> Vec<&Text> {
        self.texts.iter().filter(|x| x.text == t).collect()
    }

    /// Every pair of texts whose boxes overlap.
    pub fn overlapping_texts(&self) -> Vec<(String, String)> {
        let mut out = vec![];
        for (i, a) in self.texts.iter().enumerate() {
            for b in &self.texts[i + 1..] {
                if a.overlaps(b) {
                    out.push((a.text.clone(), b.text.clone()));
                }
            }
        }
        out
    }

    /// Texts that reach outside the picture.
    pub fn clipped_texts(&self) -> Vec<&Text> {
        self.texts
            .iter()
            .filter(|t| t.x0 < 0.0 || t.y0 < 0.0 || t.x1 > self.width || t.y1 > self.height)
            .collect()
    }

    /// The legend box: the rectangle drawn at 0.9 opacity.
    pub fn legend(&self) -> Option<(f64, f64, f64, f64)> {
        self.rects
            .iter()
            .find(|r| r.5 == "0.9")
            .map(|r| (r.0, r.1, r.2, r.3))
    }

    /// The plot's frame (x0, y0, x1, y1): where the grid lines run (the
    /// union of all panels' on a picture of several).
    pub fn frame(&self) -> (f64, f64, f64, f64) {
        let grid: Vec<&Line> = self
            .lines
            .iter()
            .filter(|l| {
                (l.stroke == "#E1E1E1" || l.stroke == "#FFFFFF")
                    && l.points.len() == 2
                    && l.width == 1.0
            })
            .collect();
        assert!(!grid.is_empty(), "no grid lines");
        let pts = grid.iter().flat_map(|l| l.points.iter());
        pts.fold(
            (f64::MAX, f64::MAX, f64::MIN, f64::MIN),
            |(a, b, c, d), &(x, y)| (a.min(x), b.min(y), c.max(x), d.max(y)),
        )
    }

    /// The tick labels left of `x` (the y axis') or under `y` (the x
    /// axis'): short texts beside the frame.
    pub fn tick_labels(&self) -> (Vec<&Text>, Vec<&Text>) {
        let (x0, _, _, y1) = self.frame();
        let short = |t: &&Text| t.text.chars().count() <= 6 && !t.turned;
        let ys = self
            .texts
            .iter()
            .filter(short)
            .filter(|t| t.x1 <= x0 && t.x1 >= x0 - 20.0)
            .collect();
        let xs = self
            .texts
            .iter()
            .filter(short)
            .filter(|t| t.y0 >= y1 && t.y0 <= y1 + 20.0)
            .collect();
        (ys, xs)
    }

    /// The lines drawn in `stroke` at width 2 (the curves).
    pub fn curves(&self, stroke: &str) -> Vec<&Line> {
        self.lines
            .iter()
            .filter(|l| l.stroke == stroke && l.width >= 2.0 && l.points.len() > 2)
            .collect()
    }
}

/// The largest distance (px) of `pts` from the straight line through
/// their ends.
pub fn off_straight(pts: &[(f64, f64)]) -> f64 {
    let (a, b) = (pts[0], pts[pts.len() - 1]);
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len = (dx * dx + dy * dy).sqrt();
    pts.iter()
        .map(|p| ((p.0 - a.0) * dy - (p.1 - a.1) * dx).abs() / len)
        .fold(0.0, f64::max)
}
