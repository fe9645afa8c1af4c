//! Everything that can happen to the explorer: the messages
//! [`update`](super::app::update)
//! (in `app`) applies. Keys, the session and the server send them.

use super::line_edit::Edit;

/// Everything that can happen to the explorer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Message {
    SelectPrev,
    SelectNext,
    /// Move the selected slider one step up or down, coarse or fine.
    Step {
        up: bool,
        fine: bool,
    },
    /// Load preset number n (0 = fig1).
    LoadPreset(usize),
    /// Back to the measured surface the session started on.
    LoadSurface,
    CycleSweep,
    ToggleModel,
    ToggleSizeEffect,
    /// Truncated / asymptotic spectrum moments.
    ToggleMoments,
    /// Tab / Shift-Tab: the next or previous view.
    NextView,
    PrevView,
    /// Another y axis for the regime map.
    NextMapY,
    /// Write the current view as an SVG picture into the save folder.
    SavePicture,
    /// Pin the current curves (on a measured surface first the fitted
    /// power law) as a ghost, or clear the ghost.
    ToggleGhost,
    /// `[ ]` `{ }`: an end of the fit band (`upper` or lower) one point up or down.
    MoveFitBand {
        upper: bool,
        up: bool,
    },
    /// `b`: the fit band found from the data again.
    AutoFitBand,
    StartSave,
    /// Open the prompt for the selected slider's value.
    StartValue,
    ToggleHelp,
    CloseHelp,
    /// The next (or previous) page of the help.
    HelpPage {
        next: bool,
    },
    /// Edit the open prompt's text.
    PromptEdit(Edit),
    PromptCancel,
    PromptAccept,
    Resize(u16, u16),
    /// A served student's `f`: show the lecturer's scene again (the serve
    /// session acts on it; the explorer alone has nothing to follow).
    Follow,
    /// In a served class (the serve session acts on these): the lecturer's
    /// `v` (open a poll, or reveal the open one) and `S` (save its answers),
    /// a student's Enter (answer with the marker's value).
    Poll,
    SavePoll,
    Answer,
    /// The lecturer's `V`: a poll on a value they type.
    PollTyped,
    /// The lecturer's `C`: cancel the open poll.
    CancelPoll,
    /// A student's `0` in a poll that allows it: "nowhere in the sweep".
    AnswerNowhere,
    /// The lecturer's `d` after a reveal: every screen shows the answers'
    /// histogram with the truth marked.
    ShareAnswers,
    /// The lecturer's `Q`: the join page's QR code, full screen (any key
    /// closes it).
    ShowJoin,
    /// The lecturer's `P`: the poll for the projector, full screen (`P` or
    /// Esc closes it).
    Projector,
    /// In the projector view, `t`: a countdown for the poll (30 s, 1 min,
    /// 2 min, off).
    Countdown,
    /// The lecturer's `F`: every student follows again.
    AllFollow,
    /// The lecturer's scene list (`o`): open it, move in it, load the one
    /// chosen, close it.
    OpenScenes,
    SceneMove {
        down: bool,
    },
    ScenePick,
    SceneClose,
    /// A lesson's next (`n`) or previous (`N`) step.
    LessonStep {
        next: bool,
    },
    /// The lecturer's class list, open or closed.
    ToggleClass,
    /// In the class list: choose the next / previous student, remove the
    /// one chosen (the serve session acts on it).
    ClassChoose {
        down: bool,
    },
    RemoveStudent,
    /// The next glyph set: braille, half blocks, blocks, ASCII (`M`).
    CycleGlyphs,
    /// Colour off (as under NO_COLOR) or on again (`c`).
    ToggleColor,
    /// Ctrl-L: paint the whole screen again (the session acts on it; over
    /// SSH after asking the terminal for its size).
    Redraw,
    /// The contact view's keys: the next or previous load, the plastic
    /// share against ζ (`b`), the initial slopes against ζ (`i`), another
    /// surface (`r`: the next seed), how many surfaces (`R`: 1, 4 or 16
    /// seeds), the convergence table (`t`), one hardness cap, each
    /// asperity's or each summit's (`A`).
    ContactLoad {
        up: bool,
    },
    ContactSweep,
    ContactSlopes,
    ContactSeed,
    ContactSeeds,
    ContactTable,
    ContactHardness,
    /// The contact solver made progress (sent by the session, not a key).
    Tick,
    Quit,
}
