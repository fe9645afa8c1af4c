//! The class's unit tests: the roster and the poll. (A lecturer's
//! explorer makes the scene a poll is asked on.)

use super::*;
use crate::class::{Arrival, Ask, Question, Shown, Transport, UNICODE};
use rough_model::Axis;

fn shown() -> Shown {
    let app = crate::tui::app::App::new(
        crate::presets::load("fig2").unwrap(),
        crate::tui::theme::Theme::plain(),
        (80, 24),
    );
    app.shown()
}

fn question() -> Question {
    Question {
        axis: Axis::Zeta,
        ask: Ask::Share { rising: true },
        truth: 321.5,
        size_effect: false,
        read: false,
    }
}

const HOME: IpAddr = IpAddr::V4(std::net::Ipv4Addr::LOCALHOST);

/// The CSV with each answer's time (checked for its form) as `T`.
fn untimed(csv: &str) -> String {
    let mut out = String::new();
    for line in csv.lines() {
        // The time is the third field from the end (then poll, revealed).
        let f: Vec<&str> = line.rsplitn(4, ',').collect();
        let (tail, time, rest) = (format!("{},{}", f[1], f[0]), f[2], f[3]);
        if time.is_empty() || time == "time" {
            out.push_str(line);
        } else {
            assert_eq!((time.len(), &time[10..11], &time[19..]), (20, "T", "Z"));
            out.push_str(&format!("{rest},T,{tail}"));
        }
        out.push('\n');
    }
    out
}

#[test]
fn two_students_of_one_name_get_distinct_names() {
    let class = Class::default();
    let a = class.join("ada", HOME, (80, 24), "braille", true);
    let b = class.join("ada", HOME, (80, 24), "braille", true);
    let c = class.join("ada", HOME, (80, 24), "braille", true);
    assert_eq!(class.name(a).unwrap(), "ada");
    assert_eq!(class.name(b).unwrap(), "ada-2");
    assert_eq!(class.name(c).unwrap(), "ada-3");
    // A long name keeps its number within NAME_CHARS.
    let long = "b".repeat(NAME_CHARS);
    class.join(&long, HOME, (80, 24), "braille", true);
    let d = class.join(&long, HOME, (80, 24), "braille", true);
    let n = class.name(d).unwrap();
    assert!(n.ends_with("-2") && n.chars().count() == NAME_CHARS, "{n}");
    // One who answered and left keeps the name in the poll's rows; an
    // ada from elsewhere does not take it.
    let id = class.open(question(), shown());
    class.answer(b, id, 100.0).unwrap();
    class.leave(b, 1);
    let away: IpAddr = "10.0.0.9".parse().unwrap();
    let e = class.join("ada", away, (80, 24), "braille", true);
    assert_eq!(class.name(e).unwrap(), "ada-4");
    assert!(class.reveal(false));
    let names: Vec<String> = (class.csv().unwrap().lines().skip(1))
        .map(|l| l.split(',').nth(4).unwrap().to_string())
        .collect();
    let mut sorted = names.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(sorted.len(), names.len(), "{names:?}");
}

#[test]
fn names_are_escaped_and_cut() {
    assert_eq!(clean_name("alice"), "alice");
    assert_eq!(clean_name(""), "(no name)");
    assert_eq!(clean_name("a\x1b[31mb"), "a\\x1b[31mb");
    assert_eq!(clean_name("x\u{202e}y\u{85}"), "x\\u{202e}y\\x85");
    assert_eq!(clean_name("a\\b"), "a\\\\b");
    let long = clean_name(&"é".repeat(10_000));
    assert_eq!(long.chars().count(), NAME_CHARS);
    assert!(long.ends_with("é…"), "{long}");
    let ctl = clean_name(&"\x07".repeat(100));
    assert_eq!(ctl.chars().count(), NAME_CHARS);
    assert!(ctl.starts_with("\\x07\\x07"), "{ctl}");
    assert!(!ctl.chars().any(char::is_control));
    assert_eq!(clean_name(&"b".repeat(32)), "b".repeat(32));
}

#[test]
fn the_roster_counts_and_wakes_only_the_lecturer() {
    let class = Class::default();
    let mut roster = class.watch_roster();
    let mut poll = class.watch_poll();
    let a = class.join("alice", HOME, (100, 30), "braille", true);
    let b = class.join("bob", HOME, (60, 20), "ascii", true);
    assert!(roster.has_changed().unwrap());
    roster.mark_unchanged();
    class.note(a, Note::Key);
    assert!(!roster.has_changed().unwrap(), "a key woke the lecturer");
    class.note(b, Note::Following(false));
    class.note(b, Note::Size(80, 24));
    assert!(roster.has_changed().unwrap());
    assert!(
        !poll.has_changed().unwrap(),
        "a roster change woke students"
    );
    let v = class.view();
    assert_eq!(
        v.line(&UNICODE),
        "2 students · 1 following · 1 on their own"
    );
    assert_eq!(v.seats[1].marker, "ascii");
    assert_eq!(
        class.summary().unwrap(),
        "class: 2 students, 1 following, 1 on their own"
    );
    class.leave(a, 1);
    class.leave(b, 1);
    assert_eq!(class.summary(), None);
    poll.mark_unchanged();
}

#[test]
fn a_poll_is_answered_revealed_and_refuses_late_answers() {
    let class = Class::default();
    let a = class.join("alice", HOME, (100, 30), "braille", true);
    let b = class.join("b,\"ob\"", HOME, (100, 30), "braille", true);
    let c = class.join("carol", HOME, (100, 30), "braille", true);
    let mut poll = class.watch_poll();
    assert_eq!(class.answer(a, 1, 100.0), Err(Refused::NoPoll));
    let id = class.open(question(), shown());
    assert!(poll.has_changed().unwrap());
    assert!(!poll.borrow_and_update().as_ref().unwrap().revealed);
    class.answer(a, id, 100.0).unwrap();
    class.answer(b, id, 1000.0).unwrap();
    // A second Enter replaces the first answer.
    class.answer(a, id, 200.0).unwrap();
    assert!(!poll.has_changed().unwrap(), "an answer woke students");
    let v = class.view();
    assert_eq!(v.line(&UNICODE), "3 students · 2/3 answered");
    assert_eq!(v.seats[2].state, SeatState::Answering);
    assert_eq!(v.seats[0].state, SeatState::Answered);
    // Bob leaves: his answer stays and still counts.
    class.leave(b, 1);
    assert_eq!(class.view().line(&UNICODE), "2 students · 2/3 answered");
    assert!(class.reveal(false));
    assert!(!class.reveal(false));
    assert!(poll.borrow_and_update().as_ref().unwrap().revealed);
    let state = |v: ClassView| {
        (
            v.poll,
            v.seats.into_iter().map(|s| s.state).collect::<Vec<_>>(),
        )
    };
    let before = (state(class.view()), class.csv());
    let mut roster = class.watch_roster();
    roster.mark_unchanged();
    assert_eq!(class.answer(c, id, 5.0), Err(Refused::Closed));
    assert_eq!(class.answer(a, id, 5.0), Err(Refused::Closed));
    // What the student reads in their status line.
    assert_eq!(
        Refused::Closed.text(),
        "too late: the answers were already revealed"
    );
    // An answer to a poll that is gone is refused the same way.
    assert_eq!(class.answer(a, id + 1, 5.0), Err(Refused::Closed));
    assert_eq!(
        (state(class.view()), class.csv()),
        before,
        "a late answer changed the class"
    );
    assert!(
        !roster.has_changed().unwrap(),
        "a late answer woke the lecturer"
    );
    assert_eq!(
        untimed(&class.csv().unwrap()),
        "question,quantity,unit,truth,name,answer,offset,step,time,poll,revealed\n\
         where does the plastic share pass 1/2?,zeta,,321.5,alice,200,-121.5,,T,1,yes\n\
         where does the plastic share pass 1/2?,zeta,,321.5,\"b,\"\"ob\"\"\",1000,678.5,,T,1,yes\n\
         where does the plastic share pass 1/2?,zeta,,321.5,carol,no answer,,,,1,yes\n"
    );
    assert_eq!(
        class.view().line(&UNICODE),
        "2 students · 2 following · 0 on their own · revealed ζ = 321.5 (2 answers)"
    );
    // A revealed poll is not cancelled: it stays for S.
    assert!(!class.cancel());
    assert!(class.csv().is_some());
    // An answer to an older poll is refused once another opened; the
    // new poll replaces the last one's answers.
    let id2 = class.open(question(), shown());
    assert_eq!(class.answer(c, id, 5.0), Err(Refused::Closed));
    class.answer(c, id2, 5.0).unwrap();
    // While open, everyone here without an answer is a no-answer row.
    assert_eq!(
        untimed(&class.csv().unwrap())
            .lines()
            .skip(1)
            .collect::<Vec<_>>(),
        [
            "where does the plastic share pass 1/2?,zeta,,321.5,carol,5,-316.5,,T,2,no",
            "where does the plastic share pass 1/2?,zeta,,321.5,alice,no answer,,,,2,no"
        ]
    );
    assert!(class.cancel());
    assert_eq!(class.poll(), None);
    assert_eq!(class.csv(), None);
    assert_eq!(class.answer(c, id2, 5.0), Err(Refused::NoPoll));
    assert_eq!((class.polls(), class.seen()), (2, 3));
}

fn arrival<'a>(name: &'a str, via: Transport, token: Option<&'a str>) -> Arrival<'a> {
    Arrival {
        name,
        addr: HOME,
        size: (80, 24),
        marker: "braille",
        following: true,
        via,
        token,
    }
}

#[test]
fn a_seat_is_taken_again_by_its_token_or_over_ssh_by_name_and_address() {
    let class = Class::default();
    let pia = class.take_seat(&arrival("pia", Transport::Phone, None));
    let bob = class.take_seat(&arrival("bob", Transport::Web, None));
    assert_eq!((pia.turn, pia.again, pia.token.len()), (1, false, 32));
    assert_ne!(pia.token, bob.token);
    let poll = class.open(question(), shown());
    class.answer(pia.id, poll, 200.0).unwrap();
    // A reload: the same seat, its next turn; the old session's leave
    // (it ends after) changes nothing.
    let again = class.take_seat(&arrival("pia", Transport::Phone, Some(&pia.token)));
    assert_eq!((again.id, again.turn, again.again), (pia.id, 2, true));
    assert_eq!(again.name, "pia");
    assert_eq!(class.turn(pia.id), Some(2));
    class.leave(pia.id, 1);
    assert_eq!(class.students(), 2);
    // Away: out of the list, the seat and the answer kept; one CSV row.
    class.leave(pia.id, 2);
    let v = class.view();
    assert_eq!(v.seats.len(), 1);
    assert_eq!(v.poll.as_ref().unwrap().asked, 2, "bob, and pia's answer");
    let back = class.take_seat(&arrival("pia", Transport::Web, Some(&pia.token)));
    assert_eq!((back.id, back.turn), (pia.id, 3));
    let v = class.view();
    assert_eq!(v.seats[0].name, "pia");
    assert_eq!(v.seats[0].via, "web");
    assert!(class.reveal(false));
    let csv = class.csv().unwrap();
    assert_eq!(csv.matches(",pia,").count(), 1, "{csv}");
    // A token of no seat takes a new one; over the web no name does.
    let stranger = class.take_seat(&arrival("pia", Transport::Web, Some("00ff")));
    assert_eq!((stranger.again, stranger.name.as_str()), (false, "pia-2"));
    // Over SSH, the same name from the same address takes the seat left.
    let ssh = class.join("sam", HOME, (80, 24), "braille", true);
    class.leave(ssh, 1);
    assert_eq!(class.join("sam", HOME, (80, 24), "braille", true), ssh);
    // A student the lecturer removed keeps no seat: the token is void.
    class.remove(bob.id);
    class.leave(bob.id, 1);
    let bob2 = class.take_seat(&arrival("bob", Transport::Web, Some(&bob.token)));
    assert!(!bob2.again && bob2.id != bob.id);
    // Students who came: seats, not sessions.
    assert_eq!(class.seen(), 5);
}
