//! What of an explorer's screen is its own beside the scene it shows: two
//! explorers with one [`Look`] that show one scene (the same lecturer's
//! state, or the same poll's, applied the same way) draw the same screen,
//! so a served class renders it once for all of them. Every field of
//! [`App`] is named here, in or out with its reason, so that a new field
//! cannot be forgotten (the destructuring below does not compile without
//! it).

use super::{App, Mode, Status};
use crate::class::{Asked, Classroom, Tally};
use crate::tui::theme::Theme;

/// An explorer's own part of its screen (see the module's doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Look {
    size: (u16, u16),
    theme: Theme,
    status: Option<Status>,
    mode: Mode,
    help_page: usize,
    student: bool,
    lecturer_keys: bool,
    lecturer_here: bool,
    /// A measured surface's scene to return to (`5`, in the footer).
    home: bool,
    asked: Option<Asked>,
    tally: Option<Tally>,
}

impl App {
    /// The explorer's own part of its screen; `None` where the screen
    /// depends on more than it and the scene (a pinned ghost, the contact
    /// view's simulation as it runs, the lecturer's panels, a prompt).
    pub fn look(&self) -> Option<Look> {
        let App {
            // The scene and what is computed from it (with the size, the
            // glyphs and the view): the caller names the scene.
            state: _,
            selected: _,
            view,
            map_y: _,
            plot: _,
            plot_cover: _,
            indices: _,
            load: _,
            spectrum: _,
            map: _,
            claims: _,
            readout: _,
            modified: _,
            file: _,
            captioned: _,
            key: _,
            indices_key: _,
            load_key: _,
            spectrum_key: _,
            claims_key: _,
            // Not drawn.
            save_dir: _,
            quit: _,
            recomputes: _,
            // Its own.
            mode,
            help_page,
            status,
            size,
            theme,
            student,
            lecturer_keys,
            lecturer_here,
            home,
            ghost,
            class,
            contact: _,
        } = self;
        let Classroom {
            view: lecturer_view,
            asked,
            typed,
            lesson,
            // The lecturer's step, from the scene.
            step: _,
            chosen,
            remove,
            scenes,
            tally,
            join_url,
            join_shown,
            projector,
            countdown,
        } = class;
        let plain = ghost.is_none()
            && *view != crate::figure::View::Contact
            && matches!(mode, Mode::Main | Mode::Help)
            && lecturer_view.is_none()
            && typed.is_none()
            && lesson.is_none()
            && *chosen == 0
            && remove.is_none()
            && scenes.is_none()
            && join_url.is_none()
            && !join_shown
            && !projector
            && countdown.is_none();
        plain.then(|| Look {
            size: *size,
            theme: *theme,
            status: status.clone(),
            mode: mode.clone(),
            // The page turned to is drawn only in the help.
            help_page: if *mode == Mode::Help { *help_page } else { 0 },
            student: *student,
            lecturer_keys: *lecturer_keys,
            lecturer_here: *lecturer_here,
            home: home.is_some(),
            asked: *asked,
            tally: tally.clone(),
        })
    }
}
