//! The class panels without a server: what the lecturer's and a student's
//! explorer draw and which keys they take when the class fills them in.

mod common;

use std::time::Duration;

use common::app::{ch, fig, press, screen, type_text};
use crossterm::event::{KeyCode, KeyModifiers};
use rough_model::Axis;
use roughtui::class::{Ask, Asked, ClassView, Question, Seat, SeatState, Tally};
use roughtui::tui::app::{update, App, Message, Mode};
use roughtui::tui::keys::message_for_key;

fn lecturer(name: &str) -> App {
    let mut a = fig(name);
    a.class.view = Some(ClassView::default());
    a
}

fn key(app: &App, code: KeyCode) -> Option<Message> {
    message_for_key(app, &common::key(code, KeyModifiers::NONE))
}

fn seat(name: &str, state: SeatState, size: (u16, u16)) -> Seat {
    Seat {
        id: 1,
        name: name.into(),
        state,
        size,
        marker: "braille".into(),
        idle: Duration::from_secs(75),
        via: "ssh",
    }
}

#[test]
fn only_the_lecturer_has_the_poll_and_class_keys() {
    let plain = fig("fig2");
    for c in ['v', 'V', 'w', 'S'] {
        assert_eq!(key(&plain, KeyCode::Char(c)), None, "{c}");
    }
    let l = lecturer("fig2");
    assert_eq!(key(&l, KeyCode::Char('v')), Some(Message::Poll));
    assert_eq!(key(&l, KeyCode::Char('V')), Some(Message::PollTyped));
    assert_eq!(key(&l, KeyCode::Char('w')), Some(Message::ToggleClass));
    assert_eq!(key(&l, KeyCode::Char('S')), Some(Message::SavePoll));
    let mut s = fig("fig2");
    s.student = true;
    s.lecturer_keys = true;
    assert_eq!(key(&s, KeyCode::Char('v')), None);
    assert_eq!(key(&s, KeyCode::Enter), Some(Message::StartValue));
    // While a poll waits for them, a student's Enter answers.
    let q = Question {
        axis: Axis::Zeta,
        ask: Ask::Share { rising: true },
        truth: 321.5,
        size_effect: false,
        read: false,
    };
    s.class.asked = Some(Asked {
        question: q,
        answer: None,
        revealed: false,
        changed: false,
    });
    assert_eq!(key(&s, KeyCode::Enter), Some(Message::Answer));
    assert!(screen(&s).contains("Predict: where does the plastic share pass ½?"));
    assert!(!screen(&s).contains("Ψ_P reaches 1 at"));
    // After the reveal, Enter dismisses the result (the session acts on it).
    s.class.asked.as_mut().unwrap().revealed = true;
    assert_eq!(key(&s, KeyCode::Enter), Some(Message::Answer));
    assert!(screen(&s).contains("the model: ζ = 321.5 · you did not answer"));
    assert!(screen(&s).contains("⏎ dismiss"));
    s.class.asked = None;
    assert_eq!(key(&s, KeyCode::Enter), Some(Message::StartValue));
    // The lecturer's C cancels.
    assert_eq!(key(&l, KeyCode::Char('C')), Some(Message::CancelPoll));
}

#[test]
fn the_lecturer_types_a_polls_value_inside_the_sweep() {
    let mut l = lecturer("fig3");
    ch(&mut l, 'V');
    assert!(matches!(l.mode, Mode::Truth(Axis::Zeta, _)));
    assert!(screen(&l).contains("poll: the true ζ = "));
    type_text(&mut l, "2e4");
    press(&mut l, KeyCode::Enter, KeyModifiers::NONE);
    assert!(
        matches!(l.mode, Mode::Truth(..)),
        "an outside value was taken"
    );
    let s = l.status.as_ref().unwrap();
    assert!(s.error);
    assert_eq!(
        s.text,
        "ζ = 20000 is outside the sweep 1…1e4: the class answers inside it"
    );
    assert_eq!(l.class.typed, None);
    press(&mut l, KeyCode::Char('u'), KeyModifiers::CONTROL);
    type_text(&mut l, "abc");
    press(&mut l, KeyCode::Enter, KeyModifiers::NONE);
    assert_eq!(l.class.typed, None);
    press(&mut l, KeyCode::Char('u'), KeyModifiers::CONTROL);
    type_text(&mut l, "250");
    press(&mut l, KeyCode::Enter, KeyModifiers::NONE);
    assert_eq!(l.mode, Mode::Main);
    assert_eq!(l.class.typed, Some((Axis::Zeta, 250.0)));
    // Esc leaves the prompt without a poll.
    l.class.typed = None;
    ch(&mut l, 'V');
    press(&mut l, KeyCode::Esc, KeyModifiers::NONE);
    assert_eq!((l.mode.clone(), l.class.typed), (Mode::Main, None));
}

#[test]
fn the_lecturer_sees_the_class_and_the_histogram() {
    let mut l = lecturer("fig2");
    l.class.view = Some(ClassView {
        seats: vec![
            seat("alice", SeatState::Answered, (100, 30)),
            seat("bob", SeatState::Answering, (70, 20)),
        ],
        poll: Some(Tally {
            question: Question {
                axis: Axis::Zeta,
                ask: Ask::Share { rising: true },
                truth: 321.5,
                size_effect: false,
                read: false,
            },
            answers: vec![100.0, 100.0, 1000.0],
            asked: 4,
            revealed: false,
            sweep: roughtui::presets::load("fig2").unwrap().sweep,
        }),
    });
    let s = screen(&l);
    assert!(
        s.lines()
            .nth(1)
            .unwrap()
            .starts_with("2 students · 3/4 answered · 1 terminal < 80×24"),
        "{s}"
    );
    // Two bars, the one of two answers twice as high (in eighths of a cell).
    let bars = |s: &str, col: usize| -> usize {
        s.lines()
            .filter_map(|l| l.chars().nth(col))
            .filter_map(|c| "▁▂▃▄▅▆▇█".chars().position(|b| b == c))
            .map(|i| i + 1)
            .sum()
    };
    let cols: Vec<usize> = (0..80).filter(|c| bars(&s, *c) > 0).collect();
    assert_eq!(cols.len(), 2, "{s}");
    assert_eq!(bars(&s, cols[0]), 2 * bars(&s, cols[1]), "{s}");
    assert!(s.contains(" 3/4 answered "), "{s}");
    // The reveal: the true value's column.
    l.class
        .view
        .as_mut()
        .unwrap()
        .poll
        .as_mut()
        .unwrap()
        .revealed = true;
    let s = screen(&l);
    assert!(s.contains("┃"), "{s}");
    assert!(s.contains("ζ = 321.5 · 3 answers"), "{s}");
    // On the load view (not along ζ) only the count, and where to look.
    l.view = roughtui::figure::View::Load;
    let s = screen(&l);
    assert!(!s.contains('█') && !s.contains('┃'), "{s}");
    assert!(s.contains("on a chart along ζ"), "{s}");
    // w: the class list.
    ch(&mut l, 'w');
    assert_eq!(l.mode, Mode::Class);
    let s = screen(&l);
    let row = s.lines().find(|r| r.contains("bob")).unwrap();
    for cell in ["bob", "answering", "70×20", "braille", "1m15s"] {
        assert!(row.contains(cell), "{cell} in {row}");
    }
    assert!(s.contains("w closes"), "{s}");
    ch(&mut l, 'w');
    assert_eq!(l.mode, Mode::Main);
}

#[test]
fn in_the_ascii_set_every_class_panel_is_ascii() {
    use roughtui::tui::glyphs::Glyphs;
    let ascii = |a: &App, what: &str| {
        let s = screen(a);
        let bad: String = s.chars().filter(|c| !c.is_ascii()).collect();
        assert!(bad.is_empty(), "{what}: {bad:?} in\n{s}");
        s
    };
    let q = Question {
        axis: Axis::Zeta,
        ask: Ask::Share { rising: false },
        truth: 321.5,
        size_effect: false,
        read: false,
    };
    let mut l = lecturer("fig2");
    l.theme = l.theme.with_glyphs(Glyphs::Ascii);
    l.class.view = Some(ClassView {
        seats: vec![
            seat("José", SeatState::Answered, (100, 30)),
            seat(&format!("{}…", "ζ".repeat(31)), SeatState::Own, (70, 20)),
        ],
        poll: Some(Tally {
            question: q,
            answers: vec![100.0, 100.0, 1000.0, 3000.0],
            asked: 4,
            revealed: false,
            sweep: roughtui::presets::load("fig2").unwrap().sweep,
        }),
    });
    let s = ascii(&l, "open poll");
    assert!(
        s.contains("2 students | 4/4 answered | 1 terminal < 80x24"),
        "{s}"
    );
    assert!(s.contains('#'), "no bars:\n{s}");
    l.class
        .view
        .as_mut()
        .unwrap()
        .poll
        .as_mut()
        .unwrap()
        .revealed = true;
    let s = ascii(&l, "revealed poll");
    assert!(s.contains("revealed zeta = 321.5 (4 answers)"), "{s}");
    ch(&mut l, 'w');
    let s = ascii(&l, "class list");
    assert!(s.contains("Jose"), "{s}");
    assert!(s.contains("70x20"), "{s}");
    ch(&mut l, 'w');
    ch(&mut l, 'V');
    let s = ascii(&l, "truth prompt");
    assert!(s.contains("poll: the true zeta = "), "{s}");

    let mut st = fig("fig2");
    st.theme = st.theme.with_glyphs(Glyphs::Ascii);
    st.student = true;
    st.lecturer_keys = true;
    st.class.asked = Some(Asked {
        question: q,
        answer: None,
        revealed: false,
        changed: false,
    });
    let s = ascii(&st, "question");
    assert!(
        s.contains("Predict: where does the plastic share fall below 1/2?"),
        "{s}"
    );
    st.class.asked.as_mut().unwrap().answer = Some(1000.0);
    ascii(&st, "answered");
    st.class.asked.as_mut().unwrap().revealed = true;
    let s = ascii(&st, "revealed");
    assert!(
        s.contains("the model: zeta = 321.5 | you: 1000 | 3.1x high | Enter dismisses"),
        "{s}"
    );
}

/// An open poll shows nothing of its answer: not on the lecturer's screen
/// (the projector), a wide student's, any help page, nor in the readout
/// while the student walks the marker across the answer.
#[test]
fn an_open_poll_shows_nothing_of_its_answer() {
    let truth = roughtui::figure::claims(&roughtui::presets::load("fig2").unwrap())[0].at;
    let digits = ["321", "320", "≈"];
    let clean = |s: &str, what: &str| {
        for d in digits {
            assert!(!s.contains(d), "{what} shows {d}:\n{s}");
        }
    };
    let q = Question {
        axis: Axis::Zeta,
        ask: Ask::Share { rising: true },
        truth,
        size_effect: false,
        read: false,
    };
    // Before the poll the lecturer's screen names the answer.
    let mut l = lecturer("fig2");
    l.size = (100, 30);
    l.class.view = Some(ClassView {
        seats: vec![seat("alice", SeatState::Answering, (160, 48))],
        poll: Some(Tally {
            question: q,
            answers: vec![],
            asked: 1,
            revealed: true,
            sweep: l.state.sweep,
        }),
    });
    ch(&mut l, 'c');
    assert!(screen(&l).contains("321.5"));
    l.class
        .view
        .as_mut()
        .unwrap()
        .poll
        .as_mut()
        .unwrap()
        .revealed = false;
    let s = screen(&l);
    clean(&s, "the lecturer");
    assert!(
        s.contains("poll open: 0/1 answered · v reveals · C cancels"),
        "{s}"
    );
    assert!(s.contains("plastic ?"), "{s}");
    // Every help page of the lecturer and of a student.
    let mut st = fig("fig2");
    st.student = true;
    st.lecturer_keys = true;
    st.class.asked = Some(Asked {
        question: q,
        answer: None,
        revealed: false,
        changed: false,
    });
    for app in [&mut l, &mut st] {
        for size in [(80, 24), (160, 48)] {
            update(app, Message::Resize(size.0, size.1));
            clean(&screen(app), "the screen");
            ch(app, '?');
            for page in 0..6 {
                let s = screen(app);
                clean(&s, &format!("help page {page} at {size:?}"));
                press(app, KeyCode::Right, KeyModifiers::NONE);
            }
            ch(app, '?');
        }
    }
    // The student walks the marker from 128 across 321.5: the share is
    // never shown, nor the slopes that make it.
    for _ in 0..8 {
        press(&mut st, KeyCode::Right, KeyModifiers::NONE);
        let s = screen(&st);
        clean(&s, "the walking student");
        assert!(s.contains("plastic ?  (until the reveal)"), "{s}");
    }
    // The index question hides the indices, and the share and regime
    // that bracket Ψ = 1 as the chart's marks do.
    st.class.asked.as_mut().unwrap().question.ask = Ask::Index {
        rising: true,
        size_effect: false,
    };
    let s = screen(&st);
    assert!(s.contains("Ψ_P    ?"), "{s}");
    assert!(s.contains("plastic ?  (until the reveal)"), "{s}");
}

/// The class list's ↑↓ choose a student (wrapping), x marks them for
/// removal (the serve session then removes them).
#[test]
fn the_class_list_chooses_and_removes() {
    let mut l = lecturer("fig2");
    let mut seats = vec![
        seat("ann", SeatState::Following, (100, 30)),
        seat("cat", SeatState::Following, (100, 30)),
    ];
    seats[1].id = 4;
    l.class.view = Some(ClassView { seats, poll: None });
    ch(&mut l, 'w');
    press(&mut l, KeyCode::Down, KeyModifiers::NONE);
    assert_eq!(l.class.chosen, 1);
    press(&mut l, KeyCode::Down, KeyModifiers::NONE);
    assert_eq!(l.class.chosen, 0);
    press(&mut l, KeyCode::Up, KeyModifiers::NONE);
    ch(&mut l, 'x');
    assert_eq!(l.class.remove, Some(4));
    assert!(screen(&l).contains("x removes"));
}
