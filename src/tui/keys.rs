//! The one key table. It drives the key handling, the help overlay and the
//! footer, so the three cannot disagree.

use crossterm::event::{Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers};

use super::app::{App, Message, Mode};
use super::line_edit::Edit;

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
}

impl Context {
    fn covers(self, mode: &Mode) -> bool {
        matches!(
            (self, mode),
            (Context::Main | Context::MainAndHelp, Mode::Main)
                | (Context::Help | Context::MainAndHelp, Mode::Help)
                | (Context::Prompt, Mode::Prompt(_) | Mode::Value(..))
        )
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

use KeyCode::{Backspace, Delete, Down, End, Enter, Esc, Home, Left, PageDown, PageUp, Right, Up};
use Message as M;

const fn edit(e: Edit) -> Message {
    M::PromptEdit(e)
}

pub const BINDINGS: &[Binding] = &[
    Binding {
        context: Context::Main,
        keys: &[
            (key(Up), M::SelectPrev),
            (ch('k'), M::SelectPrev),
            (key(Down), M::SelectNext),
            (ch('j'), M::SelectNext),
        ],
        label: "↑ ↓  k j",
        help: "select a slider",
        footer: Some("↑↓ select"),
    },
    Binding {
        context: Context::Main,
        keys: &[
            (
                key(Left),
                M::Step {
                    up: false,
                    fine: false,
                },
            ),
            (
                ch('h'),
                M::Step {
                    up: false,
                    fine: false,
                },
            ),
            (
                key(Right),
                M::Step {
                    up: true,
                    fine: false,
                },
            ),
            (
                ch('l'),
                M::Step {
                    up: true,
                    fine: false,
                },
            ),
        ],
        label: "← →  h l",
        help: "change it (¼ decade; H: 0.05)",
        footer: Some("←→ change"),
    },
    Binding {
        context: Context::Main,
        keys: &[
            (
                shift(Left),
                M::Step {
                    up: false,
                    fine: true,
                },
            ),
            (
                ch('H'),
                M::Step {
                    up: false,
                    fine: true,
                },
            ),
            (
                shift(Right),
                M::Step {
                    up: true,
                    fine: true,
                },
            ),
            (
                ch('L'),
                M::Step {
                    up: true,
                    fine: true,
                },
            ),
        ],
        label: "⇧← ⇧→  H L",
        help: "fine step (1/40 decade; H: 0.01)",
        footer: Some("⇧ fine"),
    },
    Binding {
        context: Context::Main,
        keys: &[
            (ch('1'), M::LoadPreset(0)),
            (ch('2'), M::LoadPreset(1)),
            (ch('3'), M::LoadPreset(2)),
            (ch('4'), M::LoadPreset(3)),
        ],
        label: "1 2 3 4",
        help: "load the paper's fig1 … fig4",
        footer: Some("1-4 figs"),
    },
    Binding {
        context: Context::Main,
        keys: &[(key(Enter), M::StartValue)],
        label: "Enter",
        help: "type its value (25nm, 2 mm, 1e-3)",
        footer: Some("⏎ type"),
    },
    Binding {
        context: Context::Main,
        keys: &[(ch('x'), M::CycleSweep)],
        label: "x",
        help: "sweep the next parameter",
        footer: Some("x sweep"),
    },
    Binding {
        context: Context::Main,
        keys: &[(ch('m'), M::ToggleModel)],
        label: "m",
        help: "exact / closed-form model",
        footer: Some("m model"),
    },
    Binding {
        context: Context::Main,
        keys: &[(ch('e'), M::ToggleSizeEffect)],
        label: "e",
        help: "size effect on / off",
        footer: Some("e size"),
    },
    Binding {
        context: Context::Main,
        keys: &[(ch('s'), M::StartSave)],
        label: "s",
        help: "save a snapshot here (.ron)",
        footer: Some("s save"),
    },
    Binding {
        context: Context::MainAndHelp,
        keys: &[(ch('?'), M::ToggleHelp)],
        label: "?",
        help: "show / hide this help",
        footer: Some("? help"),
    },
    Binding {
        context: Context::Help,
        keys: &[(key(Esc), M::CloseHelp)],
        label: "Esc",
        help: "close the help",
        footer: None,
    },
    Binding {
        context: Context::Help,
        keys: &[
            (key(Right), M::HelpPage { next: true }),
            (key(PageDown), M::HelpPage { next: true }),
            (ch(' '), M::HelpPage { next: true }),
            (key(Left), M::HelpPage { next: false }),
            (key(PageUp), M::HelpPage { next: false }),
        ],
        label: "→ ←  PgDn PgUp",
        help: "next / previous page of the help",
        footer: None,
    },
    Binding {
        context: Context::MainAndHelp,
        keys: &[(ch('q'), M::Quit), (ctrl('c'), M::Quit)],
        label: "q  Ctrl-C",
        help: "quit",
        footer: Some("q quit"),
    },
    Binding {
        context: Context::Prompt,
        keys: &[
            (key(Left), edit(Edit::Left)),
            (key(Right), edit(Edit::Right)),
            (key(Home), edit(Edit::Home)),
            (ctrl('a'), edit(Edit::Home)),
            (key(End), edit(Edit::End)),
            (ctrl('e'), edit(Edit::End)),
        ],
        label: "← → Home End",
        help: "move the cursor (also Ctrl-A, Ctrl-E)",
        footer: None,
    },
    Binding {
        context: Context::Prompt,
        keys: &[
            (key(Backspace), edit(Edit::Backspace)),
            (key(Delete), edit(Edit::Delete)),
        ],
        label: "⌫  Del",
        help: "delete before / under the cursor",
        footer: None,
    },
    Binding {
        context: Context::Prompt,
        keys: &[(ctrl('u'), edit(Edit::DeleteToStart))],
        label: "Ctrl-U",
        help: "delete up to the cursor (all of it at the end)",
        footer: None,
    },
    Binding {
        context: Context::Prompt,
        keys: &[(ctrl('w'), edit(Edit::DeleteWord))],
        label: "Ctrl-W",
        help: "delete the word before the cursor",
        footer: None,
    },
    Binding {
        context: Context::Prompt,
        keys: &[(key(Enter), M::PromptAccept)],
        label: "Enter",
        help: "save under that name / set that value",
        footer: None,
    },
    Binding {
        context: Context::Prompt,
        keys: &[(key(Esc), M::PromptCancel), (ctrl('c'), M::PromptCancel)],
        label: "Esc  Ctrl-C",
        help: "cancel",
        footer: None,
    },
];

/// The message a key sends in the app's current mode, if any.
pub fn message_for_key(app: &App, ev: &KeyEvent) -> Option<Message> {
    if ev.kind == KeyEventKind::Release {
        return None;
    }
    // While the terminal is too small nothing is shown: only quitting acts.
    if app.too_small() {
        let quits = BINDINGS
            .iter()
            .flat_map(|b| b.keys)
            .any(|(k, m)| *m == M::Quit && k.matches(ev));
        return quits.then_some(M::Quit);
    }
    for b in BINDINGS.iter().filter(|b| b.context.covers(&app.mode)) {
        if let Some((_, m)) = b.keys.iter().find(|(k, _)| k.matches(ev)) {
            return Some(*m);
        }
    }
    // A prompt takes any other printable character as text.
    if let (Mode::Prompt(_) | Mode::Value(..), KeyCode::Char(c)) = (&app.mode, ev.code) {
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

/// The footer entries for a mode, in table order.
pub fn footer(mode: &Mode) -> Vec<&'static str> {
    BINDINGS
        .iter()
        .filter(|b| b.context.covers(mode))
        .filter_map(|b| b.footer)
        .collect()
}
