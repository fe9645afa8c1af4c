//! The explorer's four views drawn without a terminal: Tab / Shift-Tab
//! cycling, what each view shows, and insta snapshots of the index, map and
//! load views at 80×24 and 160×48 (fig2 and fig4), plus a NO_COLOR map.

mod common;

use common::key;

use crossterm::event::{KeyCode, KeyModifiers};
use ratatui::backend::TestBackend;
use ratatui::style::Color;
use ratatui::Terminal;
use rough_model::Axis;
use roughtui::figure::{share_colour, View};
use roughtui::presets;
use roughtui::tui::app::{update, App, Message};
use roughtui::tui::keys::message_for_key;
use roughtui::tui::layout::Regions;
use roughtui::tui::theme::Theme;

fn app(name: &str, size: (u16, u16), theme: Theme) -> App {
    App::new(presets::load(name).unwrap(), theme, size)
}

fn draw(app: &App) -> Terminal<TestBackend> {
    let (w, h) = app.size;
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
    t
}

fn text(app: &App) -> String {
    common::buffer_text(&draw(app))
}

fn show(a: &mut App, view: View) {
    while a.view != view {
        update(a, Message::NextView);
    }
}

fn press(a: &mut App, code: KeyCode, mods: KeyModifiers) {
    let m = message_for_key(a, &key(code, mods)).expect("a bound key");
    update(a, m);
}

#[test]
fn tab_and_shift_tab_cycle_the_five_views() {
    let mut a = app("fig2", (80, 24), Theme::colored());
    assert_eq!(a.view, View::Slopes);
    let mut seen = vec![];
    for _ in 0..5 {
        press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
        seen.push(a.view);
    }
    assert_eq!(
        seen,
        [
            View::Indices,
            View::Map,
            View::Load,
            View::Contact,
            View::Slopes
        ]
    );
    press(&mut a, KeyCode::BackTab, KeyModifiers::SHIFT);
    assert_eq!(a.view, View::Contact);
    press(&mut a, KeyCode::BackTab, KeyModifiers::SHIFT);
    assert_eq!(a.view, View::Load);
    press(&mut a, KeyCode::BackTab, KeyModifiers::NONE);
    assert_eq!(a.view, View::Map);
    // Switching views changes nothing the snapshot holds.
    assert!(!a.modified);
    let titles = [
        (View::Slopes, "slope H0·dA/dp̄/A0 vs ζ"),
        (View::Indices, "plasticity indices vs ζ"),
        (View::Map, "plastic share over ζ × H0/E"),
        (View::Load, "A/A0 vs p̄/H0 · Ψ_P 0.523 · initial slope 1.53"),
    ];
    for (v, title) in titles {
        show(&mut a, v);
        assert!(text(&a).contains(title), "{v:?}: {title}\n{}", text(&a));
    }
}

#[test]
fn the_claims_line_states_where_the_figures_claims_hold() {
    let a = app("fig2", (80, 24), Theme::colored());
    assert!(text(&a).contains("plastic share passes ½ at ζ = 321.5 · Ψ_P reaches 1 at ζ = 3272"));
    let a = app("fig4", (80, 24), Theme::colored());
    assert!(text(&a)
        .contains("plastic share falls below ½ at ζ = 1.698e4 · Ψ* falls below 1 at ζ = 5324"));
    // Live: without the size effect fig4 stays plastic over the whole sweep.
    let mut a = a;
    update(&mut a, Message::ToggleSizeEffect);
    assert!(a.claims.is_empty(), "{:?}", a.claims);
    // The caption ("with the size effect") leaves with the scene it
    // describes; the claims row is empty.
    let s = text(&a);
    assert!(!s.contains("Fig. 4: rougher") && !s.contains("falls below ½"));
    update(&mut a, Message::ToggleSizeEffect);
    assert!(text(&a).contains("Fig. 4: rougher"));
}

#[test]
fn index_view_draws_the_four_indices_against_psi_one() {
    let mut a = app("fig2", (160, 48), Theme::colored());
    show(&mut a, View::Indices);
    let s = text(&a);
    assert!(
        s.contains("━━ Ψ_GW  ━━ Ψ_P  ━━ Ψ*  ━━ Ψ*asy eq.13  ·· Ψ = 1"),
        "{s}"
    );
    let p = &a.indices;
    assert_eq!(p.psi_p.len(), a.plot.points);
    // log10 axes: ζ from 1 to 1e4; decades 1e-2 … 1e2 hold every index.
    assert_eq!(p.x_bounds, [0.0, 4.0]);
    assert_eq!(p.y_bounds, [-2.0, 2.0]);
    // Ψ_P grows as ζ^(1−H) on the asymptotic moments: 0.2 decades per decade.
    let (first, last) = (p.psi_p[0], *p.psi_p.last().unwrap());
    assert!(((last.1 - first.1) / (last.0 - first.0) - 0.2).abs() < 1e-12);
    // Ψ* at the marker's column equals the readout's (ζ = 128 lies between samples).
    let at = |c: &Vec<(f64, f64)>, x: f64| {
        c.windows(2)
            .find(|w| w[0].0 <= x && x <= w[1].0)
            .map(|w| w[0].1 + (w[1].1 - w[0].1) * (x - w[0].0) / (w[1].0 - w[0].0))
            .unwrap()
    };
    let star = 10f64.powf(at(&p.psi_star, 128f64.log10()));
    assert!((star / a.readout.surface.indices.psi_star - 1.0).abs() < 1e-3);
    // Where eq. 13 lies within a dot row of Ψ* everywhere, the legend says
    // it is drawn under Ψ* (fig4 at 80×24: R*/R_p ≫ 1 holds over the sweep).
    assert!(!s.contains("under Ψ*"));
    let mut b = app("fig4", (80, 24), Theme::colored());
    show(&mut b, View::Indices);
    assert!(text(&b).contains("━ Ψ* ━ eq.13 under Ψ* · Ψ = 1"));
    // The Ψ = 1 line: a row of braille across the graph at the decade 1.
    let row = s.lines().find(|l| l.contains("   1┤")).unwrap();
    let braille = row
        .chars()
        .filter(|c| ('\u{2801}'..='\u{28FF}').contains(c));
    assert!(braille.count() > 100, "{row}");
}

/// The cells of the map's graph with their symbols and colours.
fn graph_cells(a: &App) -> Vec<(String, Color, Color)> {
    let t = draw(a);
    let g = Regions::of_size(a.size).unwrap().graph;
    let buf = t.backend().buffer();
    let mut v = vec![];
    for y in g.y..g.bottom() {
        for x in g.x..g.right() {
            let c = &buf[(x, y)];
            v.push((c.symbol().to_string(), c.fg, c.bg));
        }
    }
    v
}

#[test]
fn map_view_colours_two_points_per_cell_with_contour_and_point() {
    let mut a = app("fig2", (160, 48), Theme::colored());
    show(&mut a, View::Map);
    let g = Regions::of_size(a.size).unwrap().graph;
    let map = a.map.peek().unwrap();
    assert_eq!(
        (map.spec.cols, map.spec.rows),
        (usize::from(g.width), 2 * usize::from(g.height))
    );
    let cells = graph_cells(&a);
    let rgb = |s: f64| {
        let (r, g, b) = share_colour(s);
        Color::Rgb(r, g, b)
    };
    let white = Color::Rgb(255, 255, 255);
    // Top-left cell: upper half is the top map row, lower half the next.
    let rows = map.spec.rows;
    assert_eq!(cells[0].0, "▀");
    let upper_is = |c: &(String, Color, Color), s: f64| c.1 == rgb(s) || c.1 == white;
    assert!(upper_is(&cells[0], map.share_at(0, rows - 1)));
    // Bottom-left: the bottom map row is the lower half (fig2: plastic at H0/E 1e-4).
    let last_row = &cells[cells.len() - usize::from(g.width)];
    assert_eq!(last_row.2, rgb(map.share_at(0, 0)));
    assert!(map.share_at(0, 0) > 0.99);
    // The contour and the current point are drawn.
    assert!(cells.iter().any(|c| c.1 == white || c.2 == white));
    assert_eq!(cells.iter().filter(|c| c.0 == "◆").count(), 1);
    assert!(cells.iter().filter(|c| c.0 == "▀").count() >= cells.len() - 1);
    let s = text(&a);
    let legend = "elastic ██████████ plastic  ▀ Ψ_P=1  ◆ now  \
                  (elastic <10%, plastic >90%: this program's thresholds)";
    assert!(s.contains(legend), "{s}");
    // At 80×24 the short form keeps the thresholds.
    update(&mut a, Message::Resize(80, 24));
    assert!(text(&a).contains("el <10% ██████████ >90% pl  ▀ Ψ_P=1  ◆ now"));
}

#[test]
fn map_recomputes_only_when_what_it_shows_changes() {
    let mut a = app("fig2", (80, 24), Theme::colored());
    assert_eq!(a.map.computes(), 0, "hidden views compute nothing");
    show(&mut a, View::Map);
    assert_eq!(a.map.computes(), 1);
    let plastic = |a: &App| {
        a.map
            .peek()
            .unwrap()
            .share
            .iter()
            .filter(|s| **s > 0.9)
            .count()
    };
    let before = plastic(&a);
    // The swept slider only moves the point; help and redraws change nothing.
    press(&mut a, KeyCode::Right, KeyModifiers::NONE);
    update(&mut a, Message::ToggleHelp);
    update(&mut a, Message::ToggleHelp);
    assert_eq!(a.map.computes(), 1);
    // The size effect redraws it: the plastic region shrinks.
    press(&mut a, KeyCode::Char('e'), KeyModifiers::NONE);
    assert_eq!(a.map.computes(), 2);
    assert!(plastic(&a) * 3 < before * 2, "{} vs {before}", plastic(&a));
    assert!(text(&a).contains("Ψ*=1"));
    // y picks another y axis (skipping the swept ζ).
    press(&mut a, KeyCode::Char('y'), KeyModifiers::NONE);
    assert_eq!(a.map.computes(), 3);
    assert_eq!(a.map.peek().unwrap().spec.y.axis(), Axis::HRms);
    assert!(text(&a).contains("plastic share over ζ × h_rms"));
    // A resize recomputes on the new grid.
    update(&mut a, Message::Resize(100, 30));
    assert_eq!(a.map.computes(), 4);
}

#[test]
fn load_view_draws_areas_and_the_initial_slope_line() {
    let mut a = app("fig2", (160, 48), Theme::colored());
    show(&mut a, View::Load);
    let p = &a.load;
    assert_eq!(p.total.len(), a.plot.points);
    assert_eq!(p.total[0], (0.0, 0.0));
    assert_eq!(*p.total.last().unwrap(), (1.0, 1.0));
    // The tangent leaves the origin with the slopes view's S_tot.
    assert_eq!(p.slope, a.readout.slopes.total);
    assert_eq!(p.tangent[0], (0.0, 0.0));
    let (x, y) = p.tangent[1];
    assert!((y / x - a.readout.slopes.total).abs() < 1e-12 && y == 1.0);
    // Near the origin the total area follows its tangent.
    let (x1, y1) = p.total[1];
    assert!((y1 / x1 / p.slope - 1.0).abs() < 0.1, "{}", y1 / x1);
    let s = text(&a);
    assert!(
        s.contains("━━ elastic  ━━ plastic  ━━ total  ·· initial slope"),
        "{s}"
    );
    assert!(s.contains("p̄/H0"));
}

#[test]
fn snapshots_of_the_new_views() {
    for name in ["fig2", "fig4"] {
        for (w, h) in [(80, 24), (160, 48)] {
            let mut a = app(name, (w, h), Theme::colored());
            for v in [View::Indices, View::Map, View::Load] {
                show(&mut a, v);
                insta::assert_snapshot!(format!("{name}_{}_{w}x{h}", v.name()), text(&a));
            }
        }
    }
    let mut a = app("fig2", (80, 24), Theme::plain());
    show(&mut a, View::Map);
    insta::assert_snapshot!("fig2_map_no_color_80x24", text(&a));
}

#[test]
fn p_writes_the_view_as_an_svg_and_never_overwrites() {
    let dir = tempfile::tempdir().unwrap();
    let mut a = app("fig2", (80, 24), Theme::colored());
    a.save_dir = dir.path().to_path_buf();
    show(&mut a, View::Map);
    press(&mut a, KeyCode::Char('p'), KeyModifiers::NONE);
    press(&mut a, KeyCode::Char('p'), KeyModifiers::NONE);
    let files = common::files_in(dir.path());
    assert_eq!(files.len(), 2, "{files:?}");
    for f in &files {
        assert!(f.starts_with("fig2-map-") && f.ends_with(".svg"), "{f}");
        let text = std::fs::read_to_string(dir.path().join(f)).unwrap();
        let doc = roxmltree::Document::parse(&text).expect("well-formed SVG");
        assert_eq!(doc.root_element().tag_name().name(), "svg");
        assert!(text.contains("H0/E"), "the map's y axis is labelled");
    }
    let status = a.status.as_ref().unwrap();
    assert!(
        !status.error && status.text.starts_with("saved "),
        "{status:?}"
    );
    assert!(status.text.ends_with(&files[1]) || status.text.ends_with(&files[0]));
    // An unwritable folder: one clear error on the status line, no file, no panic.
    a.save_dir = dir.path().join("missing");
    press(&mut a, KeyCode::Char('p'), KeyModifiers::NONE);
    let status = a.status.as_ref().unwrap();
    assert!(
        status.error && status.text.starts_with("cannot save picture in"),
        "{status:?}"
    );
    assert_eq!(common::files_in(dir.path()).len(), 2);
    // Each view gives its own picture.
    a.save_dir = dir.path().to_path_buf();
    for v in [View::Slopes, View::Indices, View::Load] {
        show(&mut a, v);
        press(&mut a, KeyCode::Char('p'), KeyModifiers::NONE);
    }
    let files = common::files_in(dir.path());
    for v in ["slopes", "indices", "load"] {
        assert!(
            files.iter().any(|f| f.starts_with(&format!("fig2-{v}-"))),
            "{files:?}"
        );
    }
}

fn any_message() -> impl proptest::strategy::Strategy<Value = Message> {
    use proptest::prelude::*;
    prop_oneof![
        Just(Message::SelectPrev),
        Just(Message::SelectNext),
        (any::<bool>(), any::<bool>()).prop_map(|(up, fine)| Message::Step { up, fine }),
        (0usize..4).prop_map(Message::LoadPreset),
        Just(Message::CycleSweep),
        Just(Message::ToggleModel),
        Just(Message::ToggleSizeEffect),
        Just(Message::ToggleMoments),
        Just(Message::NextView),
        Just(Message::PrevView),
        Just(Message::NextMapY),
        (0u16..120, 0u16..40).prop_map(|(w, h)| Message::Resize(w, h)),
    ]
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(24))]

    /// Any sequence of messages over the four views leaves a drawable app
    /// whose curves hold finite points and whose map, when shown, fits its
    /// graph.
    #[test]
    fn no_message_sequence_breaks_a_view(
        msgs in proptest::collection::vec(any_message(), 1..30),
        theme in proptest::bool::ANY,
    ) {
        let theme = if theme { Theme::colored() } else { Theme::plain() };
        let mut a = app("fig2", (80, 24), theme);
        for m in msgs {
            update(&mut a, m);
        }
        let i = &a.indices;
        for c in [&i.psi_gw, &i.psi_p, &i.psi_star, &i.psi_star_asymptotic] {
            proptest::prop_assert!(c.iter().all(|(x, y)| x.is_finite() && y.is_finite()));
        }
        let l = &a.load;
        for c in [&l.elastic, &l.plastic, &l.total] {
            proptest::prop_assert!(c.iter().all(|(x, y)| (0.0..=1.0).contains(x) && (0.0..=1.0).contains(y)));
        }
        if let (View::Map, Some(r)) = (a.view, Regions::of_size(a.size)) {
            let spec = a.map.peek().map(|m| m.spec.clone());
            proptest::prop_assert_eq!(spec, a.map_spec(r.graph));
        }
        let _ = text(&a);
    }
}

#[test]
fn map_y_labels_keep_their_units() {
    let mut a = app("fig3", (100, 30), Theme::plain());
    show(&mut a, View::Map);
    // H0/E → h_rms → Hurst → R* (ζ is swept).
    for _ in 0..3 {
        update(&mut a, Message::NextMapY);
    }
    assert_eq!(a.map.peek().unwrap().spec.y.axis(), Axis::RStar);
    let s = text(&a);
    for label in ["100mm┤", "10 mm┤", " 1 mm┤", " 1 µm┤"] {
        assert!(s.contains(label), "{label} in\n{s}");
    }
    assert!(!s.contains("100 m┤"), "{s}");
}

#[test]
fn no_color_load_view_tells_the_tangent_from_the_elastic_curve() {
    let mut a = app("fig3", (100, 30), Theme::plain());
    show(&mut a, View::Load);
    let s = text(&a);
    assert!(
        s.contains("•• elastic  ++ plastic  ⠒⠒ total  ·· initial slope"),
        "{s}"
    );
    // The tangent's dots and the elastic curve's bullets both show.
    assert!(s.matches('·').count() > 10 + 1, "{s}");
    assert!(s.matches('•').count() > 10 + 2, "{s}");
}

#[test]
fn at_80_columns_header_and_claims_are_never_cut_inside_a_word_or_number() {
    // fig1 sweeps H0/E: its three claims in full take 180 columns.
    let a = app("fig1", (80, 24), Theme::colored());
    let s = text(&a);
    let lines: Vec<&str> = s.lines().collect();
    assert!(
        lines[0]
            .trim_end()
            .ends_with("asymptotic · size effect off"),
        "{s}"
    );
    // The caption's one row says what the paper says; the claims row,
    // short, what its equations give.
    assert_eq!(
        lines[1].trim_end(),
        "Fig. 1: the paper calls realistic hardness (E/H0 ≈ 25…1000) practically elastic…"
    );
    assert_eq!(
        lines[2].trim_end(),
        "plastic share ½ at E/H0 = 120.2 · Ψ_P = 1 at E/H0 = 191.2"
    );
    // Room enough: the header keeps the word "moments", the crossings show
    // in full, and the minimum in short.
    let a = app("fig1", (160, 48), Theme::colored());
    let s = text(&a);
    assert!(s.contains("asymptotic moments · size effect off"), "{s}");
    assert!(
        s.contains(
            "plastic share falls below ½ at H0/E = 0.008318 (E/H0 = 120.2) · \
             Ψ_P falls below 1 at H0/E = 0.00523 (E/H0 = 191.2) · \
             total slope min 0.9796 at E/H0 = 271.9"
        ),
        "{s}"
    );
    // fig3: the minimum of the total slope, where the paper says it
    // "first decreases and then increases".
    let a = app("fig3", (80, 24), Theme::colored());
    assert_eq!(
        text(&a).lines().nth(2).unwrap().trim_end(),
        "total slope's minimum 3.91 at ζ = 3.191"
    );
}

#[test]
fn at_80_columns_the_load_title_keeps_its_numbers_whole() {
    // fig3 at ζ = 128: Ψ* 0.0798 and a slope of 10.0 do not fit the long
    // form, which showed "initial slope 10." here.
    let mut a = app("fig3", (80, 24), Theme::colored());
    show(&mut a, View::Load);
    let s = text(&a);
    let title = s.lines().nth(3).unwrap().trim_end();
    assert!(
        title.ends_with("A/A0 vs p̄/H_y · Ψ* 0.0798 · S_tot 10.0"),
        "{s}"
    );
    // fig4 still fits the long form; its marker value is left out, not cut.
    let mut a = app("fig4", (80, 24), Theme::colored());
    show(&mut a, View::Load);
    let s = text(&a);
    let title = s.lines().nth(3).unwrap().trim_end();
    assert!(title.ends_with("Ψ* 0.777 · initial slope 1.11"), "{s}");
}

#[test]
fn at_80_columns_a_long_name_gives_way_to_the_scene_in_the_header() {
    let header = |name: &str, file: &str| {
        let mut a = app("fig2", (80, 24), Theme::colored());
        a.state.name = name.into();
        a.file = Some(file.into());
        let s = text(&a);
        s.lines().next().unwrap().trim_end().to_string()
    };
    // A file saved under the scene's name is named once, cut at its end.
    let h = header("fig2-20261123-205916", "fig2-20261123-205916.ron");
    let scene = "]  ζ 1…1e4 · closed form · asymptotic · size effect off";
    assert_eq!(h, format!(" roughtui [fig2-20261123…{scene}"));
    let h = header("mine", "mine.ron");
    assert_eq!(h, format!(" roughtui [mine.ron{scene}"));
    // Another name and file: the file alone, cut if need be, not the scene.
    let h = header("a long scene name for the Monday lecture", "lecture.ron");
    assert_eq!(h, format!(" roughtui [lecture.ron{scene}"));
    let h = header("fig2", "a-long-file-name-for-the-monday-lecture.ron");
    assert!(h.starts_with(" roughtui [a-long-file-n"), "{h}");
    assert!(h.ends_with(&format!("…{scene}")), "{h}");
}
