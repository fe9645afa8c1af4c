//! The lessons' unit tests.

use super::*;
use crate::class::Ask;

fn parse_here(text: &str) -> anyhow::Result<Lesson> {
    parse(text, Path::new("lessons/test.ron"))
}

#[test]
fn a_lesson_reads_its_steps_views_and_polls() {
    let l = parse_here(
        r#"(title: "t", steps: [
            (title: "one", scene: Preset("fig1")),
            (title: "two", scene: Preset("fig2"), view: "indices", poll: Claim,
             caption: "mine"),
            (title: "three", scene: Preset("fig2"), poll: Value(100.0)),
        ])"#,
    )
    .unwrap();
    assert_eq!(l.stem, "test");
    assert_eq!(l.steps.len(), 3);
    assert_eq!(l.steps[0].view, View::Slopes);
    assert_eq!(l.steps[0].poll, None);
    let q = l.steps[1].poll.unwrap();
    assert_eq!(q.text(&crate::class::UNICODE), "where does Ψ_P reach 1?");
    assert_eq!(l.steps[1].state.caption.as_deref(), Some("mine"));
    assert_eq!(l.steps[2].poll.unwrap().truth, 100.0);
    let at = LessonAt::new(Arc::new(l), 1);
    assert_eq!(at.line().text(), "step 2/3 · two");
}

#[test]
fn hidden_claims_wait_for_the_lessons_next_poll() {
    let l = parse_here(
        r#"(title: "t", steps: [
            (title: "one", scene: Preset("fig1"), claims: Hidden),
            (title: "two", scene: Preset("fig1"), poll: Claim, claims: Hidden),
            (title: "three", scene: Preset("fig2")),
            (title: "four", scene: Preset("fig2"), claims: Hidden),
        ])"#,
    )
    .unwrap();
    let mut at = LessonAt::new(Arc::new(l), 0);
    let hides = |at: &mut LessonAt, i: usize| {
        at.at = i;
        at.line().hides_claims()
    };
    assert!(hides(&mut at, 0) && hides(&mut at, 1));
    assert!(!hides(&mut at, 2));
    // Step two's poll revealed: one's and two's claims show (two's
    // question is asked again if the lecturer comes back to it).
    at.at = 1;
    at.mark_revealed();
    assert!(!hides(&mut at, 0));
    at.at = 1;
    assert!(!at.line().claims_hidden && at.line().pending.is_some());
    // No poll after step four: its claims wait for good.
    assert!(hides(&mut at, 3));
}

#[test]
fn bad_lessons_say_where_and_what() {
    let err = |t: &str| format!("{:#}", parse_here(t).unwrap_err());
    let e = err(r#"(title: "t", steps: [(title: "a", scene: Preset("fig9"))])"#);
    assert!(
        e.starts_with("the lesson lessons/test.ron, step 1: "),
        "{e}"
    );
    assert!(e.contains("fig9"), "{e}");
    let e = err(r#"(title: "t", steps: [(title: "a", scene: Preset("fig1"), view: "pie")])"#);
    assert!(
        e.contains("view \"pie\" is not one of slopes, indices"),
        "{e}"
    );
    let e = err(r#"(title: "t", steps: [(title: "a", scene: Preset("fig2"), poll: Value(1e9))])"#);
    assert!(e.contains("outside the sweep"), "{e}");
    let e = err(r#"(title: "t", steps: [])"#);
    assert_eq!(e, "the lesson lessons/test.ron has no steps");
    let e = err("(title: \"t\",\n steps: [(titel: \"a\")])");
    assert!(
        e.starts_with("the lesson lessons/test.ron, line 2 column"),
        "{e}"
    );
    assert!(e.contains("titel"), "{e}");
    let e = err(r#"(title: "t", steps: [(title: "a", scene: Snapshot("none.ron"))])"#);
    assert!(e.contains("step 1") && e.contains("none.ron"), "{e}");
}

#[test]
fn the_shipped_lesson_walks_the_paper_with_three_polls() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/paper.ron");
    let l = read(&path).unwrap();
    assert!((6..=8).contains(&l.steps.len()), "{}", l.steps.len());
    let polls: Vec<&Step> = l.steps.iter().filter(|s| s.poll.is_some()).collect();
    assert_eq!(polls.len(), 3);
    // From fig1 to fig4, in the paper's order.
    let names: Vec<&str> = l.steps.iter().map(|s| s.state.name.as_str()).collect();
    assert_eq!(names.first(), Some(&"fig1"));
    assert_eq!(names.last(), Some(&"fig4"));
    // Step 1 keeps the paper's qualifier and hides the claims that
    // would answer step 2's poll.
    let one = &l.steps[0];
    let cap = one.state.caption.as_deref().unwrap();
    assert!(
        cap.contains("only because the surface is very smooth and the magnification is quite low"),
        "{cap}"
    );
    assert!(one.claims_hidden && l.steps[1].poll.is_some());
    // fig3's poll asks what the paper asks: is there plastic area at
    // all? Nowhere: the plastic area is zero over the whole range.
    let fig3 = polls.iter().find(|s| s.state.name == "fig3").unwrap();
    let q = fig3.poll.unwrap();
    assert_eq!((q.ask, q.truth), (Ask::ShareEver, crate::class::NOWHERE));
    let message = l
        .steps
        .iter()
        .find(|s| s.title.contains("message"))
        .unwrap();
    assert!(message
        .state
        .caption
        .as_deref()
        .unwrap()
        .contains("the plastic area is zero over the whole range"));
}
