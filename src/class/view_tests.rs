//! Unit tests of the class as a screen shows it: the questions, the
//! class line, a student's poll line.

use std::time::Duration;

use rough_model::Axis;

use super::*;
use crate::figure::View;

fn q(axis: Axis, ask: Ask, truth: f64) -> Question {
    Question {
        axis,
        ask,
        truth,
        size_effect: false,
        read: false,
    }
}

#[test]
fn the_question_follows_the_view_and_the_claims() {
    let claims = crate::figure::claims(&crate::presets::load("fig2").unwrap());
    let s = Question::of_claims(View::Slopes, &claims, false).unwrap();
    assert_eq!(s.ask, Ask::Share { rising: true });
    assert_eq!(s.truth, claims[0].at);
    assert_eq!(s.text(&UNICODE), "where does the plastic share pass ½?");
    let i = Question::of_claims(View::Indices, &claims, false).unwrap();
    assert_eq!(i.text(&UNICODE), "where does Ψ_P reach 1?");
    assert_eq!(i.truth, claims[1].at);
    // fig3 claims only the total slope's minimum: that is the question,
    // on either view, its truth the claim's own number.
    let fig3 = crate::figure::claims(&crate::presets::load("fig3").unwrap());
    for view in [View::Slopes, View::Indices] {
        let m = Question::of_claims(view, &fig3, false).unwrap();
        assert_eq!(m.ask, Ask::Minimum);
        assert_eq!((m.axis, m.truth), (Axis::Zeta, fig3[0].at));
        assert_eq!(m.text(&UNICODE), "where is the total slope smallest?");
        assert_eq!(m.value(m.truth), "ζ = 3.191");
    }
    // Elsewhere the minimum comes last: fig4 asks the share.
    let fig4 = crate::figure::claims(&crate::presets::load("fig4").unwrap());
    let f = Question::of_claims(View::Slopes, &fig4, false).unwrap();
    assert_eq!(f.ask, Ask::Share { rising: false });
    // No claim at all: the lecturer types the value.
    assert_eq!(Question::of_claims(View::Slopes, &[], false), None);
    // Only an index claim: the slopes view asks it.
    let only = [claims[1].clone()];
    assert_eq!(
        Question::of_claims(View::Slopes, &only, false).map(|q| q.truth),
        Some(claims[1].at)
    );
}

#[test]
fn durations_read_short() {
    assert_eq!(duration(Duration::from_secs(45)), "45s");
    assert_eq!(duration(Duration::from_secs(123)), "2m03s");
    assert_eq!(duration(Duration::from_secs(3720)), "1h02m");
}

#[test]
fn how_far_off() {
    let z = q(Axis::Zeta, Ask::Typed, 321.5);
    // Per cent of the truth: 316.2 is (1 − 316.2/321.5) = 1.6 % low.
    assert_eq!(z.off(316.2, &UNICODE), "1.6 % low");
    // fig1's share: 0.005623 for 0.008318 is 32 % low (not 48 %).
    let s = q(Axis::H0OverE, Ask::Share { rising: false }, 0.008318);
    assert_eq!(s.off(0.005623, &UNICODE), "32 % low");
    assert_eq!(z.off(400.0, &UNICODE), "24 % high");
    assert_eq!(z.off(322.0, &UNICODE), "0.2 % high");
    assert_eq!(z.off(321.6, &UNICODE), "spot on");
    assert_eq!(z.off(643.0, &UNICODE), "2× high");
    assert_eq!(z.off(160.75, &ASCII), "2x low");
    assert_eq!(z.off(562.34, &UNICODE), "75 % high");
    assert_eq!(z.off(3215.0 * 1.26, &UNICODE), "13× high");
    let h = q(Axis::Hurst, Ask::Typed, 0.8);
    assert_eq!(h.off(0.7, &UNICODE), "0.1 low");
    assert_eq!(h.off(0.8, &UNICODE), "spot on");
    let r = q(Axis::HRms, Ask::Typed, 2e-8);
    assert_eq!(r.value(2e-8), "h_rms = 20 nm");
}

#[test]
fn the_class_line() {
    let seat = |state, size| Seat {
        id: 1,
        name: "a".into(),
        state,
        size,
        marker: "braille".into(),
        idle: Duration::ZERO,
        via: "ssh",
    };
    let mut v = ClassView {
        seats: vec![
            seat(SeatState::Following, (100, 30)),
            seat(SeatState::Following, (79, 30)),
            seat(SeatState::Own, (80, 23)),
        ],
        poll: None,
    };
    assert_eq!(
        v.line(&UNICODE),
        "3 students · 2 following · 1 on their own · 2 terminals < 80×24"
    );
    v.seats.truncate(1);
    assert_eq!(v.line(&ASCII), "1 student - 1 following - 0 on their own");
    v.poll = Some(Tally {
        question: q(Axis::Zeta, Ask::Share { rising: true }, 321.5),
        answers: vec![100.0],
        asked: 2,
        revealed: false,
        sweep: crate::presets::load("fig2").unwrap().sweep,
    });
    assert_eq!(v.line(&UNICODE), "1 student · 1/2 answered");
    v.poll.as_mut().unwrap().revealed = true;
    assert_eq!(
        v.line(&UNICODE),
        "1 student · 1 following · 0 on their own · revealed ζ = 321.5 (1 answer)"
    );
}

#[test]
fn a_students_line_fits_80_columns() {
    let mut a = Asked {
        question: q(Axis::Zeta, Ask::Share { rising: false }, 321.5),
        answer: None,
        revealed: false,
        changed: false,
    };
    for w in [80, 60, 40] {
        let l = a.line(&UNICODE, w);
        assert!(l.starts_with("Predict: where does the plastic share fall below ½?"));
        assert!(l.chars().count() <= w.max(51), "{l}");
    }
    a.answer = Some(643.0);
    assert!(a.line(&UNICODE, 80).starts_with("you answered ζ = 643"));
    a.revealed = true;
    assert_eq!(
        a.line(&UNICODE, 80),
        "the model: ζ = 321.5 · you: 643 · 2× high · Enter dismisses"
    );
    assert_eq!(
        a.line(&UNICODE, 50),
        "the model: ζ = 321.5 · you: 643 · 2× high"
    );
    a.answer = None;
    assert_eq!(
        a.line(&ASCII, 80),
        "the model: ζ = 321.5 - you did not answer - Enter dismisses"
    );
}

#[test]
fn the_tally_says_its_count_then_the_truth() {
    let mut t = Tally {
        question: q(Axis::Zeta, Ask::ShareEver, 321.5),
        answers: vec![100.0, NOWHERE, 400.0],
        asked: 5,
        revealed: false,
        sweep: crate::presets::load("fig2").unwrap().sweep,
    };
    assert_eq!(t.count(&UNICODE), "3/5 answered");
    t.revealed = true;
    assert_eq!(t.count(&UNICODE), "ζ = 321.5 · 3 answers (1 nowhere)");
    t.answers.truncate(1);
    assert_eq!(t.count(&ASCII), "ζ = 321.5 - 1 answer");
}

#[test]
fn the_claims_row_gives_way_to_the_poll_then_to_a_lessons_question() {
    let mut c = Classroom::default();
    assert_eq!(c.claims_row(), ClaimsRow::Claims);
    assert!(!c.caption_waits());
    // A lesson's step about to poll: its question, and no answer.
    let lesson = crate::class::lesson::read(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/lessons/paper.ron"
    )))
    .unwrap();
    let polled = lesson.steps.iter().position(|s| s.poll.is_some()).unwrap();
    c.step = Some(LessonAt::new(std::sync::Arc::new(lesson.clone()), polled).line());
    let question = lesson.steps[polled].poll.unwrap();
    assert_eq!(c.claims_row(), ClaimsRow::Asks(question));
    // The step before it hides its claims until that poll's reveal.
    c.step = Some(LessonAt::new(std::sync::Arc::new(lesson), polled - 1).line());
    assert_eq!(c.claims_row(), ClaimsRow::Waiting);
    c.step_revealed();
    assert_eq!(c.claims_row(), ClaimsRow::Claims);
    // A student's poll stands in for all of them; outside a lesson the
    // caption waits for its reveal.
    c.step = None;
    let asked = Asked {
        question: q(Axis::Zeta, Ask::Share { rising: true }, 321.5),
        answer: None,
        revealed: false,
        changed: false,
    };
    c.asked = Some(asked);
    assert_eq!(c.claims_row(), ClaimsRow::Asked(&asked));
    assert!(c.caption_waits());
}

#[test]
fn the_projector_counts_the_median_and_the_answers_within_ten_percent() {
    let tally = |axis, ask, truth, answers: &[f64]| Tally {
        question: q(axis, ask, truth),
        answers: answers.to_vec(),
        asked: 10,
        revealed: true,
        sweep: rough_model::Sweep::new(axis, 1.0, 1e4).unwrap(),
    };
    let share = Ask::Share { rising: true };
    // ζ (a log axis): 290 and 352 are within 10 % of 321.5, 289 is not.
    let t = tally(
        Axis::Zeta,
        share,
        321.5,
        &[289.0, 290.0, 352.0, 1000.0, 10.0],
    );
    assert_eq!(t.median(), Some(290.0));
    assert_eq!(t.within(), 2);
    // An even count: halfway between the two middle ones on the chart.
    let t = tally(Axis::Zeta, share, 321.5, &[100.0, 400.0, 10.0, 1e4]);
    assert_eq!(t.median(), Some(200.0));
    assert_eq!(t.within(), 0);
    // "Nowhere" answers are counted apart, right when the truth is nowhere.
    let t = tally(
        Axis::Zeta,
        Ask::ShareEver,
        NOWHERE,
        &[NOWHERE, NOWHERE, 50.0],
    );
    assert_eq!((t.median(), t.nowhere(), t.within()), (Some(50.0), 2, 2));
    let t = tally(Axis::Zeta, Ask::ShareEver, 30.0, &[NOWHERE]);
    assert_eq!((t.median(), t.within()), (None, 0));
    assert_eq!(tally(Axis::Zeta, share, 1.0, &[]).median(), None);
}
