//! What the screen says goes when the state it describes goes: status
//! messages after a change, a caption after its model or moments change,
//! claims that are truncation artefacts; and the footer at 80 columns
//! keeps save, picture, help and quit, with g and y where they act.

mod common;

use common::app::{ch, fig, press, screen, type_text};
use crossterm::event::{KeyCode, KeyModifiers};
use roughtui::figure::{View, TRUNCATION_ZETA};
use roughtui::tui::app::{update, Message};

#[test]
fn a_status_message_goes_with_its_state() {
    let mut a = fig("fig2");
    ch(&mut a, '1');
    assert_eq!(a.status.as_ref().unwrap().text, "loaded fig1");
    // A slider step: the scene is no longer fig1 as loaded.
    ch(&mut a, 'l');
    assert!(a.status.is_none(), "{:?}", a.status);
    ch(&mut a, '1');
    update(&mut a, Message::NextView);
    assert!(a.status.is_none(), "a change of view: {:?}", a.status);
    // A refused value goes with the text it refused.
    press(&mut a, KeyCode::Enter, KeyModifiers::NONE);
    type_text(&mut a, "3 km");
    press(&mut a, KeyCode::Enter, KeyModifiers::NONE);
    assert!(a.status.as_ref().unwrap().error);
    press(&mut a, KeyCode::Esc, KeyModifiers::NONE);
    assert!(a.status.is_none(), "{:?}", a.status);
    assert!(!screen(&a).contains("km"));
}

#[test]
fn the_caption_goes_when_its_numbers_are_no_longer_the_scenes() {
    let mut a = fig("fig2");
    assert!(a.state.caption.as_deref().unwrap().contains("320"));
    ch(&mut a, 'a');
    assert_eq!(a.state.caption, None, "truncated moments: other numbers");
    ch(&mut a, 'a');
    assert!(a.state.caption.is_some(), "back with its scene");
    ch(&mut a, 'm');
    assert_eq!(a.state.caption, None, "another model");
}

#[test]
fn truncation_artefacts_are_not_claimed() {
    let mut a = fig("fig4");
    ch(&mut a, 'a');
    assert!(!a.claims.is_empty());
    for c in &a.claims {
        assert!(c.at >= TRUNCATION_ZETA, "{}", c.text());
    }
    // The unfiltered claims do hold some at ζ ≈ 1 (the reference checks
    // them all): those are the truncation's.
    let all = roughtui::figure::claims(&a.state);
    assert!(all.iter().any(|c| c.at < TRUNCATION_ZETA), "{all:?}");
}

#[test]
fn the_footer_fits_80_columns_with_save_picture_help_and_quit() {
    let mut a = fig("fig2");
    let footer = |a: &roughtui::tui::app::App| {
        let s = screen(a);
        s.lines().last().unwrap().trim_end().to_string()
    };
    let f = footer(&a);
    assert!(f.chars().count() <= 80, "{f}");
    for k in ["s save", "p picture", "? help", "q quit"] {
        assert!(f.contains(k), "{k:?} not in {f:?}");
    }
    assert!(!f.contains("y map axis"), "{f}");
    let wide = roughtui::tui::keys::footer(&a, 300);
    assert!(
        wide.contains("g ghost") && !wide.contains("y map axis"),
        "{wide}"
    );
    while a.view != View::Map {
        update(&mut a, Message::NextView);
    }
    let wide = roughtui::tui::keys::footer(&a, 300);
    assert!(
        wide.contains("y map axis") && !wide.contains("g ghost"),
        "{wide}"
    );
    assert!(!wide.contains("f follow"));
}

#[test]
fn an_h_sweep_labels_every_tick_it_draws() {
    for size in [(80, 24), (100, 30), (160, 48)] {
        let mut a = fig("fig2");
        update(&mut a, Message::Resize(size.0, size.1));
        while a.state.sweep.axis() != rough_model::Axis::Hurst {
            ch(&mut a, 'x');
        }
        let s = screen(&a);
        let lines: Vec<&str> = s.lines().collect();
        let axis = lines.iter().position(|l| l.contains('└')).unwrap();
        let row: Vec<char> = lines[axis].chars().collect();
        let labels: Vec<char> = lines[axis + 1].chars().collect();
        let ticks: Vec<usize> = (0..row.len()).filter(|&i| row[i] == '┬').collect();
        assert!(ticks.len() >= 3, "{size:?}:\n{s}");
        for t in ticks {
            // A digit under or beside every tick.
            let near = (t.saturating_sub(2)..=(t + 2).min(labels.len() - 1))
                .any(|i| labels[i].is_ascii_digit());
            assert!(
                near,
                "{size:?}: tick at {t} unlabelled\n{}\n{}",
                lines[axis],
                lines[axis + 1]
            );
        }
    }
}

#[test]
fn what_the_drawing_is_stays_while_the_scene_changes() {
    let mut a = fig("fig2");
    ch(&mut a, 'M');
    let said = a.status.clone().unwrap().text;
    assert!(said.starts_with("drawing in "), "{said}");
    ch(&mut a, 'l');
    update(&mut a, Message::NextView);
    assert_eq!(a.status.map(|s| s.text), Some(said));
}
