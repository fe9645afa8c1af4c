//! The phone's renderer: the same session as a terminal's (its explorer,
//! its seat, its poll), drawn not as cells but as what a phone's page
//! shows — the view as a picture made by the export's SVG code
//! ([`crate::figure::render_phone`], the lecturer's scene while
//! following, less what a waiting poll keeps back) and, as JSON, the
//! texts and choices around it: the scene, the lesson's step, the
//! caption, the claims or the question, the poll's answer and reveal,
//! the answers' histogram, the status, the view and the slider.
//!
//! One text message per change: the JSON on its first line, then the
//! picture's SVG when it changed since the last message. Followers of one
//! scene at one shape share one message ([`Pictures`]), as terminals of
//! one size share frames.
//!
//! The page's buttons send the keys a terminal would (← → ⇧← ⇧→ ↑ ↓ Tab,
//! Enter, `0`, `f`); a phone takes only those ([`takes`]). Its text
//! commands choose a view, a slider or the picture's shape ([`command`]).

use std::sync::{Arc, Mutex};

use rough_model::Axis;

use super::json::Json;
use crate::class::{fmt_value, ClaimsRow, Tally, NOWHERE, UNICODE};
use crate::figure::{phone_note, render_phone, FigureOptions, Picture, View, Withheld};
use crate::physical::print::{fmt_param, fmt_short};
use crate::serve::follow::{Follow, Scene};
use crate::serve::seat::Seat;
use crate::tui::app::{App, Look, Message};

/// Points along a phone picture's curves (its plot is about 380 px wide).
const POINTS: usize = 120;

/// Bars of a phone's histogram of the answers, across the sweep.
pub const BINS: usize = 24;

/// What one phone was last sent, and the shape it asked for.
#[derive(Debug)]
pub struct Out {
    pub shape: (u32, u32),
    /// The picture it shows.
    shown: Option<Arc<Picture>>,
    /// What that picture was drawn from (an own scene's: its own draw).
    drawn: Option<Inputs>,
}

impl Default for Out {
    fn default() -> Out {
        Out {
            shape: crate::figure::UPRIGHT,
            shown: None,
            drawn: None,
        }
    }
}

/// What a picture is drawn from.
#[derive(Clone, Debug, PartialEq)]
struct Inputs {
    view: View,
    state: crate::scene::State,
    map_y: Option<Axis>,
    withheld: Withheld,
    shape: (u32, u32),
    /// The contact view's solution as it stands (drawn while it runs).
    contact: Option<String>,
}

/// A phone's message: its JSON and its picture (made once, counted as
/// made; the JSON of a page taken from another phone's is counted taken).
#[derive(Debug)]
struct Page {
    json: String,
    picture: Arc<Picture>,
}

/// What followers of one scene share: the look of their page.
#[derive(Clone, Debug, PartialEq)]
struct Key {
    scene: Scene,
    look: Look,
    follow: Follow,
    shape: (u32, u32),
}

/// Messages kept for followers to share.
const KEEP: usize = 16;

/// The class's phone messages that followers share, and how many were
/// made and taken.
#[derive(Default)]
pub struct Pictures {
    kept: Mutex<Vec<(Key, Arc<Page>)>>,
    made: std::sync::atomic::AtomicU64,
    taken: std::sync::atomic::AtomicU64,
}

impl Pictures {
    fn find(&self, key: &Key) -> Option<Arc<Page>> {
        let kept = self.kept.lock().unwrap_or_else(|p| p.into_inner());
        kept.iter()
            .find(|(k, _)| k == key)
            .map(|(_, m)| Arc::clone(m))
    }

    fn keep(&self, key: Key, m: &Arc<Page>) {
        let mut kept = self.kept.lock().unwrap_or_else(|p| p.into_inner());
        if kept.len() >= KEEP {
            kept.remove(0);
        }
        kept.push((key, Arc::clone(m)));
    }

    /// Pictures drawn, and messages taken from another phone's.
    pub fn counts(&self) -> (u64, u64) {
        use std::sync::atomic::Ordering::Relaxed;
        (self.made.load(Relaxed), self.taken.load(Relaxed))
    }
}

/// Whether a phone takes the message its key sends: the buttons' and
/// nothing that would open what a phone cannot show (a prompt, the
/// snapshot's text, another drawing).
pub fn takes(msg: Message) -> bool {
    matches!(
        msg,
        Message::SelectPrev
            | Message::SelectNext
            | Message::Step { .. }
            | Message::NextView
            | Message::PrevView
            | Message::NextMapY
            | Message::Follow
            | Message::Answer
            | Message::AnswerNowhere
            | Message::Quit
    )
}

/// The messages a page's text command stands for, on `app`: `view NAME`
/// (Tab until that view), `slider FIELD` (↓ until that slider), `shape
/// upright|wide` (the picture's shape: none).
pub fn command(app: &App, out: &mut Out, text: &str) -> Vec<Message> {
    let (what, arg) = text.split_once(' ').unwrap_or((text, ""));
    match what {
        "view" => {
            let Some(to) = View::parse(arg).filter(|v| v.exists(app.state.is_measured())) else {
                return vec![];
            };
            let mut v = app.view;
            let mut msgs = vec![];
            while v != to && msgs.len() < View::ALL.len() {
                v = v.next(app.state.is_measured());
                msgs.push(Message::NextView);
            }
            msgs
        }
        "slider" => {
            let Some(k) = Axis::ALL.iter().position(|a| a.field() == arg) else {
                return vec![];
            };
            if !app.state.roughness().is_parameter(Axis::ALL[k]) {
                return vec![];
            }
            let n = Axis::ALL.len();
            let steps = (k + n - app.selected % n) % n;
            vec![Message::SelectNext; steps]
        }
        "shape" => {
            out.shape = match arg {
                "wide" => crate::figure::WIDE,
                _ => crate::figure::UPRIGHT,
            };
            vec![]
        }
        _ => vec![],
    }
}

/// The phone's next message: the JSON, then the picture's SVG if it is
/// not the one the phone shows.
pub(in crate::serve) fn draw(s: &mut Seat, out: &mut Out) -> Vec<u8> {
    let shared = Arc::clone(&s.shared);
    let pictures = &shared.pictures;
    let key = s
        .scene
        .clone()
        .zip(s.ex.app.look())
        .map(|(scene, look)| Key {
            scene,
            look,
            follow: s.follow,
            shape: out.shape,
        });
    let taken = key.as_ref().and_then(|k| pictures.find(k));
    let m = match taken {
        Some(m) => {
            pictures
                .taken
                .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            m
        }
        None => {
            s.sync();
            let picture = picture(&s.ex.app, out);
            pictures
                .made
                .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let m = Arc::new(Page {
                json: json(&s.ex.app, s.follow, &picture.legend).text(),
                picture,
            });
            if let Some(k) = key {
                pictures.keep(k, &m);
            }
            m
        }
    };
    let mut bytes = m.json.clone().into_bytes();
    if !out
        .shown
        .as_ref()
        .is_some_and(|p| Arc::ptr_eq(p, &m.picture))
    {
        bytes.push(b'\n');
        bytes.extend_from_slice(m.picture.svg.as_bytes());
        out.shown = Some(Arc::clone(&m.picture));
    }
    bytes
}

/// The picture of what `app` shows, at the phone's shape: the one shown
/// when nothing it is drawn from changed.
fn picture(app: &App, out: &mut Out) -> Arc<Picture> {
    let withheld = app.class.withheld(app.state.size_effect);
    let inputs = Inputs {
        view: app.view,
        state: app.state.clone(),
        map_y: app.map_y.filter(|a| *a != app.state.sweep.axis()),
        withheld,
        shape: out.shape,
        contact: (app.view == View::Contact).then(|| format!("{:?}", contact_key(app))),
    };
    if let (Some(p), Some(d)) = (&out.shown, &out.drawn) {
        if *d == inputs {
            return Arc::clone(p);
        }
    }
    let opts = FigureOptions {
        points: POINTS,
        map_y: inputs.map_y,
        withheld,
        ..FigureOptions::default()
    };
    let title = format!("{} — {} view", app.state.name, app.view.name());
    let drawn = if app.view == View::Contact {
        contact_picture(app, withheld, out.shape)
    } else {
        render_phone(app.view, &app.state, &opts, out.shape)
            .unwrap_or_else(|e| phone_note(&title, &format!("{e:#}"), out.shape))
    };
    out.drawn = Some(inputs);
    Arc::new(drawn)
}

/// What of the contact view's simulation its picture shows.
fn contact_key(app: &App) -> (usize, crate::contact::Plot, u32, bool, bool, usize) {
    let c = &app.contact;
    (c.load, c.plot, c.seeds, c.table, c.busy(), c.tasks.len())
}

/// The contact view as a phone's picture: the explorer's own picture of
/// it, or a line saying why there is none yet.
fn contact_picture(app: &App, withheld: Withheld, shape: (u32, u32)) -> Picture {
    let title = format!("{} — contact view", app.state.name);
    if withheld.marks {
        return phone_note(
            &title,
            "the simulation and the theory's areas at the marker wait for the reveal: they \
             would answer the poll",
            shape,
        );
    }
    if app.contact.busy() {
        return phone_note(&title, "solving the contact …", shape);
    }
    crate::figure::render_phone_with(shape, || crate::tui::contact::picture(app))
        .unwrap_or_else(|e| phone_note(&title, &format!("{e:#}"), shape))
}

/// The page's texts and choices, as JSON.
fn json(app: &App, follow: Follow, legend: &[crate::figure::LegendEntry]) -> Json {
    let state = &app.state;
    let withheld = app.class.withheld(state.size_effect);
    let step = app.class.step.as_ref().map(|s| s.text());
    let caption = crate::tui::caption::text(app);
    let claims = match app.class.claims_row() {
        ClaimsRow::Claims => {
            let all: Vec<String> = app.claims.iter().map(|c| c.text()).collect();
            (!all.is_empty()).then(|| all.join(" · "))
        }
        ClaimsRow::Asks(q) => Some(format!("this step asks: {}", q.text(&UNICODE))),
        ClaimsRow::Waiting => Some("(this step's claims show after the lesson's next poll)".into()),
        ClaimsRow::Asked(_) | ClaimsRow::Open(_) => None,
    };
    let poll = app.class.asked.map(|a| {
        let q = a.question;
        let answer = a.answer.map(|v| q.value(v));
        let mut fields = vec![
            (
                "question",
                Json::from(format!("Predict: {}", q.text(&UNICODE))),
            ),
            ("answer", Json::from(answer)),
            ("revealed", a.revealed.into()),
            ("nowhere", q.nowhere_ok().into()),
            ("line", a.line(&UNICODE, usize::MAX).into()),
        ];
        if a.revealed {
            let asked = if a.changed { ", as asked" } else { "" };
            fields.push((
                "truth",
                format!("the model{asked}: {}", q.value(q.truth)).into(),
            ));
            fields.push(("off", Json::from(a.answer.map(|v| q.off(v, &UNICODE)))));
        }
        Json::Obj(fields)
    });
    let status = app.status.as_ref().map(|s| {
        Json::Obj(vec![
            ("text", buttons(&s.text).into()),
            ("error", s.error.into()),
        ])
    });
    let axis = app.selected_axis();
    let (lo, hi) = app.range(axis);
    let v = state.params.get(axis);
    let slider = Json::Obj(vec![
        ("field", axis.field().into()),
        ("symbol", axis.symbol().into()),
        ("value", fmt_param(axis, v).trim().to_string().into()),
        ("lo", fmt_short(axis, lo).into()),
        ("hi", fmt_short(axis, hi).into()),
        ("swept", (axis == state.sweep.axis()).into()),
    ]);
    let sliders = Json::Arr(
        Axis::ALL
            .iter()
            .filter(|a| state.roughness().is_parameter(**a))
            .map(|a| Json::Arr(vec![a.field().into(), a.symbol().into()]))
            .collect(),
    );
    let views = Json::Arr(
        View::ALL
            .iter()
            .filter(|v| v.exists(state.is_measured()))
            .map(|v| v.name().into())
            .collect(),
    );
    let follow = match follow {
        Follow::Following => "following",
        Follow::Answering => "answering",
        Follow::Detached => "own",
        Follow::Alone | Follow::Away => "alone",
    };
    Json::Obj(vec![
        ("scene", state.name.clone().into()),
        ("modified", app.modified.into()),
        ("step", step.into()),
        (
            "caption",
            (!caption.is_empty()).then(|| caption.to_string()).into(),
        ),
        ("claims", claims.into()),
        ("poll", poll.into()),
        ("status", status.into()),
        ("follow", follow.into()),
        ("lecturer", (app.lecturer_keys && app.lecturer_here).into()),
        ("view", app.view.name().into()),
        ("views", views),
        ("slider", slider),
        ("sliders", sliders),
        ("readout", readout(app, withheld)),
        (
            "legend",
            Json::Arr(
                legend
                    .iter()
                    .map(|e| {
                        Json::Arr(vec![
                            e.label.clone().into(),
                            e.colour.clone().into(),
                            e.sample.into(),
                        ])
                    })
                    .collect(),
            ),
        ),
        ("histogram", app.class.tally.as_ref().map(histogram).into()),
    ])
}

/// A few values at the marker, `?` while a poll's answer waits.
fn readout(app: &App, withheld: Withheld) -> Json {
    let r = &app.readout;
    let psi = app.state.index_name();
    let hide = |s: String| if withheld.marks { "?".to_string() } else { s };
    let share = r.slopes.plastic_share();
    Json::Arr(vec![
        Json::Arr(vec![
            psi.into(),
            hide(crate::physical::short_number(r.psi)).into(),
        ]),
        Json::Arr(vec![
            "plastic share".into(),
            hide(format!("{:.0} %", share * 100.0)).into(),
        ]),
    ])
}

/// The answers' histogram as the page draws it: [`BINS`] counts across
/// the sweep (log-spaced on a log axis), the truth's bar, the count.
pub fn histogram(t: &Tally) -> Json {
    let sw = &t.sweep;
    let axis = sw.axis();
    let f = |v: f64| if axis.is_log() { v.log10() } else { v };
    let (a, b) = (f(sw.from()), f(sw.to()));
    let bin = |v: f64| -> Option<usize> {
        let x = (f(v) - a) / (b - a);
        (v.is_finite() && (0.0..=1.0).contains(&x))
            .then(|| ((x * BINS as f64) as usize).min(BINS - 1))
    };
    let mut counts = [0usize; BINS];
    for v in &t.answers {
        if let Some(k) = bin(*v) {
            counts[k] += 1;
        }
    }
    let nowhere = t.answers.iter().filter(|v| **v == NOWHERE).count();
    let truth = t.question.truth;
    Json::Obj(vec![
        (
            "counts",
            Json::Arr(counts.iter().map(|c| Json::Num(*c as f64)).collect()),
        ),
        ("truth", bin(truth).map(|k| Json::Num(k as f64)).into()),
        ("nowhere", Json::Num(nowhere as f64)),
        ("count", t.count(&UNICODE).into()),
        ("lo", fmt_value(axis, sw.from()).into()),
        ("hi", fmt_value(axis, sw.to()).into()),
        ("axis", axis.symbol().into()),
    ])
}

/// A status line as a phone says it: its buttons for the keys.
pub fn buttons(text: &str) -> String {
    [
        (
            "←→ move the marker (⇧ fine), Enter answers",
            "move the marker with less and more, then tap answer",
        ),
        (
            "move the marker, then Enter answers",
            "move the marker, then tap answer",
        ),
        ("f to follow", "tap follow to follow"),
        ("Enter dismisses", "OK dismisses"),
        (
            "any change explores on your own",
            "a change explores on your own",
        ),
    ]
    .iter()
    .fold(text.to_string(), |t, (key, button)| t.replace(key, button))
}

#[cfg(test)]
#[path = "phone_tests.rs"]
mod tests;
