//! What a lecturer's explorer shows, as the class carries it: every
//! student who follows shows the same, and a poll is asked on it. The
//! explorer makes it and takes it (`App::shown`, `App::follow`).

use rough_model::Axis;

use super::lesson::StepLine;
use crate::figure::View;
use crate::scene::State;

/// What a lecturer's explorer shows: the scene (parameters, sweep, model,
/// moments), the selected slider, the view, the map's y axis, and the
/// header's file name and modified mark.
#[derive(Clone, Debug, PartialEq)]
pub struct Shown {
    pub state: State,
    pub selected: usize,
    pub view: View,
    pub map_y: Option<Axis>,
    pub modified: bool,
    pub file: Option<String>,
    /// The contact view's load, plot, seeds and table.
    pub contact: ContactShown,
    /// The lesson's step, when the lecturer leads one.
    pub step: Option<StepLine>,
}

/// What the contact view shows of a scene: the load (`[ ]`), the plot
/// (`b`, `i`), how many seeds it averages over (`R`), whether the
/// convergence table is up (`t`) and where the hardness applies (`A`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ContactShown {
    pub load: usize,
    pub plot: crate::contact::Plot,
    pub seeds: u32,
    pub table: bool,
    pub hardness: crate::contact::Hardness,
}
