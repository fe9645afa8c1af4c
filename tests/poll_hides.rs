//! An open poll hides every mark that gives or brackets its answer, on
//! every view a student (or the lecturer's projector) can reach, at 80×24
//! and 160×48, for each of the shipped lesson's polls: the claims and
//! their numbers, the readout's values at the marker, the slopes chart's
//! regime marks, the map's colours and contour, the load and contact
//! views at the marker. After the reveal they are back.

mod common;

use std::path::Path;
use std::sync::Arc;

use crossterm::event::{KeyCode, KeyModifiers};
use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::style::Color;
use ratatui::Terminal;
use roughtui::class::{Asked, ClassView, Lesson, LessonAt, Tally};
use roughtui::figure::{claims, View};
use roughtui::tui::app::{update, App, Message};
use roughtui::tui::theme::Theme;

fn lesson() -> Arc<Lesson> {
    Arc::new(roughtui::class::lesson::read(Path::new("lessons/paper.ron")).unwrap())
}

fn draw(app: &App) -> Buffer {
    let (w, h) = app.size;
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
    t.backend().buffer().clone()
}

fn text(b: &Buffer) -> String {
    let mut s = String::new();
    for y in 0..b.area.height {
        for x in 0..b.area.width {
            s.push_str(b[(x, y)].symbol());
        }
        s.push('\n');
    }
    s
}

/// The screen as a student or the lecturer has it at step `at` with its
/// poll open, as the server sets it up (the poll's scene, the step line
/// with its question pending, the question asked).
fn at_poll(lesson: &Arc<Lesson>, at: usize, size: (u16, u16), lecturer: bool) -> App {
    let step = &lesson.steps[at];
    let q = step.poll.unwrap();
    let mut app = App::new(step.state.clone(), Theme::colored(), size);
    app.view = step.view;
    app.lecturer_keys = true;
    app.class.step = Some(LessonAt::new(Arc::clone(lesson), at).line());
    if lecturer {
        app.class.view = Some(ClassView {
            seats: vec![],
            poll: Some(Tally {
                question: q,
                answers: vec![],
                asked: 0,
                revealed: false,
                sweep: step.state.sweep,
            }),
        });
    } else {
        app.student = true;
        app.class.asked = Some(Asked {
            question: q,
            answer: None,
            revealed: false,
            changed: false,
        });
    }
    update(&mut app, Message::Tick);
    app
}

/// The poll revealed: the step's question no longer pending.
fn reveal(app: &mut App) {
    if let Some(a) = app.class.asked.as_mut() {
        a.revealed = true;
    }
    if let Some(p) = app.class.view.as_mut().and_then(|v| v.poll.as_mut()) {
        p.revealed = true;
    }
    // As the server reveals: the step's answer and its claims show.
    if let Some(s) = app.class.step.as_mut() {
        s.pending = None;
        s.claims_hidden = false;
    }
    update(app, Message::Tick);
}

/// The numbers the scene's claims print ("0.008318", "120.2").
fn claim_numbers(app: &App) -> Vec<String> {
    let mut out = Vec::new();
    for c in claims(&app.state) {
        for t in [c.text(), c.short_text()] {
            let after = t.split(" at ").nth(1).unwrap_or("");
            for tok in after.split(|c: char| c.is_whitespace() || "()".contains(c)) {
                if tok.len() >= 3 && tok.parse::<f64>().is_ok() {
                    out.push(tok.to_string());
                }
            }
        }
    }
    out.sort();
    out.dedup();
    out
}

/// The row of the chart's x axis (the one with its corner).
fn x_axis_row(s: &str) -> &str {
    s.lines().find(|l| l.contains('└')).unwrap_or("")
}

/// Cells drawn as the regime map draws its points (upper half blocks).
fn map_cells(b: &Buffer) -> usize {
    b.content.iter().filter(|c| c.symbol() == "▀").count()
}

/// Braille cells of the graph drawn in `colour` (a curve's).
fn curve_cells(b: &Buffer, colour: Color) -> usize {
    b.content
        .iter()
        .filter(|c| {
            let ch = c.symbol().chars().next().unwrap_or(' ');
            ('\u{2801}'..='\u{28ff}').contains(&ch) && c.fg == colour
        })
        .count()
}

/// The curves a step's screen must not draw while its poll (or the next,
/// for a step that hides its claims) waits, by view: the paper's lesson
/// asks a reading question first (its chart stays), then predictions —
/// fig. 2's share (no plastic or total slope, no Ψ_P), fig. 3's share with
/// the size-dependent hardness (no plastic or total slope, no Ψ*), which
/// step 4's indices keep off too.
fn withheld_curves(at: usize, view: View, t: &Theme) -> Vec<(&'static str, Color)> {
    let c = |s: ratatui::style::Style| s.fg.unwrap();
    match (at, view) {
        (2 | 4, View::Slopes) => vec![("plastic", c(t.plastic.style)), ("total", c(t.total.style))],
        (2, View::Indices) => vec![("Ψ_P", c(t.psi_p.style))],
        (3 | 4, View::Indices) => vec![("Ψ*", c(t.psi_star.style))],
        _ => vec![],
    }
}

/// The curves that stay: the reading question's, and the others'.
fn kept_curves(at: usize, view: View, t: &Theme) -> Vec<(&'static str, Color)> {
    let c = |s: ratatui::style::Style| s.fg.unwrap();
    match (at, view) {
        (0 | 1, View::Slopes) => vec![("plastic", c(t.plastic.style)), ("total", c(t.total.style))],
        (2, View::Indices) => vec![("Ψ*", c(t.psi_star.style))],
        (3 | 4, View::Indices) => vec![("Ψ_P", c(t.psi_p.style))],
        _ => vec![],
    }
}

fn check_hidden(app: &App, what: &str) {
    let b = draw(app);
    let s = text(&b);
    // The legend names curves, never where one went ("= total here",
    // "plastic < 1", "below the chart").
    for remark in [" here", "plastic <", "plastic >", "below the chart"] {
        assert!(
            !s.contains(remark),
            "{what}: the legend says {remark:?}\n{s}"
        );
    }
    let at = app.class.step.as_ref().map_or(0, |l| l.at - 1);
    for (name, colour) in withheld_curves(at, app.view, &app.theme) {
        assert_eq!(curve_cells(&b, colour), 0, "{what}: {name} is drawn\n{s}");
        assert!(
            s.contains(&format!("{name} ?")),
            "{what}: {name} unnamed\n{s}"
        );
    }
    for (name, colour) in kept_curves(at, app.view, &app.theme) {
        assert!(
            curve_cells(&b, colour) > 0,
            "{what}: {name} is not drawn\n{s}"
        );
    }
    for n in claim_numbers(app) {
        assert!(!s.contains(&n), "{what}: the claims' {n} shows\n{s}");
    }
    if let Some(c) = claims(&app.state).first() {
        assert!(!s.contains(&c.text()), "{what}: a claim shows\n{s}");
    }
    // The readout: no index, slope or share at the marker.
    assert!(s.contains("Ψ_P    ?"), "{what}: Ψ_P shows\n{s}");
    // The readout's column, left of the chart.
    for line in s.lines().map(|l| l.chars().take(34).collect::<String>()) {
        for label in [
            "Ψ_GW  ", "Ψ_P    ", "Ψ*    ", "S_el  ", "S_pl  ", "S_tot ", "S_P   ",
        ] {
            for (i, _) in line.match_indices(label) {
                let value = &line[i + label.len()..];
                assert!(value.starts_with('?'), "{what}: {label} shows\n{s}");
            }
        }
    }
    if app.size.1 >= 48 {
        let until = if app.class.hidden_question().is_some() {
            "plastic ?  (until the reveal)"
        } else {
            "plastic ?  (until the next poll)"
        };
        assert!(s.contains(until), "{what}\n{s}");
    }
    match app.view {
        View::Slopes => {
            let axis = x_axis_row(&s);
            for m in ["ψ", "◦", "●"] {
                assert!(!axis.contains(m), "{what}: the regime mark {m} shows\n{s}");
            }
        }
        View::Map => {
            assert_eq!(map_cells(&b), 0, "{what}: the map's colours show\n{s}");
            assert!(s.contains("contour wait for "), "{what}\n{s}");
            assert!(!s.contains(">90%"), "{what}: the colour scale shows\n{s}");
        }
        View::Load => {
            assert!(s.contains("the areas at the marker wait"), "{what}\n{s}");
            assert!(!s.contains("━ elastic"), "{what}: the curves show\n{s}");
        }
        View::Contact => {
            assert!(s.contains("the simulation and the theory's"), "{what}\n{s}");
            assert!(
                !s.contains("plastic ·") && !s.contains("%pl"),
                "{what}\n{s}"
            );
        }
        _ => {}
    }
}

fn check_shown(app: &App, what: &str) {
    let b = draw(app);
    let s = text(&b);
    let at = app.class.step.as_ref().map_or(0, |l| l.at - 1);
    // The curves withheld are back (fig. 3's plastic slope lies below
    // its chart, its total under Persson's line: the legend says so now).
    for (name, colour) in withheld_curves(at, app.view, &app.theme) {
        if at == 4 && app.view == View::Slopes {
            assert!(
                s.contains("plastic <") && s.contains("= total"),
                "{what}\n{s}"
            );
            continue;
        }
        assert!(
            curve_cells(&b, colour) > 0,
            "{what}: {name} is not back\n{s}"
        );
    }
    assert!(
        !s.contains("Ψ_P    ?"),
        "{what}: the readout still waits\n{s}"
    );
    match app.view {
        View::Map => assert!(map_cells(&b) > 100, "{what}: no map\n{s}"),
        View::Load => assert!(s.contains("━ elastic"), "{what}\n{s}"),
        View::Slopes if app.state.name == "fig1" => {
            // fig1's share passes 90 % inside its sweep: its mark is back.
            assert!(x_axis_row(&s).contains('●'), "{what}\n{s}")
        }
        _ => {}
    }
}

#[test]
fn every_view_hides_the_open_polls_answer() {
    let lesson = lesson();
    let polls: Vec<usize> = (0..lesson.steps.len())
        .filter(|i| lesson.steps[*i].poll.is_some())
        .collect();
    assert_eq!(polls, [1, 2, 4], "the paper's three polls");
    // The first a reading question, the others predictions.
    let read: Vec<bool> = polls
        .iter()
        .map(|i| lesson.steps[*i].poll.unwrap().read)
        .collect();
    assert_eq!(read, [true, false, false]);
    for at in polls {
        for size in [(80, 24), (160, 48)] {
            for lecturer in [false, true] {
                let mut app = at_poll(&lesson, at, size, lecturer);
                let who = if lecturer { "lecturer" } else { "student" };
                for _ in 0..View::ALL.len() {
                    if app.view.exists(app.state.is_measured()) {
                        let what = format!("step {} {:?} {who} {size:?}", at + 1, app.view);
                        check_hidden(&app, &what);
                    }
                    common::app::press(&mut app, KeyCode::Tab, KeyModifiers::NONE);
                }
                // Every help page, too.
                update(&mut app, Message::ToggleHelp);
                for page in 0..6 {
                    let what = format!("step {} {who} {size:?} help {page}", at + 1);
                    check_help(&app, &what);
                    update(&mut app, Message::HelpPage { next: true });
                }
                update(&mut app, Message::ToggleHelp);
                // Revealed: everything is back.
                reveal(&mut app);
                for _ in 0..View::ALL.len() {
                    let what = format!("step {} {:?} {who} {size:?} revealed", at + 1, app.view);
                    check_shown(&app, &what);
                    common::app::press(&mut app, KeyCode::Tab, KeyModifiers::NONE);
                }
            }
        }
    }
}

fn check_help(app: &App, what: &str) {
    let s = text(&draw(app));
    for n in claim_numbers(app) {
        assert!(!s.contains(&n), "{what}: the claims' {n} shows\n{s}");
    }
}

/// A student walking the marker across fig. 2's answer: the readout's
/// values at the marker, the map and the load view stay as they were.
#[test]
fn walking_across_the_answer_changes_nothing_that_answers() {
    let lesson = lesson();
    let mut app = at_poll(&lesson, 2, (100, 30), false);
    let q = app.class.asked.unwrap().question;
    for view in [View::Slopes, View::Map, View::Load, View::Contact] {
        app.view = view;
        let mut seen = Vec::new();
        for z in [q.truth * 0.8, q.truth * 1.25] {
            app.state.params = app.state.params.with(q.axis, z).unwrap();
            update(&mut app, Message::Tick);
            let b = draw(&app);
            let s = text(&b);
            let at_marker: Vec<String> = s
                .lines()
                .map(|l| l.chars().take(34).collect::<String>())
                // (H_y/H0 moves with ζ: it is the hardness, not the answer.)
                .filter(|l| !l.contains("H_y"))
                .filter(|l| {
                    ["Ψ", "S_", "plastic", "marker"]
                        .iter()
                        .any(|p| l.starts_with(p))
                })
                .collect();
            assert!(at_marker.len() >= 4, "{s}");
            seen.push((at_marker, map_cells(&b), s.contains("━ elastic")));
        }
        assert_eq!(
            seen[0], seen[1],
            "{view:?}: what answers moved with the marker"
        );
    }
}

/// The steps before a poll that hide their claims (the paper's steps 1
/// and 4) keep off what would answer that poll too: step 4's Ψ*, which
/// answers fig. 3's question, while fig. 2's Ψ_P stays.
#[test]
fn the_step_before_a_poll_hides_what_answers_it() {
    let lesson = lesson();
    for at in [0, 3] {
        assert!(lesson.steps[at].claims_hidden, "step {}", at + 1);
        for size in [(80, 24), (160, 48)] {
            let step = &lesson.steps[at];
            let mut app = App::new(step.state.clone(), Theme::colored(), size);
            app.view = step.view;
            app.student = true;
            app.lecturer_keys = true;
            app.class.step = Some(LessonAt::new(Arc::clone(&lesson), at).line());
            update(&mut app, Message::Tick);
            for _ in 0..View::ALL.len() {
                if app.view.exists(app.state.is_measured()) {
                    let what = format!("step {} {:?} {size:?}", at + 1, app.view);
                    check_hidden(&app, &what);
                }
                common::app::press(&mut app, KeyCode::Tab, KeyModifiers::NONE);
            }
        }
    }
}

/// On an ASCII terminal of 100×30 every step of the lesson, its poll open
/// or waiting, says until when in whole words: nothing cut mid-sentence.
#[test]
fn an_ascii_screen_says_until_when_in_whole_words() {
    use roughtui::tui::glyphs::Glyphs;
    let lesson = lesson();
    for at in 0..lesson.steps.len() {
        let step = &lesson.steps[at];
        let theme = Theme::colored().with_glyphs(Glyphs::Ascii);
        let mut app = App::new(step.state.clone(), theme, (100, 30));
        app.view = step.view;
        app.student = true;
        app.lecturer_keys = true;
        app.class.step = Some(LessonAt::new(Arc::clone(&lesson), at).line());
        if let Some(q) = step.poll {
            app.class.asked = Some(Asked {
                question: q,
                answer: None,
                revealed: false,
                changed: false,
            });
        }
        update(&mut app, Message::Tick);
        let s = text(&draw(&app));
        for l in s
            .lines()
            .filter(|l| l.contains("(until") || l.contains("(this step"))
        {
            let open = l.find('(').unwrap();
            let said = &l[open..l[open..].find(')').map_or(l.len(), |c| open + c + 1)];
            assert!(
                [
                    "(until the reveal)",
                    "(until the next poll)",
                    "(this step's claims show after the lesson's next poll)"
                ]
                .contains(&said),
                "step {}: {said:?}\n{s}",
                at + 1
            );
        }
    }
}
