//! The explorer on a measured surface, without a terminal: h_rms and H are
//! read-only lines, `a` says why it does not apply, Tab reaches the
//! spectrum view, `5` returns to the surface after a preset, `g` pins the
//! fitted power law, ζ steps cost no curve recomputation, claims find the
//! steps of a discrete spectrum; insta snapshots of the new views.

mod common;

use common::app::{ch, press, screen};
use common::measured::{fig2_state, line_state};
use crossterm::event::{KeyCode, KeyModifiers};
use ratatui::backend::TestBackend;
use ratatui::Terminal;
use rough_model::Axis;
use roughtui::figure::{claims, ClaimKind, View};
use roughtui::tui::app::{update, App, Message, Mode};
use roughtui::tui::ghost::GhostKind;
use roughtui::tui::theme::Theme;

fn surface(size: (u16, u16)) -> App {
    App::new(fig2_state(), Theme::colored(), size)
}

fn drawn(app: &App) -> String {
    let (w, h) = app.size;
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
    common::buffer_text(&t)
}

#[test]
fn a_surface_opens_on_the_papers_material_at_its_largest_zeta() {
    let a = surface((80, 24));
    let s = &a.state;
    assert_eq!(s.name, "fig2-psd");
    assert_eq!(
        (s.params.h0_over_e(), s.params.r_star(), s.size_effect),
        (0.01, 1e-3, true)
    );
    assert_eq!((s.sweep.axis(), s.sweep.from()), (Axis::Zeta, 1.0));
    assert_eq!(s.sweep.to(), s.params.zeta());
    assert!((s.params.zeta() - 1e4).abs() < 1e-9);
    assert_eq!(s.model, rough_model::Model::Exact);
    assert_eq!(a.selected_axis(), Axis::Zeta);
    let text = screen(&a);
    for w in [
        "[fig2-psd]",
        "exact · measured moments · size effect on",
        "√m0 at ζ",
        "H fit  0.80±0.00  q 1.0e5…1.0e9",
        "Ψ*asy n/a on measured data",
        "5 surface",
    ] {
        assert!(text.contains(w), "wants {w:?} in\n{text}");
    }
}

#[test]
fn h_rms_and_h_are_shown_not_set() {
    let mut a = surface((80, 24));
    // ↑ ↓ pass over them.
    ch(&mut a, 'k');
    assert_eq!(a.selected_axis(), Axis::H0OverE);
    ch(&mut a, 'j');
    assert_eq!(a.selected_axis(), Axis::Zeta);
    ch(&mut a, 'j');
    assert_eq!(a.selected_axis(), Axis::RStar);
    // Reached anyway (a follower's selection), they refuse to change.
    for (i, axis, words) in [
        (1, Axis::HRms, "h_rms is the data's on a measured surface"),
        (3, Axis::Hurst, "H is the data's on a measured surface"),
    ] {
        a.selected = i;
        let before = a.state.clone();
        ch(&mut a, 'l');
        assert_eq!(a.state, before, "{axis:?}");
        let st = a.status.clone().unwrap();
        assert!(st.error && st.text.starts_with(words), "{}", st.text);
        assert!(st.text.chars().count() <= 80, "{}", st.text);
        press(&mut a, KeyCode::Enter, KeyModifiers::NONE);
        assert_eq!(a.mode, Mode::Main);
    }
    ch(&mut a, 'a');
    let st = a.status.clone().unwrap();
    assert!(st
        .text
        .starts_with("a: a measured surface's moments are summed from its data"));
    assert!(st.text.chars().count() <= 80, "{}", st.text);
    assert_eq!(a.state.moments, rough_model::Moments::Truncated);
}

#[test]
fn zeta_steps_move_the_marker_and_the_measured_h_rms() {
    let mut a = surface((80, 24));
    let h = a.readout.surface.spectrum.h_rms_actual;
    let n = a.recomputes;
    ch(&mut a, 'h');
    assert!((a.state.params.zeta() - 10f64.powf(3.75)).abs() < 1e-9);
    assert_eq!(a.recomputes, n, "the swept value only moves the marker");
    let h2 = a.readout.surface.spectrum.h_rms_actual;
    assert!(h2 < h, "{h2} {h}");
    // √m0 of the band 1e5 … ζ q0 of the power law, m0 = πZ q0^(−2H)(1 − ζ^(−2H))/H.
    let z = a.state.params.zeta();
    let m0 = std::f64::consts::PI * 1e-8 / 0.8 * 1e5f64.powf(-1.6) * (1.0 - z.powf(-1.6));
    assert!((h2 / m0.sqrt() - 1.0).abs() < 1e-13, "{h2}");
    // The fit keeps its own band, the whole table's: not the cutoff's.
    let f = a.readout.fit.unwrap().fit;
    assert!((f.q_hi / 1e9 - 1.0).abs() < 1e-11, "{}", f.q_hi);
    // ζ stops at the data's end; typed beyond it, it is refused.
    for _ in 0..8 {
        ch(&mut a, 'l');
    }
    assert!((a.state.params.zeta() - 1e4).abs() < 1e-9);
    update(&mut a, Message::StartValue);
    for c in "2e4".chars() {
        ch(&mut a, c);
    }
    press(&mut a, KeyCode::Enter, KeyModifiers::NONE);
    let st = a.status.clone().unwrap();
    assert!(st.text.contains("beyond the data"), "{}", st.text);
}

#[test]
fn tab_reaches_the_spectrum_only_on_a_surface() {
    let mut a = surface((80, 24));
    let mut seen = vec![];
    for _ in 0..6 {
        seen.push(a.view);
        press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
    }
    assert_eq!(seen, View::ALL);
    assert_eq!(a.view, View::Slopes);
    press(&mut a, KeyCode::BackTab, KeyModifiers::SHIFT);
    assert_eq!(a.view, View::Contact);
    press(&mut a, KeyCode::BackTab, KeyModifiers::SHIFT);
    assert_eq!(a.view, View::Spectrum);
    let text = screen(&a);
    assert!(text.contains("C^iso (m⁴) vs q · H 0.80±0.00"), "{text}");
    // A preset has no spectrum: the view goes back to the slopes.
    ch(&mut a, '2');
    assert_eq!(a.view, View::Slopes);
    for _ in 0..4 {
        press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
        assert_ne!(a.view, View::Spectrum);
    }
    // 5 comes back to the surface as it opened.
    ch(&mut a, '5');
    assert_eq!(a.state, fig2_state());
    assert!(!a.modified);
    assert_eq!(
        a.status.clone().unwrap().text,
        "loaded fig2-psd (measured surface)"
    );
    // Without a surface, 5 is not a key.
    let mut p = common::app::fig("fig2");
    ch(&mut p, '5');
    assert_eq!(p.state.name, "fig2");
    assert!(!screen(&p).contains("5 surface"));
}

#[test]
fn sweeps_and_map_axes_are_the_surfaces_parameters() {
    let mut a = surface((80, 24));
    let mut axes = vec![];
    for _ in 0..3 {
        ch(&mut a, 'x');
        axes.push(a.state.sweep.axis());
    }
    assert_eq!(axes, [Axis::RStar, Axis::H0OverE, Axis::Zeta]);
    assert!((a.state.sweep.to() - 1e4).abs() < 1e-9);
    press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
    press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
    assert_eq!(a.view, View::Map);
    let mut ys = vec![];
    for _ in 0..3 {
        ch(&mut a, 'y');
        ys.push(a.map_y);
    }
    assert_eq!(
        ys,
        [Some(Axis::RStar), Some(Axis::H0OverE), Some(Axis::RStar)]
    );
}

#[test]
fn g_pins_the_fitted_power_law_then_the_curves() {
    let mut a = surface((80, 24));
    ch(&mut a, 'g');
    let g = a.ghost.clone().unwrap();
    assert_eq!(g.kind, GhostKind::Fit);
    // fig2's own power law: H 0.8, h_rms 19.8 nm, truncated, no surface.
    assert!(g.state.surface.is_none());
    assert!((g.state.params.hurst() - 0.8).abs() < 1e-12);
    assert!((g.state.params.h_rms() / 1.9816636488030044e-8 - 1.0).abs() < 1e-12);
    assert_eq!(
        g.label(&a.state),
        "ghost: power-law fit H 0.80, h_rms 19.8 nm"
    );
    // The measured curves lie on it (the table is that power law).
    let (p, q) = (&a.plot.total, &g.plot.total);
    assert_eq!(p.len(), q.len());
    for (u, v) in p.iter().zip(q) {
        assert!((u.1 - v.1).abs() < 1e-12, "{u:?} {v:?}");
    }
    assert!(screen(&a).contains("ghost: power-law fit H 0.80"));
    ch(&mut a, 'g');
    assert_eq!(a.ghost.as_ref().unwrap().kind, GhostKind::Curves);
    ch(&mut a, 'g');
    assert!(a.ghost.is_none());
    // A preset's fit ghost goes with the surface.
    ch(&mut a, 'g');
    ch(&mut a, '2');
    assert!(a.ghost.is_none());
}

#[test]
fn claims_on_a_step_function_find_the_step() {
    let mut s = line_state();
    // Ψ_P without the size effect, H0/E chosen so that it passes 1
    // between ζ = 20 and 21: a jump at the data's 21st wavevector.
    s.size_effect = false;
    let m = |z: f64| s.roughness().table().unwrap().at_zeta(z).m2;
    let h0e = ((0.5 * (m(20.0) + m(21.0))) / 2.0).sqrt();
    s.params = s.params.with(Axis::H0OverE, h0e).unwrap();
    let c = claims(&s);
    let one = c.iter().find(|c| c.kind == ClaimKind::IndexOne).unwrap();
    assert!(one.step && one.rising);
    assert!((one.at - 21.0).abs() < 1e-9, "{}", one.at);
    assert_eq!(one.text(), "Ψ_P jumps past 1 at ζ = 21");
    // Just below the step Ψ_P < 1, at it > 1.
    let psi = |z: f64| {
        let p = s.params.with(Axis::Zeta, z).unwrap();
        s.roughness().indices(&p, s.moments).psi_p
    };
    assert!(psi(21.0 * (1.0 - 1e-9)) < 1.0 && psi(21.0) > 1.0);
    // The explorer shows it on the claims line.
    let a = App::new(s, Theme::plain(), (100, 30));
    assert!(screen(&a).contains("Ψ_P jumps past 1 at ζ = 21"));
}

#[test]
fn a_minimum_on_steps_is_where_the_slope_drops_to_it() {
    // SurfaceTopography's line scan of 1024 points (rough-surface's test
    // data) with R* = 10 µm: the size effect lifts the total slope again
    // at fine scales, and the lowest step lies inside the sweep.
    let p = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/crates/rough-surface/tests/data/line_xz.txt"
    );
    let src = roughtui::surface::SurfaceSource::read(p.as_ref(), Default::default()).unwrap();
    let mut s = roughtui::scene::State::measured(src).unwrap();
    roughtui::scene::set(&mut s, Axis::RStar, "10um").unwrap();
    let c = claims(&s);
    let min = c
        .iter()
        .find(|c| c.kind == ClaimKind::TotalMinimum)
        .unwrap();
    assert!(min.step, "{min:?}");
    // At one of the data's wavevectors (a line's: integer multiples of q0).
    assert!((min.at - min.at.round()).abs() < 1e-9, "{}", min.at);
    let total = |z: f64| {
        let p = s.params.with(Axis::Zeta, z).unwrap();
        let (psi, _) = s.roughness().psi_in_use(&p, s.size_effect, s.moments);
        rough_model::slopes(s.model, psi).total
    };
    // The slope takes its minimum there, and was higher just before.
    assert_eq!(total(min.at), min.value);
    assert!(total(min.at * (1.0 - 1e-9)) > min.value);
    assert!(total(min.at + 0.5) >= min.value);
    assert!(
        min.text() == "total slope drops to its minimum 11.53 at ζ = 266",
        "{}",
        min.text()
    );
}

#[test]
fn snapshots_of_the_measured_views() {
    for size in [(80, 24), (160, 48)] {
        let mut a = surface(size);
        let tag = format!("{}x{}", size.0, size.1);
        insta::assert_snapshot!(format!("surface_slopes_{tag}"), drawn(&a));
        update(&mut a, Message::PrevView);
        update(&mut a, Message::PrevView);
        assert_eq!(a.view, View::Spectrum);
        // The cutoff inside the data: q1 = 1e7.
        for _ in 0..8 {
            ch(&mut a, 'h');
        }
        insta::assert_snapshot!(format!("surface_spectrum_{tag}"), drawn(&a));
        for _ in 0..3 {
            update(&mut a, Message::NextView);
        }
        insta::assert_snapshot!(format!("surface_indices_{tag}"), drawn(&a));
    }
    let a = App::new(line_state(), Theme::plain(), (80, 24));
    insta::assert_snapshot!("line_slopes_80x24_plain", drawn(&a));
}

/// Every character of a measured surface's screens in the ASCII set: the
/// six views (the spectrum's title, axes and legend), the read-only h_rms
/// and H lines, the help's pages with the surface's symbols, the fitted
/// ghost and `a`'s refusal on the status line.
#[test]
fn a_surface_in_the_ascii_set_draws_only_ascii() {
    use roughtui::tui::glyphs::Glyphs;
    use roughtui::tui::theme::Palette;
    let bad = |s: &str| -> Vec<char> { s.chars().filter(|c| !c.is_ascii()).collect() };
    for size in [(80, 24), (160, 48)] {
        for state in [fig2_state(), line_state()] {
            let mut a = App::new(
                state,
                Theme::new(Glyphs::Ascii, Palette::Ansi16, true),
                size,
            );
            for _ in 0..6 {
                let s = drawn(&a);
                assert!(
                    bad(&s).is_empty(),
                    "{:?} {size:?}: {:?}\n{s}",
                    a.view,
                    bad(&s)
                );
                update(&mut a, Message::NextView);
            }
            ch(&mut a, 'g');
            let s = drawn(&a);
            assert!(s.contains("ghost: power-law fit H"), "{s}");
            assert!(bad(&s).is_empty(), "{:?} {s}", bad(&s));
            ch(&mut a, 'a');
            let s = drawn(&a);
            assert!(s.contains("moments are summed from its data"), "{s}");
            assert!(bad(&s).is_empty(), "{:?} {s}", bad(&s));
            ch(&mut a, '?');
            let mut help = String::new();
            for _ in 0..4 {
                let s = drawn(&a);
                assert!(bad(&s).is_empty(), "help {size:?}: {:?}\n{s}", bad(&s));
                help.push_str(&s);
                press(&mut a, KeyCode::Right, KeyModifiers::NONE);
            }
            for (sym, what) in roughtui::tui::help::MEASURED_SYMBOLS {
                let first: String = what.chars().take(20).collect();
                assert!(help.contains(&first), "{sym}: {first}\n{help}");
            }
        }
    }
    let mut a = App::new(
        fig2_state(),
        Theme::new(Glyphs::Ascii, Palette::Ansi16, false),
        (80, 24),
    );
    update(&mut a, Message::PrevView);
    update(&mut a, Message::PrevView);
    for _ in 0..8 {
        ch(&mut a, 'h');
    }
    insta::assert_snapshot!("surface_spectrum_80x24_ascii", drawn(&a));
    update(&mut a, Message::NextView);
    update(&mut a, Message::NextView);
    insta::assert_snapshot!("surface_slopes_80x24_ascii", drawn(&a));
}

#[test]
fn a_lay_says_so_on_the_spectrum_view() {
    let lay = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("crates/rough-surface/tests/data/map_lay.txt");
    let src = roughtui::surface::SurfaceSource::read(&lay, Default::default()).unwrap();
    let state = roughtui::scene::State::measured(src).unwrap();
    let mut a = App::new(state, Theme::colored(), (160, 48));
    press(&mut a, KeyCode::BackTab, KeyModifiers::SHIFT);
    press(&mut a, KeyCode::BackTab, KeyModifiers::SHIFT);
    assert_eq!(a.view, View::Spectrum);
    let text = screen(&a);
    // scripts/direction_reference.py: h′x/h′y = 0.309/0.0854 = 3.62; Ψ_P
    // = h′/(√2 H0/E) at the scene's H0/E = 0.01.
    assert!(
        text.contains("anisotropic: h′x/h′y = 3.62, Ψ_P across 21.9, along 6.04"),
        "{text}"
    );
    // An isotropic surface says nothing of it.
    let mut b = surface((160, 48));
    press(&mut b, KeyCode::BackTab, KeyModifiers::SHIFT);
    assert!(!screen(&b).contains("anisotropic"));
}
