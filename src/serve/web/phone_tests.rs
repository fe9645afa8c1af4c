//! The phone's page hides a poll's answer as the terminal does: over the
//! shipped lesson's three polls and the steps that hide their claims,
//! every view's picture and texts, before the reveal and after.

use std::path::Path;
use std::sync::Arc;

use super::*;
use crate::class::{Asked, Lesson, LessonAt};
use crate::tui::app::{update, App};
use crate::tui::theme::Theme;

fn lesson() -> Arc<Lesson> {
    Arc::new(crate::class::lesson::read(Path::new("lessons/paper.ron")).unwrap())
}

/// A phone student's explorer at step `at`, its poll open if it has one.
fn at_step(lesson: &Arc<Lesson>, at: usize) -> App {
    let step = &lesson.steps[at];
    let mut app = App::new(step.state.clone(), Theme::colored(), (80, 24));
    app.view = step.view;
    app.student = true;
    app.lecturer_keys = true;
    app.class.step = Some(LessonAt::new(Arc::clone(lesson), at).line());
    app.class.asked = step.poll.map(|question| Asked {
        question,
        answer: None,
        revealed: false,
        changed: false,
    });
    update(&mut app, Message::Tick);
    app
}

/// The page's text and picture for `app` as a phone upright shows it.
fn page(app: &App) -> (String, String) {
    let mut out = Out::default();
    let p = picture(app, &mut out);
    let j = json(app, Follow::Answering, &p.legend).text();
    (j, p.svg.clone())
}

/// The numbers the scene's claims print ("0.008318", "321.5").
fn claim_numbers(app: &App) -> Vec<String> {
    let mut out = Vec::new();
    for c in crate::figure::claims(&app.state) {
        for t in [c.text(), c.short_text()] {
            let after = t.split(" at ").nth(1).unwrap_or("");
            for tok in after.split(|c: char| c.is_whitespace() || "()".contains(c)) {
                if tok.len() >= 3 && tok.parse::<f64>().is_ok() {
                    out.push(tok.to_string());
                }
            }
        }
    }
    out
}

/// The picture's words: its text elements' lines (SVG's coordinates
/// are numbers too).
fn svg_text(svg: &str) -> String {
    svg.lines()
        .filter(|l| !l.starts_with('<'))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Whether the picture strokes a curve in `colour`.
fn draws(svg: &str, colour: &str) -> bool {
    svg.lines()
        .any(|l| l.starts_with("<polyline") && l.contains(&format!("stroke=\"{colour}\"")))
}

const PLASTIC: &str = "#0000FF";
const RED: &str = "#FF0000";

#[test]
fn nothing_on_a_phone_answers_a_poll_before_its_reveal() {
    let lesson = lesson();
    // Steps 1–5: the three polls (2, 3, 5) and the steps that hide their
    // claims before them (1, 4).
    for at in 0..5 {
        let mut app = at_step(&lesson, at);
        for view in [View::Slopes, View::Indices, View::Map, View::Load] {
            app.view = view;
            update(&mut app, Message::Tick);
            let what = format!("step {} {view:?}", at + 1);
            let (j, svg) = page(&app);
            let words = svg_text(&svg);
            for n in claim_numbers(&app) {
                assert!(
                    !j.contains(&n) && !words.contains(&n),
                    "{what}: {n}\n{j}\n{words}"
                );
            }
            for remark in [" here", "below the chart", "plastic <"] {
                assert!(
                    !j.contains(remark) && !words.contains(remark),
                    "{what}: {remark}"
                );
            }
            assert!(
                j.contains(r#"["plastic share","?"]"#),
                "{what}: the readout\n{j}"
            );
            match (at, view) {
                // The reading question keeps its chart.
                (0 | 1, View::Slopes) => assert!(draws(&svg, PLASTIC), "{what}"),
                // Fig. 2's and fig. 3's predictions: no plastic or total
                // slope, no Ψ_P (fig. 2) or Ψ* (fig. 3, and step 4 before it).
                (2 | 4, View::Slopes) => {
                    assert!(!draws(&svg, PLASTIC) && !draws(&svg, RED), "{what}");
                    assert!(j.contains("plastic: after the reveal"), "{what}\n{j}");
                }
                (2, View::Indices) => {
                    assert!(!draws(&svg, PLASTIC) && draws(&svg, RED), "{what}");
                }
                (3 | 4, View::Indices) => {
                    assert!(draws(&svg, PLASTIC) && !draws(&svg, RED), "{what}");
                    assert!(j.contains("Ψ*: after the reveal"), "{what}\n{j}");
                }
                (_, View::Map) => assert!(svg.contains("contour"), "{what}"),
                (_, View::Load) => assert!(svg.contains("wait for the reveal"), "{what}"),
                _ => {}
            }
        }
    }
}

#[test]
fn after_the_reveal_the_phone_shows_the_answer() {
    let lesson = lesson();
    let mut app = at_step(&lesson, 2);
    if let Some(a) = app.class.asked.as_mut() {
        a.answer = Some(300.0);
        a.revealed = true;
    }
    if let Some(s) = app.class.step.as_mut() {
        s.pending = None;
    }
    update(&mut app, Message::Tick);
    let (j, svg) = page(&app);
    assert!(draws(&svg, PLASTIC) && draws(&svg, RED));
    assert!(j.contains(r#""truth":"the model: ζ = 321.5""#), "{j}");
    assert!(j.contains(r#""off":"6.7 % low""#), "{j}");
    assert!(j.contains(r#""answer":"ζ = 300""#), "{j}");
}
