//! The pictures' structure as snapshots (insta): for each view of fig2 and
//! fig4 and the example surface's spectrum, the title, the description,
//! every text in reading order and how many of each element are drawn, so
//! that a change to what a picture says or holds shows in review.

mod common;

use common::cli::stdout;

fn structure(args: &[&str]) -> String {
    let svg = stdout(&[&["export", "--format", "svg"][..], args].concat());
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let mut out = String::new();
    let mut counts = std::collections::BTreeMap::new();
    for n in doc.descendants().filter(|n| n.is_element()) {
        *counts.entry(n.tag_name().name().to_string()).or_insert(0) += 1;
        match n.tag_name().name() {
            "title" | "desc" => {
                out.push_str(&format!("<{}>\n", n.tag_name().name()));
                for l in n.text().unwrap_or("").lines() {
                    // The version moves with every release.
                    let l = l.replace(env!("CARGO_PKG_VERSION"), "VERSION");
                    out.push_str(&format!("  {l}\n"));
                }
            }
            "text" => {
                let t = n.text().unwrap_or("").trim();
                if !t.is_empty() {
                    out.push_str(&format!("text {t}\n"));
                }
            }
            _ => {}
        }
    }
    // Only whether lines and cells are there: their number follows the data.
    for (tag, n) in counts {
        let n = if matches!(tag.as_str(), "polyline" | "rect" | "line" | "circle") {
            if n > 0 {
                "some".to_string()
            } else {
                "none".to_string()
            }
        } else {
            n.to_string()
        };
        out.push_str(&format!("count {tag}: {n}\n"));
    }
    out
}

#[test]
fn each_view_of_fig2_and_fig4() {
    for preset in ["fig2", "fig4"] {
        for view in ["slopes", "indices", "map", "load"] {
            let s = structure(&["--preset", preset, "--view", view]);
            insta::assert_snapshot!(format!("{preset}_{view}"), s);
        }
    }
}

#[test]
fn the_example_surfaces_spectrum() {
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/surfaces/example.txt");
    let s = structure(&["--surface", example, "--view", "spectrum"]);
    insta::assert_snapshot!("example_spectrum", s);
}
