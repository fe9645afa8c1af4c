//! One explorer session against any byte sink: the [`App`], its update and
//! its frames, at a size the caller gives. The local terminal ([`super::run`])
//! and each SSH session (`serve`) drive the explorer through this one path.

use std::io::{self, Write};

use crossterm::event::Event;
use ratatui::backend::CrosstermBackend;
use ratatui::layout::Rect;
use ratatui::{Frame, Terminal, TerminalOptions, Viewport};

use super::app::{update, App, Message};
use super::keys;
use super::theme::Theme;
use crate::snapshot::State;

/// An explorer drawing into `W` at a fixed size that only [`Session::resize`]
/// changes (nothing asks a terminal for its size).
pub struct Session<W: Write> {
    terminal: Terminal<CrosstermBackend<W>>,
    pub app: App,
}

impl<W: Write> Session<W> {
    pub fn new(out: W, state: State, theme: Theme, (w, h): (u16, u16)) -> io::Result<Self> {
        let terminal = Terminal::with_options(
            CrosstermBackend::new(out),
            TerminalOptions {
                viewport: Viewport::Fixed(Rect::new(0, 0, w, h)),
            },
        )?;
        Ok(Session {
            terminal,
            app: App::new(state, theme, (w, h)),
        })
    }

    /// The message `ev` sends in the app's current mode, if any.
    pub fn message_for(&self, ev: &Event) -> Option<Message> {
        keys::message_for_event(&self.app, ev)
    }

    /// Applies `msg` (a resize also resizes the frame, which then repaints
    /// in full).
    pub fn update(&mut self, msg: Message) -> io::Result<()> {
        if let Message::Resize(w, h) = msg {
            self.terminal.resize(Rect::new(0, 0, w, h))?;
        }
        update(&mut self.app, msg);
        Ok(())
    }

    /// Draws the app, then `overlay` on top, and flushes the backend.
    pub fn draw_with(&mut self, overlay: impl FnOnce(&App, &mut Frame)) -> io::Result<()> {
        let app = &self.app;
        self.terminal.draw(|f| {
            f.render_widget(app, f.area());
            overlay(app, f);
        })?;
        Ok(())
    }

    pub fn draw(&mut self) -> io::Result<()> {
        self.draw_with(|_, _| {})
    }
}
