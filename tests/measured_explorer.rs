//! The explorer on a file written here: the reader's notes on the status
//! row and under the readout, Sq and Sdq beside the spectral h_rms(ζ) and
//! h′(ζ), and the fit band moved with `[ ]` `{ }` and found again with `b`.

mod common;

use common::app::{ch, screen};
use roughtui::scene::State;
use roughtui::surface::SurfaceSource;
use roughtui::tui::app::App;
use roughtui::tui::theme::Theme;

fn app(dir: &std::path::Path, size: (u16, u16)) -> App {
    let p = dir.join("map.txt");
    let mut t = String::from("# Width: 5 um\n# Height: 3.75 um\n");
    let mut s = 99u64;
    for _ in 0..24 {
        let mut v = 0.0;
        let row: Vec<String> = (0..32)
            .map(|_| {
                s = s
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                v += ((s >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.01;
                format!("{v:.6}")
            })
            .collect();
        t.push_str(&row.join(" "));
        t.push('\n');
    }
    std::fs::write(&p, t).unwrap();
    let src = SurfaceSource::read(&p, Default::default()).unwrap();
    App::new(State::measured(src).unwrap(), Theme::colored(), size)
}

#[test]
fn notes_show_on_the_status_row_and_under_the_readout() {
    let d = tempfile::tempdir().unwrap();
    let a = app(d.path(), (100, 40));
    let note = "heights read in µm (the width's unit; --height-unit to change)";
    let st = a.status.clone().unwrap();
    // Every note of the file on the status row, joined (this small map is
    // anisotropic too, and says so).
    assert!(st.text.split(" · ").any(|n| n == note), "{}", st.text);
    assert!(!st.error);
    let text = screen(&a);
    // Twice: under the readout and on the status row.
    assert!(text.matches("heights read in µm").count() >= 2, "{text}");
    for w in ["h_rms(ζ) ", "h′(ζ) ", "Sq ", "Sdq ", "H fit"] {
        assert!(text.contains(w), "wants {w:?} in\n{text}");
    }
    // The height parameters beside Sq, where there is room: Sa and Sz on
    // one line, Ssk and Sku on the next, as the readout prints them.
    use roughtui::physical::print::{fmt_len, fmt_num};
    let r = a.state.surface.as_ref().unwrap().measured.real.unwrap();
    let [sa, ssk, sku, sz] = r.heights();
    let line = |l: &str, v: String| format!("{l:<6}{v:<10}");
    for (w, next) in [
        (
            line("Sa", fmt_len(sa.1)),
            format!("Sz     {}", fmt_len(sz.1)),
        ),
        (
            line("Ssk", fmt_num(ssk.1)),
            format!("Sku    {}", fmt_num(sku.1)),
        ),
    ] {
        let want = format!("{w}{next}");
        assert!(text.contains(&want), "wants {want:?} in\n{text}");
    }
    // An 80 × 24 terminal keeps its readout for the model's numbers.
    let small = app(d.path(), (80, 24));
    assert!(!screen(&small).contains("Ssk"));
}

#[test]
fn the_fit_band_moves_with_its_keys() {
    let d = tempfile::tempdir().unwrap();
    let mut a = app(d.path(), (100, 40));
    let band = |a: &App| a.state.surface.as_ref().unwrap().fit_band().unwrap();
    let found = band(&a);
    ch(&mut a, ']');
    let moved = band(&a);
    assert!(
        moved.0 > found.0 && moved.1 == found.1,
        "{found:?} {moved:?}"
    );
    assert!(a.modified);
    let st = a.status.clone().unwrap().text;
    assert!(
        st.starts_with("fit band ") && st.contains("(b: the band found from the data): H"),
        "{st}"
    );
    ch(&mut a, '{');
    assert!(band(&a).1 < found.1);
    // The H the scene records follows the fit.
    let h = a.readout.fit.unwrap().fit.hurst;
    assert_eq!(a.state.params.hurst(), h.clamp(0.01, 1.0));
    ch(&mut a, 'b');
    assert_eq!(band(&a), found);
    assert!(a
        .status
        .clone()
        .unwrap()
        .text
        .contains("(found from the data)"));
    // Down past the first point: refused with the reason.
    for _ in 0..40 {
        ch(&mut a, '[');
    }
    let st = a.status.clone().unwrap();
    assert!(
        st.error && st.text.contains("cannot move that way"),
        "{}",
        st.text
    );
}
