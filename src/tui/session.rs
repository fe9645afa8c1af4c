//! One explorer session against any byte sink: the [`App`], its update and
//! its frames, at a size the caller gives. The local terminal ([`super::run`])
//! and each SSH session (`serve`) drive the explorer through this one path.

use std::io::{self, Write};
use std::sync::Arc;

use crossterm::event::Event;
use ratatui::backend::{Backend, ClearType, CrosstermBackend};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;
use ratatui::{Terminal, TerminalOptions, Viewport};

use super::app::{update, App, Message};
use super::keys;
use super::theme::Theme;
use crate::physical::ascii::ascii_name;
use crate::scene::State;

/// An explorer drawing into `W` at a fixed size that only [`Session::resize`]
/// changes (nothing asks a terminal for its size).
pub struct Session<W: Write> {
    terminal: Terminal<CrosstermBackend<W>>,
    pub app: App,
    /// The shared frame the screen shows, while it was the last thing
    /// drawn: another session that showed it too and went on to the same
    /// next frame wrote the bytes this one needs (see
    /// [`Session::draw_frame_as`]).
    shown: Option<Arc<Buffer>>,
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
            shown: None,
        })
    }

    /// The byte sink frames are written into (for what the caller sends
    /// the terminal besides frames: a question, written before the next
    /// frame).
    pub fn writer(&mut self) -> &mut impl Write {
        self.shown = None;
        self.terminal.backend_mut()
    }

    /// The message `ev` sends in the app's current mode, if any.
    pub fn message_for(&self, ev: &Event) -> Option<Message> {
        keys::message_for_event(&self.app, ev)
    }

    /// Applies `msg` (a resize also resizes the frame, which then repaints
    /// in full; so does a redraw, after clearing the screen).
    pub fn update(&mut self, msg: Message) -> io::Result<()> {
        if matches!(msg, Message::Resize(..) | Message::Redraw) {
            self.shown = None;
        }
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
    pub fn draw_with(&mut self, overlay: impl FnOnce(&App, &mut Buffer)) -> io::Result<()> {
        self.shown = None;
        let app = &self.app;
        self.terminal
            .draw(|f| paint(app, f.buffer_mut(), overlay))?;
        Ok(())
    }

    pub fn draw(&mut self) -> io::Result<()> {
        self.draw_with(|_, _| {})
    }

    /// The frame [`Session::draw_with`] would draw, drawn apart (to be
    /// shown by other sessions with the same screen, see [`App::look`]).
    pub fn render(&self, overlay: impl FnOnce(&App, &mut Buffer)) -> Buffer {
        let (w, h) = self.app.size;
        let mut buf = Buffer::empty(Rect::new(0, 0, w, h));
        paint(&self.app, &mut buf, overlay);
        buf
    }

    /// The shared frame the screen shows, if nothing was drawn since.
    pub fn shown(&self) -> Option<&Arc<Buffer>> {
        self.shown.as_ref()
    }

    /// Shows `frame` (drawn by [`Session::render`], here or in another
    /// session at this size): only what differs from the screen before is
    /// sent, as for a frame drawn here.
    pub fn draw_frame(&mut self, frame: &Arc<Buffer>) -> io::Result<()> {
        self.shown = Some(Arc::clone(frame));
        self.terminal.draw(|f| {
            let buf = f.buffer_mut();
            // (A frame's size is part of what it shows, so it fits.)
            debug_assert_eq!(buf.area, frame.area);
            if buf.area == frame.area {
                buf.content.clone_from_slice(&frame.content);
            }
        })?;
        Ok(())
    }

    /// Shows `frame` by writing `bytes`: what [`Session::draw_frame`]
    /// wrote in a session whose screen showed what this one's shows
    /// ([`Session::shown`]) — the same change, not worked out again.
    pub fn draw_frame_as(&mut self, frame: &Arc<Buffer>, bytes: &[u8]) -> io::Result<()> {
        self.shown = Some(Arc::clone(frame));
        let t = &mut self.terminal;
        t.current_buffer_mut()
            .content
            .clone_from_slice(&frame.content);
        t.backend_mut().write_all(bytes)?;
        t.swap_buffers();
        Backend::flush(t.backend_mut())
    }
}

/// The app, then `overlay`, into `buf` (all of it), in ASCII where the
/// glyphs say so.
fn paint(app: &App, buf: &mut Buffer, overlay: impl FnOnce(&App, &mut Buffer)) {
    app.render(buf.area, buf);
    overlay(app, buf);
    if app.theme.glyphs.ascii_only() {
        ascii_only(buf);
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
