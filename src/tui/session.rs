//! One explorer session against any byte sink: the [`App`], its update and
//! its frames, at a size the caller gives. The local terminal ([`super::run`])
//! and each SSH session (`serve`) drive the explorer through this one path.

use std::io::{self, Write};

use crossterm::event::Event;
use ratatui::backend::{Backend, ClearType, CrosstermBackend};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::{Frame, Terminal, TerminalOptions, Viewport};

use super::app::{update, App, Message};
use super::glyphs::ascii_name;
use super::keys;
use super::theme::Theme;
use crate::scene::State;

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

    /// The byte sink frames are written into (for what the caller sends
    /// the terminal besides frames: a question, written before the next
    /// frame).
    pub fn writer(&mut self) -> &mut impl Write {
        self.terminal.backend_mut()
    }

    /// The message `ev` sends in the app's current mode, if any.
    pub fn message_for(&self, ev: &Event) -> Option<Message> {
        keys::message_for_event(&self.app, ev)
    }

    /// Applies `msg` (a resize also resizes the frame, which then repaints
    /// in full; so does a redraw, after clearing the screen).
    pub fn update(&mut self, msg: Message) -> io::Result<()> {
        match msg {
            Message::Resize(w, h) => self.terminal.resize(Rect::new(0, 0, w, h))?,
            Message::Redraw => {
                self.terminal.backend_mut().clear_region(ClearType::All)?;
                let (w, h) = self.app.size;
                self.terminal.resize(Rect::new(0, 0, w, h))?;
            }
            _ => {}
        }
        update(&mut self.app, msg);
        Ok(())
    }

    /// Draws the app, then `overlay` on top, and flushes the backend. With
    /// the ASCII glyphs, whatever is not ASCII in the frame (nothing the
    /// views draw; a safety net) is sent as its ASCII fallback.
    pub fn draw_with(&mut self, overlay: impl FnOnce(&App, &mut Frame)) -> io::Result<()> {
        let app = &self.app;
        self.terminal.draw(|f| {
            f.render_widget(app, f.area());
            overlay(app, f);
            if app.theme.glyphs.ascii_only() {
                ascii_only(f.buffer_mut());
            }
        })?;
        Ok(())
    }

    pub fn draw(&mut self) -> io::Result<()> {
        self.draw_with(|_, _| {})
    }
}

/// Replaces every cell of `buf` that is not ASCII by a one-column ASCII
/// fallback; the number of cells replaced.
pub fn ascii_only(buf: &mut Buffer) -> usize {
    let mut n = 0;
    for cell in &mut buf.content {
        let sym = cell.symbol();
        if !sym.is_ascii() {
            let name = sym.chars().next().map_or("?", ascii_name);
            let c = if name.len() == 1 { name } else { "?" };
            cell.set_symbol(c);
            n += 1;
        }
    }
    n
}
