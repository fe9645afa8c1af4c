//! The explorer and the lecturer's screen the class follows
//! ([`Shown`]): what this explorer shows, and showing what another shows.

use super::{update, App, Message};
use crate::class::{ContactShown, Shown};
use crate::tui::contact::ContactPane;

impl App {
    /// What this explorer shows, for the class to follow.
    pub fn shown(&self) -> Shown {
        Shown {
            state: self.state.clone(),
            selected: self.selected,
            view: self.view,
            map_y: self.map_y,
            modified: self.modified,
            file: self.file.clone(),
            contact: contact_shown(&self.contact),
            step: self.class.step.clone(),
        }
    }

    /// Shows what another explorer shows (a followed lecturer's, or the
    /// scene a poll was asked on).
    pub fn follow(&mut self, shown: &Shown) {
        let c = &mut self.contact;
        let moved = contact_shown(c) != shown.contact;
        let s = &shown.contact;
        (c.load, c.plot, c.seeds, c.table) = (s.load, s.plot, s.seeds, s.table);
        c.sampling.hardness = s.hardness;
        self.show(&shown.state, shown.selected, shown.view, shown.map_y);
        if moved {
            update(self, Message::Tick);
        }
        self.modified = shown.modified;
        self.file.clone_from(&shown.file);
        self.class.step.clone_from(&shown.step);
    }
}

/// What the contact view shows of its scene.
fn contact_shown(c: &ContactPane) -> ContactShown {
    ContactShown {
        load: c.load,
        plot: c.plot,
        seeds: c.seeds,
        table: c.table,
        hardness: c.sampling.hardness,
    }
}
