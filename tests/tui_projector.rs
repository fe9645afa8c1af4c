//! The lecturer's projector view (`P`) without a server: while the poll
//! is open, the question and how many answered in large type, the
//! countdown (`t`), no answers; after the reveal the model's answer, the
//! median, the share within 10 % and the count over the histogram; it
//! takes the poll's keys and not the explorer's.

mod common;

use common::app::{ch, fig, press, screen};
use crossterm::event::{KeyCode, KeyModifiers};
use rough_model::Axis;
use roughtui::class::{Ask, ClassView, Question, Tally};
use roughtui::tui::app::{update, App, Message};
use roughtui::tui::keys::message_for_key;

/// The lecturer at `size` with a poll of 30 answers around fig2's 321.5
/// (12 within 10 % of it), open or revealed.
fn lecturer(size: (u16, u16), revealed: bool) -> App {
    let mut a = fig("fig2");
    update(&mut a, Message::Resize(size.0, size.1));
    let mut answers = vec![300.0; 12];
    answers.extend([100.0; 8]);
    answers.extend([1000.0; 10]);
    a.class.view = Some(ClassView {
        seats: vec![],
        poll: Some(Tally {
            question: Question {
                axis: Axis::Zeta,
                ask: Ask::Share { rising: true },
                truth: 321.5,
                size_effect: false,
                read: false,
            },
            answers,
            asked: 31,
            revealed,
            sweep: roughtui::presets::load("fig2").unwrap().sweep,
        }),
    });
    a
}

fn key(app: &App, c: char) -> Option<Message> {
    message_for_key(app, &common::key(KeyCode::Char(c), KeyModifiers::NONE))
}

/// The rows of `s` that carry large type (or bars): four blocks or more.
fn large_rows(s: &str) -> usize {
    s.lines().filter(|l| l.matches('█').count() >= 4).count()
}

#[test]
fn while_the_poll_is_open_the_projector_counts_and_counts_down() {
    let mut l = lecturer((160, 45), false);
    ch(&mut l, 'P');
    assert!(l.class.projector);
    let s = screen(&l);
    eprintln!("{s}");
    assert!(
        s.starts_with("Predict: where does the plastic share pass ½?"),
        "{s}"
    );
    assert!(s.contains("answered") && large_rows(&s) >= 3, "{s}");
    assert!(s.contains("the answers show here at the reveal"), "{s}");
    // Nothing of the answers, nor the truth.
    assert!(!s.contains("321") && !s.contains("median"), "{s}");
    // t: a countdown of 30 s, then 1 min, 2 min, off.
    ch(&mut l, 't');
    let s = screen(&l);
    assert!(s.contains("time left"), "{s}");
    for (want, secs) in [(Some(60), 60), (Some(120), 120), (None, 0)] {
        ch(&mut l, 't');
        assert_eq!(
            l.class.countdown.map(|c| c.1.as_secs()),
            want.map(|_: u64| secs)
        );
    }
    // The explorer's keys do nothing here; the poll's act.
    let before = l.state.params;
    press(&mut l, KeyCode::Right, KeyModifiers::NONE);
    assert_eq!(l.state.params, before);
    assert_eq!(key(&l, 'x'), None);
    assert_eq!(key(&l, 'v'), Some(Message::Poll));
    assert_eq!(key(&l, 'C'), Some(Message::CancelPoll));
    press(&mut l, KeyCode::Esc, KeyModifiers::NONE);
    assert!(!l.class.projector);
    // A student has no projector.
    let mut st = fig("fig2");
    st.student = true;
    assert_eq!(key(&st, 'P'), None);
}

#[test]
fn after_the_reveal_the_projector_shows_the_truth_median_and_share() {
    let mut l = lecturer((160, 45), true);
    ch(&mut l, 'P');
    let s = screen(&l);
    eprintln!("{s}");
    for t in [
        "the model: ζ =",
        "median answer: ζ =",
        "within 10 % of it",
        "12 of 30",
        "answered",
        "▲ the model: 321.5",
    ] {
        assert!(s.contains(t), "{t}:\n{s}");
    }
    // Four figures in a row, five rows of large type.
    assert!(large_rows(&s) >= 3, "{s}");
    // The histogram: three bars, their counts over them.
    for n in ["12", "8", "10"] {
        assert!(
            s.lines().any(|l| l.split_whitespace().any(|w| w == n)),
            "{n}:\n{s}"
        );
    }
    // At 80×24 the figures fit as plain lines.
    let mut l = lecturer((80, 24), true);
    ch(&mut l, 'P');
    let s = screen(&l);
    eprintln!("{s}");
    assert!(s.contains("the model: ζ = 321.5"), "{s}");
    assert!(s.contains("within 10 % of it 40%  12 of 30"), "{s}");
}

#[test]
fn in_ascii_the_projector_is_all_ascii() {
    use roughtui::tui::glyphs::Glyphs;
    for revealed in [false, true] {
        for size in [(160, 45), (80, 24)] {
            let mut l = lecturer(size, revealed);
            l.theme = l.theme.with_glyphs(Glyphs::Ascii);
            ch(&mut l, 'P');
            ch(&mut l, 't');
            let s = screen(&l);
            assert!(s.is_ascii(), "{s}");
            assert!(s.contains("###") || size.0 == 80, "{s}");
        }
    }
}
