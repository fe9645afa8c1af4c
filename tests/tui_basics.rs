//! What a class runs into, without a terminal: the value prompt, the save
//! prompt's editing keys, the help's symbols, status lines at 80 columns,
//! and a too-small terminal that takes only quit keys.

mod common;

use common::app::{ch, ctrl, fig, press, screen, type_text};
use crossterm::event::{KeyCode, KeyModifiers};
use rough_model::Axis;
use roughtui::tui::app::{update, Message, Mode};
use roughtui::tui::help::SYMBOLS;

fn enter(a: &mut roughtui::tui::app::App) {
    press(a, KeyCode::Enter, KeyModifiers::NONE);
}

fn prompt_text(a: &roughtui::tui::app::App) -> String {
    match &a.mode {
        Mode::Prompt(l) | Mode::Value(_, l) => l.text(),
        m => panic!("no prompt open: {m:?}"),
    }
}

#[test]
fn enter_types_an_exact_value_with_units() {
    let mut a = fig("fig2");
    ch(&mut a, 'k'); // h_rms, above ζ
    assert_eq!(a.selected_axis(), Axis::HRms);
    enter(&mut a);
    assert!(matches!(a.mode, Mode::Value(Axis::HRms, _)), "{:?}", a.mode);
    let s = screen(&a);
    assert!(s.contains("h_rms = "), "{s}");
    assert!(s.contains("units m cm mm µm nm pm"), "{s}");
    // The footer lists the prompt's keys, from the key table.
    let footer = s.lines().last().unwrap();
    for k in ["⏎ accept", "Esc cancel", "←→ move", "^U clear", "^W word"] {
        assert!(footer.contains(k), "{k} not in {footer:?}");
    }
    type_text(&mut a, "25nm");
    enter(&mut a);
    assert_eq!(a.mode, Mode::Main);
    assert_eq!(a.state.params.get(Axis::HRms), 2.5e-8);
    assert!(a.modified);
    assert!(screen(&a).contains("25.0 nm"));

    // With a space and another unit; then a plain number on ζ.
    enter(&mut a);
    type_text(&mut a, "0.1 µm");
    enter(&mut a);
    assert_eq!(a.state.params.get(Axis::HRms), 1e-7);
    ch(&mut a, 'j'); // ζ
    enter(&mut a);
    type_text(&mut a, "300");
    enter(&mut a);
    assert_eq!(a.state.params.get(Axis::Zeta), 300.0);
}

#[test]
fn bad_values_keep_the_prompt_with_the_reason_and_esc_cancels() {
    let mut a = fig("fig2");
    ch(&mut a, 'j'); // H, the Hurst exponent, below ζ
    assert_eq!(a.selected_axis(), Axis::Hurst);
    let before = a.state.clone();
    enter(&mut a);
    type_text(&mut a, "1.5");
    enter(&mut a);
    assert!(
        matches!(a.mode, Mode::Value(..)),
        "a refusal keeps the prompt"
    );
    let st = a.status.clone().unwrap();
    assert!(
        st.error && st.text.contains("H = 1.5 is out of range"),
        "{st:?}"
    );
    assert!(screen(&a).contains("H = 1.5 is out of range"));
    // q and other command keys are text in the prompt.
    type_text(&mut a, "qx");
    assert!(!a.quit);
    assert_eq!(prompt_text(&a), "1.5qx");
    enter(&mut a);
    let st = a.status.clone().unwrap();
    assert!(st.text.contains("H takes no unit (\"qx\")"), "{st:?}");
    press(&mut a, KeyCode::Esc, KeyModifiers::NONE);
    assert_eq!(a.mode, Mode::Main);
    assert_eq!(a.state, before);
    assert!(!a.modified);
    // A unit on a number without one.
    enter(&mut a);
    type_text(&mut a, "0.5 nm");
    enter(&mut a);
    assert!(a.status.as_ref().unwrap().text.contains("H takes no unit"));
}

#[test]
fn the_save_prompt_edits_at_a_cursor() {
    let dir = tempfile::tempdir().unwrap();
    let mut a = fig("fig2");
    a.save_dir = dir.path().to_path_buf();
    ch(&mut a, 's');
    let stem = prompt_text(&a);
    assert!(stem.starts_with("fig2-20"), "{stem}");
    // Ctrl-W deletes the last word, then the separator and the next one.
    ctrl(&mut a, 'w');
    ctrl(&mut a, 'w');
    assert_eq!(prompt_text(&a), "fig2-");
    ctrl(&mut a, 'u');
    assert_eq!(prompt_text(&a), "");
    type_text(&mut a, "run");
    press(&mut a, KeyCode::Home, KeyModifiers::NONE);
    type_text(&mut a, "my-");
    press(&mut a, KeyCode::End, KeyModifiers::NONE);
    type_text(&mut a, "1");
    press(&mut a, KeyCode::Left, KeyModifiers::NONE);
    press(&mut a, KeyCode::Left, KeyModifiers::NONE);
    press(&mut a, KeyCode::Delete, KeyModifiers::NONE);
    ctrl(&mut a, 'a');
    press(&mut a, KeyCode::Right, KeyModifiers::NONE);
    press(&mut a, KeyCode::Backspace, KeyModifiers::NONE);
    ctrl(&mut a, 'e');
    assert_eq!(prompt_text(&a), "y-ru1");
    // The cursor is drawn where it is.
    press(&mut a, KeyCode::Left, KeyModifiers::NONE);
    let s = screen(&a);
    assert!(s.contains("save as: y-ru1.ron"), "{s}");
    enter(&mut a);
    assert!(dir.path().join("y-ru1.ron").exists());
}

#[test]
fn the_help_explains_every_symbol_on_some_page() {
    let mut a = fig("fig2");
    ch(&mut a, '?');
    let mut seen = String::new();
    for _ in 0..6 {
        seen.push_str(&screen(&a));
        press(&mut a, KeyCode::Right, KeyModifiers::NONE);
    }
    assert_eq!(a.mode, Mode::Help, "paging keeps the help open");
    for (sym, what) in SYMBOLS {
        let first_words: String = what.chars().take(20).collect();
        assert!(
            seen.contains(&first_words),
            "{sym}: \"{first_words}\" not in the help"
        );
    }
    for must in [
        "Ψ_GW",
        "Ψ*asy",
        "R_s",
        "λ1",
        "h′",
        "S_P",
        "p̄",
        "Hurst exponent",
        "H_y",
    ] {
        assert!(seen.contains(must), "{must}");
    }
    assert!(seen.contains("this program's thresholds"));
    assert!(
        seen.contains("help 1/") && seen.contains("help 2/"),
        "{seen}"
    );
}

#[test]
fn the_help_shows_the_whole_caption_its_claims_and_the_split_it_rests_on() {
    // At 80×24 the screen shows one row of the caption; the help all of it.
    let mut a = fig("fig1");
    let help = help_pages(&mut a);
    assert!(help.contains("this scene:"), "{help}");
    assert!(help.contains("Persson's green line."), "{help}");
    assert!(
        help.contains("· Ψ_P falls below 1 at H0/E = 0.00523 (E/H0 = 191.2)"),
        "{help}"
    );
    assert!(
        help.contains("· plastic share falls below ½ at H0/E = 0.008318 (E/H0 = 120.2)"),
        "{help}"
    );
    // Which split of the area every share claim rests on.
    assert!(
        help.contains("mass on [0, H] of Appendix A's solution"),
        "{help}"
    );
    assert!(help.contains("0.078, not 0.738"), "{help}");
    // fig3's minimum; a scene without caption or claims has no section.
    assert!(help_pages(&mut fig("fig3")).contains("· total slope's minimum 3.91 at ζ = 3.191"));
    let mut a = fig("fig4");
    update(&mut a, Message::ToggleSizeEffect);
    assert!(a.claims.is_empty() && a.state.caption.is_none());
    assert!(!help_pages(&mut a).contains("this scene:"));
}

#[test]
fn long_status_lines_keep_their_reason_at_80_columns() {
    let dir = tempfile::tempdir().unwrap();
    let mut a = fig("fig2");
    a.save_dir = dir.path().to_path_buf();
    ch(&mut a, 's');
    ctrl(&mut a, 'u');
    type_text(&mut a, "a/b");
    enter(&mut a);
    let s = screen(&a);
    assert!(s.contains("it must be a file name, not a path"), "{s}");
    // A very long bad name: its middle gives way, the reason stays.
    ctrl(&mut a, 'u');
    type_text(&mut a, &format!("x/{}", "y".repeat(150)));
    enter(&mut a);
    let s = screen(&a);
    assert!(s.contains("not a path (no '/' or '\\')"), "{s}");
    assert!(s.contains('…'), "{s}");
    // Outside the prompt, a long status wraps onto the footer's row.
    press(&mut a, KeyCode::Esc, KeyModifiers::NONE);
    a.save_dir = "/proc/no/such/folder/with/a/rather/long/name/to/push/the/reason/out".into();
    ch(&mut a, 's');
    enter(&mut a);
    let st = a.status.clone().unwrap();
    assert!(st.error && st.text.chars().count() > 80, "{st:?}");
    let s = screen(&a);
    let tail: String = st
        .text
        .chars()
        .rev()
        .take(20)
        .collect::<Vec<_>>()
        .into_iter()
        .rev()
        .collect();
    assert!(s.contains(&tail), "\"{tail}\" not shown:\n{s}");
}

#[test]
fn too_small_only_quit_keys_act() {
    let mut a = fig("fig2");
    let before = a.state.clone();
    update(&mut a, Message::Resize(40, 12));
    press(&mut a, KeyCode::Right, KeyModifiers::NONE);
    for c in ['l', 'x', 'm', 'e', '2', 's', '?', 'g'] {
        ch(&mut a, c);
    }
    enter(&mut a);
    assert_eq!(a.state, before, "hidden state changed");
    assert_eq!(a.mode, Mode::Main);
    assert!(!a.modified);
    // A prompt opened before the shrink takes no text while too small.
    update(&mut a, Message::Resize(80, 24));
    ch(&mut a, 's');
    let stem = prompt_text(&a);
    update(&mut a, Message::Resize(60, 20));
    ch(&mut a, 'x');
    assert_eq!(prompt_text(&a), stem);
    ch(&mut a, 'q');
    assert!(a.quit, "q quits even with the prompt open");
    let mut b = fig("fig2");
    update(&mut b, Message::Resize(79, 24));
    ctrl(&mut b, 'c');
    assert!(b.quit);
}

#[test]
fn a_loaded_file_shows_its_name_and_a_save_keeps_the_typed_name() {
    let dir = tempfile::tempdir().unwrap();
    let mut a = fig("fig2");
    a.file = Some("mine.ron".into());
    // At 80 columns the file alone, so that the scene's settings fit.
    assert!(screen(&a).contains("[mine.ron]  ζ 1…1e4"), "{}", screen(&a));
    a.size = (160, 48);
    assert!(screen(&a).contains("[fig2 · mine.ron]"), "{}", screen(&a));
    ch(&mut a, 'l');
    assert!(screen(&a).contains("[fig2 · mine.ron*]"));
    a.save_dir = dir.path().to_path_buf();
    ch(&mut a, 's');
    ctrl(&mut a, 'u');
    type_text(&mut a, "lecture 3");
    enter(&mut a);
    let saved = roughtui::snapshot::load_file(&dir.path().join("lecture 3.ron")).unwrap();
    assert_eq!(saved.name, "lecture 3");
    assert_eq!(saved.params, a.state.params);
    let s = screen(&a);
    // Saved under the scene's name: named once.
    assert!(s.contains("[lecture 3.ron]"), "{s}");
    // A preset is a preset again.
    ch(&mut a, '3');
    assert!(screen(&a).contains("[fig3]"));
    assert_eq!(a.file, None);
}

#[test]
fn the_r_star_hint_clears_when_it_stops_applying() {
    let mut a = fig("fig2");
    assert!(!a.state.size_effect);
    while a.state.sweep.axis() != Axis::RStar {
        ch(&mut a, 'x');
    }
    assert!(screen(&a).contains("R* acts only with the size effect"));
    ch(&mut a, 'j'); // unrelated: the hint still applies
    assert!(screen(&a).contains("R* acts only with the size effect"));
    ch(&mut a, 'e');
    assert_eq!(a.status, None);
    assert!(!screen(&a).contains("R* acts only"));
    // Again, and this time the sweep moves on.
    ch(&mut a, 'e');
    for _ in 0..5 {
        ch(&mut a, 'x');
    }
    assert_eq!(a.state.sweep.axis(), Axis::RStar);
    assert!(screen(&a).contains("R* acts only with the size effect"));
    ch(&mut a, 'x');
    assert!(!screen(&a).contains("R* acts only"));
}

#[test]
fn the_regime_word_is_bold_without_colour() {
    use ratatui::style::{Color, Modifier};
    for preset in ["fig1", "fig2", "fig4"] {
        let a = fig(preset);
        let regime = a.readout.slopes.regime().label();
        let (w, h) = a.size;
        let mut t = ratatui::Terminal::new(ratatui::backend::TestBackend::new(w, h)).unwrap();
        t.draw(|f| f.render_widget(&a, f.area())).unwrap();
        let s = common::buffer_text(&t);
        let (row, line) = s
            .lines()
            .enumerate()
            .find(|(_, l)| l.starts_with("plastic ") && l.contains(&format!("%  {regime}")))
            .unwrap();
        let at = line.find(&format!("%  {regime}")).expect(line) + 3;
        let col = line[..at].chars().count();
        let cell = &t.backend().buffer()[(col as u16, row as u16)];
        assert_eq!(cell.symbol(), &regime[..1]);
        assert_eq!(cell.fg, Color::Reset, "{preset}: {regime} coloured");
        assert!(cell.modifier.contains(Modifier::BOLD));
    }
}

#[test]
fn the_share_shown_agrees_with_the_regime_word() {
    use roughtui::physical::print::fmt_share;
    assert_eq!(fmt_share(0.09996), "9.996%");
    assert_eq!(fmt_share(0.1), "10.0%");
    assert_eq!(fmt_share(0.294), "29.4%");
    assert_eq!(fmt_share(0.90004), "90.004%");
    assert_eq!(fmt_share(0.9), "90.0%");
    assert_eq!(fmt_share(0.0), "0.0%");
    assert_eq!(fmt_share(1.0), "100.0%");
    assert_eq!(fmt_share(0.1 - 1e-12), "< 10%");
    // On screen: find a ζ where the share is 9.996 % and read the line.
    let mut a = fig("fig2");
    let p = a.state.params;
    let (mut lo, mut hi) = (1.0f64, 128.0f64);
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        a.state.params = p.with(Axis::Zeta, mid).unwrap();
        update(&mut a, Message::Resize(80, 24));
        if a.readout.slopes.plastic_share() < 0.09996 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    a.state.params = p.with(Axis::Zeta, lo).unwrap();
    update(&mut a, Message::Resize(80, 24));
    let share = a.readout.slopes.plastic_share();
    assert!((0.09995..0.09996).contains(&share), "{share}");
    let s = screen(&a);
    assert!(s.contains("plastic 9.99"), "{s}");
    assert!(s.contains("%  elastic"), "{s}");
}

/// The ζ in [lo, hi] where `f` changes sign, by bisection on log ζ.
fn root(f: impl Fn(f64) -> f64, (mut lo, mut hi): (f64, f64)) -> f64 {
    assert!((f(lo) < 0.0) != (f(hi) < 0.0));
    for _ in 0..100 {
        let mid = (lo * hi).sqrt();
        if (f(mid) < 0.0) == (f(lo) < 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

#[test]
fn regime_marks_sit_where_psi_and_the_share_cross() {
    use rough_model::{slopes, Surface};
    use roughtui::tui::plots::RegimeMark;
    let a = fig("fig2");
    let st = a.state.clone();
    let psi = |z: f64| {
        let p = st.params.with(Axis::Zeta, z).unwrap();
        Surface::of(&p, st.moments)
            .indices
            .psi_in_use(st.size_effect)
            .to_f64()
    };
    let share = |z: f64| slopes(st.model, psi(z)).plastic_share();
    let want = [
        (root(|z| share(z) - 0.1, (1.0, 1e4)), RegimeMark::ShareLow),
        (root(|z| psi(z) - 1.0, (1.0, 1e4)), RegimeMark::PsiOne),
        (root(|z| share(z) - 0.9, (1.0, 1e4)), RegimeMark::ShareHigh),
    ];
    let got = &a.plot.regime_marks;
    assert_eq!(got.len(), 3, "{got:?}");
    // Within one sample of the curves (4 decades over the points drawn).
    let step = 4.0 / (a.plot.points - 1) as f64;
    for ((x, m), (z, wm)) in got.iter().zip(want) {
        assert_eq!(*m, wm);
        assert!(
            (x - z.log10()).abs() < step,
            "{m:?} at 10^{x}, want 10^{}",
            z.log10()
        );
    }
    // All three are on the x axis line, side by side where they share a cell.
    let s = screen(&a);
    let axis = s.lines().find(|l| l.contains('└')).unwrap();
    for m in ["ψ", "◦", "●"] {
        assert!(axis.contains(m), "{m} missing: {axis}");
    }
    // Fig. 3 (size effect on) stays elastic: no marks at all.
    assert_eq!(fig("fig3").plot.regime_marks, vec![]);
}

#[test]
fn g_pins_a_ghost_that_stays_while_parameters_change() {
    let mut a = fig("fig2");
    let pinned = a.plot.clone();
    ch(&mut a, 'g');
    assert!(a.ghost.is_some());
    assert!(screen(&a).contains("ghost = now"), "{}", screen(&a));
    ch(&mut a, 'k'); // h_rms
    ch(&mut a, 'l');
    ch(&mut a, 'm');
    assert_ne!(a.plot, pinned, "the curves moved");
    let g = a.ghost.as_ref().unwrap();
    assert_eq!(g.plot, pinned, "the ghost did not");
    let s = screen(&a);
    assert!(s.contains("ghost: h_rms 19.8 nm, closed form"), "{s}");
    // Dim, under the current curves: some cells of the chart are the ghost's.
    let (w, h) = a.size;
    let mut t = ratatui::Terminal::new(ratatui::backend::TestBackend::new(w, h)).unwrap();
    t.draw(|f| f.render_widget(&a, f.area())).unwrap();
    let dim = t
        .backend()
        .buffer()
        .content()
        .iter()
        .filter(|c| {
            c.fg == ratatui::style::Color::DarkGray
                && ('\u{2801}'..='\u{28FF}').contains(&c.symbol().chars().next().unwrap())
        })
        .count();
    assert!(dim > 10, "{dim} ghost cells");
    // In a wide terminal the legend itself names it.
    update(&mut a, Message::Resize(160, 48));
    let s = screen(&a);
    let legend = s.lines().find(|l| l.contains("━━ elastic")).unwrap();
    assert!(
        legend.contains("┄┄ ghost: h_rms 19.8 nm, closed form"),
        "{legend}"
    );
    update(&mut a, Message::Resize(80, 24));
    // g again clears it.
    ch(&mut a, 'g');
    assert!(a.ghost.is_none());
    assert!(!screen(&a).contains("ghost:"));
    // A new sweep gives a new x axis: the ghost goes, and says so.
    ch(&mut a, 'g');
    ch(&mut a, 'x');
    assert!(a.ghost.is_none());
    assert!(a.status.as_ref().unwrap().text.contains("ghost cleared"));
}

/// All pages of the help, as text.
fn help_pages(a: &mut roughtui::tui::app::App) -> String {
    ch(a, '?');
    let mut seen = String::new();
    for _ in 0..6 {
        seen.push_str(&screen(a));
        press(a, KeyCode::Right, KeyModifiers::NONE);
    }
    ch(a, '?');
    seen
}

#[test]
fn only_a_served_student_has_the_follow_key() {
    use roughtui::tui::keys::{footer, message_for_key};
    let f = common::key(KeyCode::Char('f'), KeyModifiers::NONE);

    let mut local = fig("fig2");
    assert_eq!(message_for_key(&local, &f), None);
    assert!(!footer(&local, 200).contains("f follow"));
    let help = help_pages(&mut local);
    assert!(help.contains("Esc or ? closes"), "{help}");
    assert!(!help.contains("follow the lecturer"), "{help}");
    assert!(help.contains("save a snapshot here (.ron)"), "{help}");
    assert!(!help.contains("snapshot (.ron text) to copy"), "{help}");

    let mut student = fig("fig2");
    student.student = true;
    // Without --lecturer-keys there is nobody to follow.
    assert_eq!(message_for_key(&student, &f), None);
    assert!(!footer(&student, 200).contains("f follow"));
    assert!(!help_pages(&mut student).contains("follow the lecturer"));
    student.lecturer_keys = true;
    assert_eq!(message_for_key(&student, &f), Some(Message::Follow));
    // The footer offers it only while a lecturer is connected (the key
    // itself answers "no lecturer connected" otherwise) ...
    assert!(!footer(&student, 200).contains("f follow"));
    student.lecturer_here = true;
    // ... and first, so that 80 columns keep it.
    assert!(footer(&student, 78).starts_with("f follow  "));
    assert!(screen(&student).contains("f follow"));
    let help = help_pages(&mut student);
    assert!(help.contains(" f ") && help.contains("follow the lecturer again"));
    // A student's s and p write nothing on the server; the help says so.
    assert!(
        help.contains("show the snapshot (.ron) to copy; y there: clipboard"),
        "{help}"
    );
    assert!(help.contains("no pictures over SSH"), "{help}");
    assert!(!help.contains("save a snapshot here"), "{help}");
    assert!(!help.contains("as a picture here"), "{help}");
    assert_eq!(
        message_for_key(
            &student,
            &common::key(KeyCode::Char('s'), KeyModifiers::NONE)
        ),
        Some(Message::StartSave)
    );
    // Under the help or in a prompt, f is not the follow key.
    ch(&mut student, '?');
    assert_eq!(message_for_key(&student, &f), None);
    ch(&mut student, '?');
    press(&mut student, KeyCode::Enter, KeyModifiers::NONE);
    assert!(matches!(student.mode, Mode::Value(..)));
    assert_ne!(message_for_key(&student, &f), Some(Message::Follow));
    // The explorer itself leaves the scene alone on Follow.
    let before = student.state.clone();
    update(&mut student, Message::Follow);
    assert_eq!(student.state, before);
}

#[test]
fn a_swept_value_typed_outside_the_sweep_says_where_the_marker_went() {
    let mut a = fig("fig2");
    assert_eq!(a.selected_axis(), Axis::Zeta);
    enter(&mut a);
    ctrl(&mut a, 'u');
    type_text(&mut a, "1e5");
    enter(&mut a);
    assert_eq!(a.state.params.get(Axis::Zeta), 1e5);
    assert_eq!(a.marker(), None);
    let s = screen(&a);
    assert!(
        s.contains("outside the sweep: no marker on the chart"),
        "{s}"
    );
    // A step brings the value back into the sweep, and the hint goes.
    press(&mut a, KeyCode::Left, KeyModifiers::NONE);
    assert!(a.marker().is_some());
    assert_eq!(a.status, None);
}
