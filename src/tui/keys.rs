//! The one key table. It drives the key handling, the help overlay and the
//! footer, so the three cannot disagree.

use std::borrow::Cow;

use crossterm::event::{Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers};

use super::app::{App, Message, Mode};
use super::glyphs::Glyphs;
use super::line_edit::Edit;
use crate::figure::View;

/// Where a binding applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Context {
    /// The explorer itself.
    Main,
    /// The help overlay is open.
    Help,
    /// The explorer and the help overlay.
    MainAndHelp,
    /// A prompt (the save name, a slider's value) is open.
    Prompt,
    /// The explorer of a student in a served class (`roughtui serve`).
    Student,
    /// The explorer of anyone else: it writes files where it runs.
    NotStudent,
    /// A student's explorer in a class with a lecturer to follow.
    Follower,
    /// An explorer whose session has a measured surface to return to.
    Surface,
    /// A student's explorer while a poll waits for their answer.
    Answering,
    /// A student's explorer showing a poll's result (until Enter).
    Revealed,
    /// The lecturer's explorer in a served class.
    Lecturer,
    /// The lecturer's class list is open.
    ClassList,
    /// The explorer showing the contact view.
    ContactView,
    /// An explorer leading a lesson (`--lesson`: the lecturer, or alone to
    /// rehearse).
    Lesson,
    /// The lecturer's scene list is open.
    Scenes,
    /// A student's explorer while a poll that allows "nowhere" waits.
    Nowhere,
    /// The lecturer's explorer when the class is also served on the web.
    Joinable,
    /// The lecturer's projector view is up.
    Projector,
    /// Everywhere: the explorer, the help, a prompt, a terminal too small.
    Any,
}

impl Context {
    fn covers(self, app: &App) -> bool {
        if app.class.scenes.is_some() && app.mode == Mode::Main {
            return matches!(self, Context::Scenes | Context::Any);
        }
        matches!(
            (self, &app.mode),
            (Context::Main | Context::MainAndHelp, Mode::Main)
                | (Context::Help | Context::MainAndHelp, Mode::Help)
                | (
                    Context::Prompt,
                    Mode::Prompt(_) | Mode::Value(..) | Mode::Truth(..)
                )
                | (Context::ClassList, Mode::Class)
                | (Context::Any, _)
        ) || (app.mode == Mode::Main && self.listed(app) && self.is_role())
            || (self == Context::Projector && app.mode == Mode::Main && app.class.projector)
            || (self == Context::ContactView
                && app.mode == Mode::Main
                && app.view == crate::figure::View::Contact)
            || (self == Context::Answering
                && app.mode == Mode::Main
                && app.class.asked.is_some_and(|a| !a.revealed))
            || (self == Context::Revealed
                && app.mode == Mode::Main
                && app.class.asked.is_some_and(|a| a.revealed))
            || (self == Context::Nowhere
                && app.mode == Mode::Main
                && app
                    .class
                    .asked
                    .is_some_and(|a| !a.revealed && a.question.nowhere_ok()))
    }

    fn is_role(self) -> bool {
        matches!(
            self,
            Context::Student
                | Context::NotStudent
                | Context::Follower
                | Context::Surface
                | Context::Lecturer
                | Context::Joinable
                | Context::Lesson
        )
    }

    /// Whether the help overlay of `app` lists bindings of this context.
    pub fn listed(self, app: &App) -> bool {
        match self {
            Context::Student => app.student,
            Context::NotStudent => !app.student,
            Context::Surface => app.home.is_some(),
            Context::Follower | Context::Answering | Context::Revealed => {
                app.student && app.lecturer_keys
            }
            Context::Lecturer => app.class.view.is_some(),
            Context::Joinable => app.class.view.is_some() && app.class.join_url.is_some(),
            Context::Nowhere => app.student && app.lecturer_keys,
            // The contact view's keys, in its help only.
            Context::ContactView => app.view == crate::figure::View::Contact,
            Context::Lesson => app.class.lesson.is_some(),
            Context::Projector => app.class.projector,
            // The class list's and the scene list's titles name their keys.
            Context::ClassList | Context::Scenes => false,
            _ => true,
        }
    }
}

/// One key combination.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Key {
    pub code: KeyCode,
    pub mods: KeyModifiers,
}

const fn key(code: KeyCode) -> Key {
    Key {
        code,
        mods: KeyModifiers::NONE,
    }
}

const fn shift(code: KeyCode) -> Key {
    Key {
        code,
        mods: KeyModifiers::SHIFT,
    }
}

const fn ctrl(c: char) -> Key {
    Key {
        code: KeyCode::Char(c),
        mods: KeyModifiers::CONTROL,
    }
}

const fn ch(c: char) -> Key {
    key(KeyCode::Char(c))
}

impl Key {
    /// Letters carry their case in the character, so Shift is ignored for
    /// them (terminals differ in reporting it); for other keys it counts.
    fn matches(&self, ev: &KeyEvent) -> bool {
        if self.code != ev.code {
            return false;
        }
        match ev.code {
            KeyCode::Char(_) => {
                let strip = |m: KeyModifiers| m - KeyModifiers::SHIFT;
                strip(self.mods) == strip(ev.modifiers)
            }
            _ => self.mods == ev.modifiers,
        }
    }
}

/// A row of the table: the keys, what they send, and how help and footer
/// describe them.
#[derive(Clone, Copy, Debug)]
pub struct Binding {
    pub context: Context,
    pub keys: &'static [(Key, Message)],
    /// The keys as the help overlay shows them.
    pub label: &'static str,
    pub help: &'static str,
    /// A short form for the footer; `None` keeps it out of the footer.
    pub footer: Option<&'static str>,
}

use Context::{
    Answering, Any, ClassList, ContactView, Follower, Help, Joinable, Lecturer, Lesson, Main,
    MainAndHelp, NotStudent, Nowhere, Projector, Prompt, Revealed, Scenes, Student, Surface,
};
use KeyCode::{
    BackTab, Backspace, Delete, Down, End, Enter, Esc, Home, Left, PageDown, PageUp, Right, Tab, Up,
};
use Message as M;

const fn edit(e: Edit) -> Message {
    M::PromptEdit(e)
}

const fn bind(
    context: Context,
    keys: &'static [(Key, Message)],
    label: &'static str,
    help: &'static str,
    footer: Option<&'static str>,
) -> Binding {
    Binding {
        context,
        keys,
        label,
        help,
        footer,
    }
}

const DOWN: Message = M::Step {
    up: false,
    fine: false,
};
const UP: Message = M::Step {
    up: true,
    fine: false,
};
const FINE_DOWN: Message = M::Step {
    up: false,
    fine: true,
};
const FINE_UP: Message = M::Step {
    up: true,
    fine: true,
};

#[rustfmt::skip]
pub const BINDINGS: &[Binding] = &[
    bind(Answering, &[(key(Enter), M::Answer)], "Enter", "in a poll: answer with the marker's value", Some("⏎ answer")),
    bind(Nowhere, &[(ch('0'), M::AnswerNowhere)], "0", "in a poll that allows it: answer \"nowhere in the sweep\"", Some("0 nowhere")),
    bind(Revealed, &[(key(Enter), M::Answer)], "Enter", "after the reveal: dismiss the result", Some("⏎ dismiss")),
    bind(Follower, &[(ch('f'), M::Follow)], "f", "follow the lecturer again", Some("f follow")),
    bind(Lecturer, &[(ch('v'), M::Poll)], "v", "poll: the class predicts; v again reveals", Some("v V poll")),
    bind(Lecturer, &[(ch('V'), M::PollTyped)], "V", "poll on a value you type", None),
    bind(Lecturer, &[(ch('w'), M::ToggleClass)], "w", "the class list", Some("w class")),
    bind(Lecturer, &[(ch('C'), M::CancelPoll)], "C", "cancel the open poll (its answers are dropped)", Some("C cancel")),
    bind(Lecturer, &[(ch('o'), M::OpenScenes)], "o", "load a scene for everyone: a preset or a snapshot here", Some("o open")),
    bind(Scenes, &[(key(Up), M::SceneMove { down: false }), (ch('k'), M::SceneMove { down: false }), (key(Down), M::SceneMove { down: true }), (ch('j'), M::SceneMove { down: true })], "↑ ↓  k j", "choose a scene", None),
    bind(Scenes, &[(key(Enter), M::ScenePick)], "Enter", "load it", None),
    bind(Scenes, &[(key(Esc), M::SceneClose), (ch('o'), M::SceneClose)], "Esc  o", "close the list", None),
    bind(Lecturer, &[(ch('F'), M::AllFollow)], "F", "everyone follow: pull every student back to you", Some("F all")),
    bind(Lesson, &[(ch('n'), M::LessonStep { next: true }), (ch('N'), M::LessonStep { next: false })], "n N", "the lesson's next / previous step", Some("n N step")),
    bind(Lecturer, &[(ch('S'), M::SavePoll)], "S", "save the last poll's answers here (.csv)", Some("S csv")),
    bind(Lecturer, &[(ch('d'), M::ShareAnswers)], "d", "after a reveal: show everyone the answers' histogram", None),
    bind(Joinable, &[(ch('Q'), M::ShowJoin)], "Q", "the web page's address and QR code, full screen", None),
    bind(Projector, &[(ch('P'), M::Projector), (key(Esc), M::Projector)], "P  Esc", "close the projector view", None),
    bind(Projector, &[(ch('t'), M::Countdown)], "t", "projector: a countdown for the poll (30 s, 1 min, 2 min, off)", None),
    bind(Lecturer, &[(ch('P'), M::Projector)], "P", "the poll for the projector: answers, truth, median, share within 10 %", None),
    bind(ClassList, &[(ch('w'), M::ToggleClass), (key(Esc), M::ToggleClass)], "w  Esc", "close the class list", None),
    bind(ClassList, &[(key(Down), M::ClassChoose { down: true }), (ch('j'), M::ClassChoose { down: true }), (key(Up), M::ClassChoose { down: false }), (ch('k'), M::ClassChoose { down: false })], "↓ ↑  j k", "choose a student", None),
    bind(ClassList, &[(ch('x'), M::RemoveStudent)], "x", "remove the student chosen (told why)", None),
    bind(ClassList, &[(key(Right), M::HelpPage { next: true }), (key(PageDown), M::HelpPage { next: true }), (ch(' '), M::HelpPage { next: true }), (key(Left), M::HelpPage { next: false }), (key(PageUp), M::HelpPage { next: false })], "→ ←  PgDn PgUp", "next / previous page of the class list", None),
    bind(ClassList, &[(ch('q'), M::Quit), (ctrl('c'), M::Quit)], "q  Ctrl-C", "quit", None),
    bind(Main, &[(key(Up), M::SelectPrev), (ch('k'), M::SelectPrev), (key(Down), M::SelectNext), (ch('j'), M::SelectNext)], "↑ ↓  k j", "select a slider", Some("↑↓ select")),
    bind(Main, &[(key(Left), DOWN), (ch('h'), DOWN), (key(Right), UP), (ch('l'), UP)], "← →  h l", "change it (¼ decade; H: 0.05)", Some("←→ change")),
    bind(Main, &[(shift(Left), FINE_DOWN), (ch('H'), FINE_DOWN), (shift(Right), FINE_UP), (ch('L'), FINE_UP)], "⇧← ⇧→  H L", "fine step (1/40 decade; H: 0.01)", None),
    bind(Main, &[(key(Tab), M::NextView), (shift(BackTab), M::PrevView), (key(BackTab), M::PrevView)], "Tab ⇧Tab", "next / previous view (a surface adds its spectrum)", Some("Tab view")),
    bind(Main, &[(ch('1'), M::LoadPreset(0)), (ch('2'), M::LoadPreset(1)), (ch('3'), M::LoadPreset(2)), (ch('4'), M::LoadPreset(3))], "1 2 3 4", "load the paper's fig1 … fig4", Some("1-4 figs")),
    bind(Surface, &[(ch('5'), M::LoadSurface)], "5", "back to the measured surface", Some("5 surface")),
    bind(Main, &[(key(Enter), M::StartValue)], "Enter", "type its value (25nm, 1e-3; also q0=… l=… e=… h0=…)", None),
    bind(Main, &[(ch('x'), M::CycleSweep)], "x", "sweep the next parameter", Some("x sweep")),
    bind(Main, &[(ch('m'), M::ToggleModel)], "m", "exact / closed-form model", Some("m model")),
    bind(Main, &[(ch('e'), M::ToggleSizeEffect)], "e", "size effect on / off", Some("e size")),
    bind(Main, &[(ch('a'), M::ToggleMoments)], "a", "truncated / asymptotic moments (eq. 10; power law)", Some("a moments")),
    bind(ContactView, &[(ch('['), M::ContactLoad { up: false }), (ch(']'), M::ContactLoad { up: true })], "[ ]", "contact view: lower / higher load p̄/H (¼ decade)", Some("[] load")),
    bind(ContactView, &[(ch('b'), M::ContactSweep)], "b", "contact view: plastic share vs ζ at the load / areas vs load", Some("b vs ζ")),
    bind(ContactView, &[(ch('i'), M::ContactSlopes)], "i", "contact view: initial slopes vs ζ, simulated and theory / areas vs load", Some("i slopes")),
    bind(ContactView, &[(ch('r'), M::ContactSeed)], "r", "contact view: another surface (next seed)", None),
    bind(ContactView, &[(ch('R'), M::ContactSeeds)], "R", "contact view: seeds 4 / 16 / 1 (mean ± sd over the surfaces)", Some("R seeds")),
    bind(ContactView, &[(ch('t'), M::ContactTable)], "t", "contact view: convergence table (grids × cells) / the plot", Some("t converge")),
    bind(ContactView, &[(ch('A'), M::ContactHardness)], "A", "contact view: one hardness cap / each asperity's / each summit's (size effect)", None),
    bind(Main, &[(ch('y'), M::NextMapY)], "y", "the regime map's next y parameter", Some("y map axis")),
    bind(NotStudent, &[(ch('s'), M::StartSave)], "s", "save a snapshot here (.ron)", Some("s save")),
    bind(Student, &[(ch('s'), M::StartSave)], "s", "show the snapshot (.ron) to copy; y there: clipboard", Some("s snapshot")),
    bind(Surface, &[(ch('['), M::MoveFitBand { upper: false, up: false }), (ch(']'), M::MoveFitBand { upper: false, up: true })], "[ ]", "spectrum: the fit band's lower end down / up", None),
    bind(Surface, &[(ch('{'), M::MoveFitBand { upper: true, up: false }), (ch('}'), M::MoveFitBand { upper: true, up: true })], "{ }", "spectrum: the fit band's upper end down / up", None),
    bind(Surface, &[(ch('b'), M::AutoFitBand)], "b", "spectrum: the fit band found from the data", None),
    bind(Main, &[(ch('g'), M::ToggleGhost)], "g", "pin a dim ghost (a surface: its fit first) / clear", Some("g ghost")),
    bind(NotStudent, &[(ch('p'), M::SavePicture)], "p", "save the view as a picture here (.svg)", Some("p picture")),
    bind(Student, &[(ch('p'), M::SavePicture)], "p", "no pictures over SSH: s shows the snapshot", None),
    bind(MainAndHelp, &[(ch('?'), M::ToggleHelp)], "?", "show / hide this help", Some("? help")),
    bind(Help, &[(key(Esc), M::CloseHelp)], "Esc", "close the help", None),
    bind(Help, &[(key(Right), M::HelpPage { next: true }), (key(PageDown), M::HelpPage { next: true }), (ch(' '), M::HelpPage { next: true }), (key(Left), M::HelpPage { next: false }), (key(PageUp), M::HelpPage { next: false })], "→ ←  PgDn PgUp", "next / previous page of the help", None),
    bind(MainAndHelp, &[(ch('M'), M::CycleGlyphs)], "M", "drawing: braille, half blocks, blocks, ASCII", Some("M drawing")),
    bind(MainAndHelp, &[(ch('c'), M::ToggleColor)], "c", "colour off / on (as NO_COLOR=1)", None),
    bind(Any, &[(ctrl('l'), M::Redraw)], "Ctrl-L", "redraw the screen (over SSH: at the terminal's size)", None),
    bind(MainAndHelp, &[(ch('q'), M::Quit), (ctrl('c'), M::Quit)], "q  Ctrl-C", "quit", Some("q quit")),
    bind(Prompt, &[(key(Left), edit(Edit::Left)), (key(Right), edit(Edit::Right)), (key(Home), edit(Edit::Home)), (ctrl('a'), edit(Edit::Home)), (key(End), edit(Edit::End)), (ctrl('e'), edit(Edit::End))], "← → Home End", "move the cursor (also Ctrl-A, Ctrl-E)", Some("←→ move")),
    bind(Prompt, &[(key(Backspace), edit(Edit::Backspace)), (key(Delete), edit(Edit::Delete))], "⌫  Del", "delete before / under the cursor", None),
    bind(Prompt, &[(ctrl('u'), edit(Edit::DeleteToStart))], "Ctrl-U", "delete up to the cursor (all of it at the end)", Some("^U clear")),
    bind(Prompt, &[(ctrl('w'), edit(Edit::DeleteWord))], "Ctrl-W", "delete the word before the cursor", Some("^W word")),
    bind(Prompt, &[(key(Enter), M::PromptAccept)], "Enter", "save under that name / set that value", Some("⏎ accept")),
    bind(Prompt, &[(key(Esc), M::PromptCancel), (ctrl('c'), M::PromptCancel)], "Esc  Ctrl-C", "cancel", Some("Esc cancel")),
];

/// The keys' names where text is drawn in ASCII ([`Glyphs::ascii_text`]):
/// arrows by name, in the footer short.
const ASCII_KEYS: &[(&str, &str)] = &[
    ("↑ ↓  k j", "Up Down  k j"),
    ("← →  h l", "Left Right  h l"),
    ("⇧← ⇧→  H L", "S-Left S-Right  H L"),
    ("Tab ⇧Tab", "Tab S-Tab"),
    ("→ ←  PgDn PgUp", "Right Left  PgDn PgUp"),
    ("← → Home End", "Left Right Home End"),
    ("⌫  Del", "Bksp  Del"),
    ("↑↓ select", "Up/Dn select"),
    ("←→ change", "<-/-> change"),
    ("←→ move", "<-/-> move"),
    ("⏎ accept", "Enter accept"),
];

/// A key's label or footer entry as `glyphs` writes it.
pub fn key_text(glyphs: Glyphs, text: &'static str) -> Cow<'static, str> {
    if !glyphs.ascii_text() {
        return Cow::Borrowed(text);
    }
    match ASCII_KEYS.iter().find(|(u, _)| *u == text) {
        Some((_, a)) => Cow::Borrowed(a),
        None => glyphs.text(text),
    }
}

/// The message a key sends in the app's current mode, if any.
pub fn message_for_key(app: &App, ev: &KeyEvent) -> Option<Message> {
    if ev.kind == KeyEventKind::Release {
        return None;
    }
    // The join page's QR code, full screen: any key closes it.
    if app.class.join_shown {
        return Some(M::ShowJoin);
    }
    // While the terminal is too small nothing is shown: only quitting and
    // redrawing act; on a student's compact screen also following,
    // moving the marker and answering.
    if app.too_small() {
        let compact = super::views::compact::applies(app);
        let moves = |m: &Message| {
            matches!(
                m,
                M::Step { .. }
                    | M::SelectPrev
                    | M::SelectNext
                    | M::Answer
                    | M::AnswerNowhere
                    | M::Follow
            )
        };
        let compact_key = BINDINGS
            .iter()
            .filter(|b| compact && b.context.covers(app))
            .flat_map(|b| b.keys)
            .find(|(k, m)| moves(m) && k.matches(ev));
        return compact_key
            .or_else(|| {
                BINDINGS
                    .iter()
                    .flat_map(|b| b.keys)
                    .find(|(k, m)| matches!(m, M::Quit | M::Redraw) && k.matches(ev))
            })
            .map(|(_, m)| *m);
    }
    // The projector view takes the poll's and the lesson's keys, not the
    // explorer's (which would change a scene nobody sees).
    let projected = app.class.projector && app.mode == Mode::Main;
    let acts = |m: &Message| {
        !projected
            || matches!(
                m,
                M::Projector
                    | M::Countdown
                    | M::Poll
                    | M::PollTyped
                    | M::CancelPoll
                    | M::ShareAnswers
                    | M::SavePoll
                    | M::LessonStep { .. }
                    | M::AllFollow
                    | M::ToggleClass
                    | M::ShowJoin
                    | M::ToggleHelp
                    | M::Redraw
                    | M::Quit
            )
    };
    for b in BINDINGS.iter().filter(|b| b.context.covers(app)) {
        if let Some((_, m)) = b.keys.iter().find(|(k, m)| k.matches(ev) && acts(m)) {
            return Some(*m);
        }
    }
    // A prompt takes any other printable character as text.
    if let (Mode::Prompt(_) | Mode::Value(..) | Mode::Truth(..), KeyCode::Char(c)) =
        (&app.mode, ev.code)
    {
        let plain = ev.modifiers - KeyModifiers::SHIFT;
        if plain.is_empty() && !c.is_control() {
            return Some(edit(Edit::Insert(c)));
        }
    }
    None
}

/// The message a terminal event sends, if any. Events that send nothing
/// (mouse, focus, unbound keys) cause no redraw.
pub fn message_for_event(app: &App, ev: &Event) -> Option<Message> {
    match ev {
        Event::Key(k) => message_for_key(app, k),
        Event::Resize(w, h) => Some(Message::Resize(*w, *h)),
        _ => None,
    }
}

/// The footer for the app's mode in `width` columns: the entries in table
/// order, those that do not fit left out, but help, save, picture, quit and
/// (on a surface) `5` always kept (so 80 columns show them); `g` only on
/// the slopes view, `y` only on the map, where they act, and `f` only while
/// a lecturer is connected.
pub fn footer(app: &App, width: usize) -> String {
    let glyphs = app.theme.glyphs;
    let entries: Vec<(Cow<str>, bool)> = BINDINGS
        .iter()
        .filter(|b| b.context.covers(app))
        .filter(|b| {
            b.keys.iter().all(|(_, m)| match m {
                Message::ToggleGhost => app.view == View::Slopes,
                Message::NextMapY => app.view == View::Map,
                // `f` answers "no lecturer connected" when there is none;
                // the footer offers it only when there is one.
                Message::Follow => app.lecturer_here,
                _ => true,
            })
        })
        .filter_map(|b| {
            let keep = b.keys.iter().any(|(_, m)| {
                matches!(
                    m,
                    Message::ToggleHelp
                        | Message::StartSave
                        | Message::SavePicture
                        | Message::Quit
                        | Message::LoadSurface
                )
            });
            b.footer.map(|f| (key_text(glyphs, f), keep))
        })
        .collect();
    let len = |e: &str| e.chars().count() + 2;
    let mut reserved: usize = entries.iter().filter(|e| e.1).map(|e| len(&e.0)).sum();
    let mut used = 0;
    let mut parts = Vec::new();
    for (entry, keep) in entries {
        if keep {
            reserved -= len(&entry);
        } else if used + len(&entry) + reserved > width + 2 {
            continue;
        }
        used += len(&entry);
        parts.push(entry);
    }
    parts.join("  ")
}
