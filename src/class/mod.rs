//! The class: what a served class (or a lesson rehearsed alone) is made
//! of, as data, on a floor below both the explorer that draws it (`tui`)
//! and the transports that carry it (`serve`: SSH and the web). No
//! terminal code and no sockets here.
//!
//! - [`Class`] ([`room`]): the state the server owns and every session
//!   shares: the roster of students (their seats) and the poll (its
//!   question, scene, answers and reveal), with the answers' [`csv`];
//! - [`Question`]: what a poll asks, its truth, how far an answer is;
//! - [`ClassView`], [`Seat`], [`Tally`], [`Asked`] : the class
//!   as a screen shows it: the lecturer's roster and poll, its answers'
//!   tally, a student's question and reveal;
//! - [`lesson`]: lessons read from RON, the step on screen and what a step
//!   hides until its poll is revealed;
//! - [`Classroom`]: the class as one session holds it, and the lesson's
//!   moves (a step's scene comes back as a new [`crate::scene::State`]
//!   for the explorer to show);
//! - [`Shown`]: the lecturer's screen, which students follow and a poll
//!   is asked on; [`scenes`]: the scenes a lecturer can load.
//!
//! A session's class is plain data: its [`Classroom`] beside the [`Shown`]
//! scene. The terminal draws it (`tui::views::class`); another renderer
//! can draw the same.

mod classroom;
pub mod csv;
mod glyphs;
pub mod lesson;
mod question;
pub mod room;
pub mod scenes;
mod shown;
mod view;

pub use classroom::{ClaimsRow, Classroom, LessonEnd};
pub use csv::CSV_HEADER;
pub use glyphs::{ClassGlyphs, ASCII, UNICODE};
pub use lesson::{Lesson, LessonAt, Step, StepLine, StepScene};
pub use question::{fmt_value, Ask, Question, NOWHERE};
pub use room::{
    clean_name, Arrival, Class, Note, Poll, Refused, SeatId, Taken, Transport, NAME_CHARS,
};
pub use shown::{ContactShown, Shown};
pub use view::{duration, Asked, ClassView, Seat, SeatState, Tally, MIN_SIZE, WITHIN};

#[cfg(test)]
mod view_tests;
