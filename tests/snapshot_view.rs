//! Snapshots keep the view: `s` records the view, the map's y axis and the
//! ghost, and loading the file shows them again; older snapshots (without
//! those fields) still load, on the slopes view; `s` then `p` names the
//! picture after the scene and the view, with one time stamp.

mod common;

use common::app::{ch, fig, press};
use crossterm::event::{KeyCode, KeyModifiers};
use rough_model::Axis;
use roughtui::figure::View;
use roughtui::scene::GhostOf;
use roughtui::snapshot;
use roughtui::tui::app::{update, App, Message};
use roughtui::tui::theme::Theme;

fn show(a: &mut App, view: View) {
    while a.view != view {
        update(a, Message::NextView);
    }
}

/// `s` and Enter: the snapshot saved under the offered name; its path.
fn save(a: &mut App) -> std::path::PathBuf {
    ch(a, 's');
    press(a, KeyCode::Enter, KeyModifiers::NONE);
    let status = a.status.clone().unwrap();
    assert!(!status.error, "{status:?}");
    std::path::PathBuf::from(status.text.strip_prefix("saved ").unwrap())
}

#[test]
fn a_snapshot_reloads_on_its_view_with_its_ghost() {
    let dir = tempfile::tempdir().unwrap();
    let mut a = fig("fig2");
    a.save_dir = dir.path().to_path_buf();
    // A ghost pinned on the slopes, then h_rms changed, then the map with
    // h_rms up.
    ch(&mut a, 'g');
    let pinned = a.ghost.clone().unwrap();
    while a.selected_axis() != Axis::HRms {
        update(&mut a, Message::SelectNext);
    }
    assert_eq!(a.selected_axis(), Axis::HRms);
    update(
        &mut a,
        Message::Step {
            up: true,
            fine: false,
        },
    );
    show(&mut a, View::Map);
    update(&mut a, Message::NextMapY);
    let map_y = a.map_y;
    assert!(map_y.is_some());
    let path = save(&mut a);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains("view: Map"), "{text}");
    assert!(text.contains("ghost: (kind: Curves"), "{text}");
    // The scene keeps its name: the offered time stamp is the file's only.
    assert!(text.contains("name: \"fig2\""), "{text}");
    assert_eq!(a.state.name, "fig2");

    let loaded = snapshot::load_file(&path).unwrap();
    assert_eq!(loaded.shown.view, View::Map);
    assert_eq!(loaded.shown.map_y, map_y);
    let g = loaded.shown.ghost.unwrap();
    assert_eq!(g.kind, GhostOf::Curves);
    assert_eq!(g.params, pinned.state.params);
    let b = App::new(loaded, Theme::colored(), (80, 24));
    assert_eq!(b.view, View::Map);
    assert_eq!(b.map_y, map_y);
    assert_eq!(b.state.params, a.state.params, "the marker and parameters");
    let ghost = b.ghost.as_ref().expect("the ghost comes back");
    assert_eq!(ghost.state.params, pinned.state.params);
    assert_eq!(ghost.plot.total, pinned.plot.total, "recomputed the same");
    // The explorer holds the view; the state keeps none of it.
    assert_eq!(b.state.shown, roughtui::scene::Shown::default());
}

#[test]
fn s_then_p_names_the_picture_once() {
    let dir = tempfile::tempdir().unwrap();
    let mut a = fig("fig2");
    a.save_dir = dir.path().to_path_buf();
    show(&mut a, View::Map);
    save(&mut a);
    ch(&mut a, 'p');
    let files = common::files_in(dir.path());
    let svg: Vec<&String> = files.iter().filter(|f| f.ends_with(".svg")).collect();
    assert_eq!(svg.len(), 1, "{files:?}");
    // fig2-map-YYYYMMDD-HHMMSS.svg
    let stem = svg[0].strip_suffix(".svg").unwrap();
    let stamp = stem
        .strip_prefix("fig2-map-")
        .unwrap_or_else(|| panic!("{stem}"));
    assert_eq!(stamp.len(), 15, "{stem}");
    assert!(
        stamp.chars().all(|c| c.is_ascii_digit() || c == '-'),
        "{stem}"
    );
    // A name typed by hand is the scene's name.
    ch(&mut a, 's');
    for _ in 0..40 {
        press(&mut a, KeyCode::Backspace, KeyModifiers::NONE);
    }
    common::app::type_text(&mut a, "rough steel");
    press(&mut a, KeyCode::Enter, KeyModifiers::NONE);
    assert_eq!(a.state.name, "rough steel");
}

#[test]
fn older_snapshots_load_on_the_slopes_view() {
    let s = roughtui::scene::State::from_ron(common::GOOD).unwrap();
    assert_eq!(s.shown, roughtui::scene::Shown::default());
    let a = App::new(s.clone(), Theme::colored(), (80, 24));
    assert_eq!(a.view, View::Slopes);
    assert!(a.ghost.is_none());
    // Saved on the slopes without a ghost: byte for byte what older
    // builds wrote (no view fields).
    assert!(!s.to_ron().contains("view"));
}

#[test]
fn a_view_the_scene_cannot_show_is_refused_by_name() {
    let with = |extra: &str| {
        let text = common::GOOD.replace("model: Exact,", &format!("model: Exact, {extra}"));
        roughtui::scene::State::from_ron(&text).map_err(|e| e.to_string())
    };
    assert_eq!(with("view: Load,").unwrap().shown.view, View::Load);
    let e = with("view: Spectrum,").unwrap_err();
    assert!(e.contains("view: spectrum needs a measured surface"), "{e}");
    let e = with("view: Mapp,").unwrap_err();
    assert!(e.contains("Mapp") && e.contains("Slopes"), "{e}");
    let ghost = "ghost: (kind: Fit, params: (h0_over_e: 0.01, h_rms: 2e-8, zeta: 128.0, \
                 hurst: 0.8, r_star: 0.001, q0: 100000.0), size_effect: false, model: Exact),";
    let e = with(ghost).unwrap_err();
    assert!(
        e.contains("ghost: kind Fit needs a measured surface"),
        "{e}"
    );
    let e = with(&ghost.replace("0.8", "-1").replace("Fit", "Curves")).unwrap_err();
    assert!(e.contains("ghost.params: hurst = -1"), "{e}");
    let ok = with(&ghost.replace("Fit", "Curves")).unwrap();
    assert_eq!(ok.shown.ghost.unwrap().kind, GhostOf::Curves);
}
