//! The explorer drawn without a terminal: insta snapshots of each preset at
//! 80×24 and 160×48, and the drawing at sizes down to 1×1.

mod common;

use ratatui::backend::TestBackend;
use ratatui::Terminal;
use roughtui::presets;
use roughtui::tui::app::{update, App, Message};
use roughtui::tui::theme::Theme;

fn draw(app: &App) -> Terminal<TestBackend> {
    let (w, h) = app.size;
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
    t
}

fn text(t: &Terminal<TestBackend>) -> String {
    common::buffer_text(t)
}

fn app(name: &str, size: (u16, u16), theme: Theme) -> App {
    App::new(presets::load(name).unwrap(), theme, size)
}

fn braille_cells(s: &str) -> usize {
    s.chars()
        .filter(|c| ('\u{2801}'..='\u{28FF}').contains(c))
        .count()
}

#[test]
fn presets_at_80x24() {
    for name in ["fig1", "fig2", "fig3", "fig4"] {
        let t = draw(&app(name, (80, 24), Theme::colored()));
        let s = text(&t);
        assert!(braille_cells(&s) > 30, "{name}: {}", braille_cells(&s));
        assert!(s.contains(&format!("[{name}]")));
        insta::assert_snapshot!(format!("{name}_80x24"), s);
    }
}

#[test]
fn presets_at_160x48() {
    for name in ["fig1", "fig2", "fig3", "fig4"] {
        let t = draw(&app(name, (160, 48), Theme::colored()));
        insta::assert_snapshot!(format!("{name}_160x48"), text(&t));
    }
}

#[test]
fn help_overlay_at_80x24() {
    let mut a = app("fig2", (80, 24), Theme::colored());
    update(&mut a, Message::ToggleHelp);
    insta::assert_snapshot!("help_80x24", text(&draw(&a)));
}

#[test]
fn fig2_plain_at_100x30() {
    let t = draw(&app("fig2", (100, 30), Theme::plain()));
    insta::assert_snapshot!("fig2_plain_100x30", text(&t));
}

#[test]
fn any_size_draws_without_panic() {
    let mut a = app("fig4", (80, 24), Theme::colored());
    for (w, h) in [
        (1, 1),
        (0, 0),
        (40, 12),
        (79, 24),
        (80, 23),
        (80, 24),
        (81, 25),
        (300, 100),
    ] {
        roughtui::tui::app::update(&mut a, Message::Resize(w, h));
        let t = draw(&a);
        if w < 80 || h < 24 {
            if w >= 40 {
                assert!(text(&t).contains("enlarge the terminal"), "{w}x{h}");
            }
        } else {
            assert!(braille_cells(&text(&t)) > 60, "{w}x{h}");
        }
    }
}

#[test]
fn plain_theme_tells_curves_apart_by_marker() {
    let s = text(&draw(&app("fig2", (100, 30), Theme::plain())));
    for m in ['•', '+', 'o'] {
        assert!(s.matches(m).count() > 5, "marker {m} in\n{s}");
    }
    // The total (braille) lies under Persson's curve up to ζ ≈ 2000 and
    // leaves it above: both are listed, not "Persson = total here".
    assert!(braille_cells(&s) > 10);
    assert!(s.contains("•• elastic") && s.contains("++ plastic"));
    assert!(s.contains(" total ") && s.contains("oo Persson"), "{s}");
    assert!(!s.contains("= total here"), "{s}");
}

#[test]
fn hurst_and_r_star_sweeps_label_their_axes() {
    let mut a = app("fig3", (80, 24), Theme::colored());
    update(&mut a, Message::CycleSweep);
    let s = text(&draw(&a));
    assert!(
        s.contains("0.1") && s.contains("1.0") && s.contains("H 0.05…1 · closed form"),
        "{s}"
    );
    update(&mut a, Message::CycleSweep);
    let s = text(&draw(&a));
    assert!(
        s.contains("1 µm") && s.contains("10 mm") && s.contains("R* = 1.00 mm"),
        "{s}"
    );
    insta::assert_snapshot!("fig3_sweep_r_star_80x24", s);
}

#[test]
fn help_symbols_line_up_even_with_a_combining_bar() {
    let mut a = app("fig2", (160, 48), Theme::colored());
    update(&mut a, Message::ToggleHelp);
    // The page that holds p̄'s line.
    for _ in 0..4 {
        let t = draw(&a);
        let buf = t.backend().buffer();
        // The cell column where `text` starts, reading cell by cell.
        let column = |text: &str| {
            let n = text.chars().count() as u16;
            (0..buf.area.height)
                .flat_map(|y| (0..buf.area.width.saturating_sub(n)).map(move |x| (x, y)))
                .find(|&(x, y)| {
                    let s: String = (x..x + n).map(|i| buf[(i, y)].symbol()).collect();
                    s.starts_with(text)
                })
                .map(|(x, _)| x)
        };
        if let Some(pressure) = column("mean (nominal) contact pressure") {
            assert_eq!(Some(pressure), column("their sum, the total"));
            assert_eq!(Some(pressure), column("Persson's purely elastic slope"));
            return;
        }
        update(&mut a, Message::HelpPage { next: true });
    }
    panic!("no page of the help holds p̄'s line");
}
