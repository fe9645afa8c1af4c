//! Frames to one client. The explorer renders into a [`FrameBuf`] and hands
//! the bytes to this writer through a one-frame slot (a channel of capacity
//! one): while the client has not taken a frame, the explorer only notes
//! that the screen changed and renders the latest state once the slot is
//! free. So a stalled client holds at most one pending frame, and a client
//! that takes nothing for [`STALL`] is dropped.

use std::io::{self, Write};
use std::sync::{Arc, Mutex};

use crossterm::cursor::Show;
use crossterm::style::{Attribute, ResetColor, SetAttribute};
use crossterm::terminal::LeaveAlternateScreen;
use ratatui::buffer::Buffer;
use ratatui::style::Modifier;
use russh::server::{Handle, Msg};
use russh::{ChannelWriteHalf, Disconnect};
use tokio::sync::mpsc;

use super::stream::Kill;
pub use super::stream::STALL;

/// A byte sink the explorer's terminal backend writes frames into.
#[derive(Clone, Debug, Default)]
pub struct FrameBuf(Arc<Mutex<Vec<u8>>>);

impl FrameBuf {
    /// The bytes written since the last take.
    pub fn take(&self) -> Vec<u8> {
        std::mem::take(&mut *self.0.lock().unwrap_or_else(|p| p.into_inner()))
    }

    /// How many bytes wait.
    pub fn len(&self) -> usize {
        self.0.lock().unwrap_or_else(|p| p.into_inner()).len()
    }

    /// Whether none wait.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The bytes written past the first `from`.
    pub fn since(&self, from: usize) -> Vec<u8> {
        let b = self.0.lock().unwrap_or_else(|p| p.into_inner());
        b.get(from..).unwrap_or_default().to_vec()
    }
}

impl Write for FrameBuf {
    fn write(&mut self, b: &[u8]) -> io::Result<usize> {
        self.0
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .extend_from_slice(b);
        Ok(b.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// The slot's sending side, for the explorer.
pub type Slot = mpsc::Sender<Vec<u8>>;

/// Why the server ends a session, set before the slot is dropped: the
/// client's terminal shows it as a line on its normal screen; and whether
/// the terminal is on its normal screen already (a student's printed
/// snapshot), where leaving the alternate screen again would put the
/// cursor back where the session began, over the snapshot.
#[derive(Clone, Debug, Default)]
pub struct Bye(Arc<Mutex<(Option<String>, bool)>>, Arc<Mutex<Vec<String>>>);

impl Bye {
    pub fn set(&self, why: impl Into<String>) {
        self.0.lock().unwrap_or_else(|p| p.into_inner()).0 = Some(why.into());
    }

    /// Lines the client's normal screen keeps above the goodbye (who the
    /// student was in the class, their polls' results).
    pub fn keep(&self, lines: Vec<String>) {
        *self.1.lock().unwrap_or_else(|p| p.into_inner()) = lines;
    }

    /// The session printed on the normal screen (`true`) or went back to
    /// the alternate one.
    pub fn normal_screen(&self, on: bool) {
        self.0.lock().unwrap_or_else(|p| p.into_inner()).1 = on;
    }

    /// Why the server ends the session, if it does.
    pub fn why(&self) -> Option<String> {
        self.0.lock().unwrap_or_else(|p| p.into_inner()).0.clone()
    }

    /// The goodbye's bytes for the terminal as it is now.
    pub fn bytes(&self) -> Vec<u8> {
        let (why, normal) = std::mem::take(&mut *self.0.lock().unwrap_or_else(|p| p.into_inner()));
        let kept = std::mem::take(&mut *self.1.lock().unwrap_or_else(|p| p.into_inner()));
        goodbye_keeping(why.as_deref(), !normal, &kept)
    }
}

/// What ends a session on the client's terminal: out of the alternate
/// screen (when `alt`: it is on it), the cursor shown, colours and
/// attributes reset, then `why` (if the server ended it) on a line of its
/// own.
pub fn goodbye(why: Option<&str>, alt: bool) -> Vec<u8> {
    goodbye_keeping(why, alt, &[])
}

/// [`goodbye`] with `kept` lines above the line that says why.
pub fn goodbye_keeping(why: Option<&str>, alt: bool, kept: &[String]) -> Vec<u8> {
    let mut bye = Vec::new();
    if alt {
        let _ = crossterm::execute!(bye, LeaveAlternateScreen);
    }
    let _ = crossterm::execute!(bye, Show, ResetColor, SetAttribute(Attribute::Reset));
    for l in kept {
        bye.extend_from_slice(format!("\r\n{l}").as_bytes());
    }
    match why {
        Some(why) => bye.extend_from_slice(format!("\r\nroughtui: {why}\r\n").as_bytes()),
        None if !kept.is_empty() => bye.extend_from_slice(b"\r\n"),
        None => {}
    }
    bye
}

/// The screen `buf` shows as lines for the normal screen: each row's
/// text in its colours and attributes (reset at the row's end), blanks at
/// the end of a row left out. The class's goodbye keeps the last screen
/// above its line, so a student can still read the chart and the result.
pub fn screen_lines(buf: &Buffer) -> Vec<String> {
    use crossterm::style::{SetBackgroundColor, SetForegroundColor};
    use ratatui::backend::IntoCrossterm;
    let (w, h) = (buf.area.width, buf.area.height);
    let mut lines = Vec::with_capacity(usize::from(h));
    for y in 0..h {
        let row: Vec<&ratatui::buffer::Cell> = (0..w).filter_map(|x| buf.cell((x, y))).collect();
        // The last cell that shows something (text, or a background).
        let end = row
            .iter()
            .rposition(|c| c.symbol() != " " || c.bg != ratatui::style::Color::Reset)
            .map_or(0, |i| i + 1);
        let mut line = Vec::new();
        let mut style = None;
        let mut skip = 0;
        for c in &row[..end] {
            if skip > 0 {
                skip -= 1;
                continue;
            }
            let now = (c.fg, c.bg, c.modifier);
            if style != Some(now) {
                let _ = crossterm::queue!(line, SetAttribute(Attribute::Reset));
                if c.fg != ratatui::style::Color::Reset {
                    let _ = crossterm::queue!(line, SetForegroundColor(c.fg.into_crossterm()));
                }
                if c.bg != ratatui::style::Color::Reset {
                    let _ = crossterm::queue!(line, SetBackgroundColor(c.bg.into_crossterm()));
                }
                for (m, a) in [
                    (Modifier::BOLD, Attribute::Bold),
                    (Modifier::DIM, Attribute::Dim),
                    (Modifier::ITALIC, Attribute::Italic),
                    (Modifier::UNDERLINED, Attribute::Underlined),
                    (Modifier::REVERSED, Attribute::Reverse),
                ] {
                    if c.modifier.contains(m) {
                        let _ = crossterm::queue!(line, SetAttribute(a));
                    }
                }
                style = Some(now);
            }
            line.extend_from_slice(c.symbol().as_bytes());
            skip = ratatui::text::Span::raw(c.symbol())
                .width()
                .saturating_sub(1);
        }
        if style.is_some() {
            let _ = crossterm::queue!(line, SetAttribute(Attribute::Reset), ResetColor);
        }
        lines.push(String::from_utf8_lossy(&line).into_owned());
    }
    lines
}

/// Starts the writer of `out`; it ends when the slot's sender is dropped
/// (then it restores the client's terminal, sends exit status `0`, closes
/// the channel and the connection, cut after a grace period if the
/// client does not let go) or when the client stalls or is gone.
pub fn spawn(out: ChannelWriteHalf<Msg>, conn: Handle, kill: Kill, bye: Bye) -> Slot {
    let (tx, rx) = mpsc::channel(1);
    tokio::spawn(async move {
        if !write_frames(out, rx, bye).await {
            // Stalled or gone: cut the connection now.
            kill.kill();
            return;
        }
        // The explorer was the connection's only use. A client closes the
        // connection itself once the channel is closed; one that does not
        // is disconnected (an earlier disconnect would make OpenSSH report
        // status 255 instead of the session's 0).
        tokio::time::sleep(STALL).await;
        let _ = tokio::time::timeout(
            STALL,
            conn.disconnect(
                Disconnect::ByApplication,
                "session ended".into(),
                String::new(),
            ),
        )
        .await;
        // A client that neither reads nor lets go keeps nothing here.
        tokio::time::sleep(STALL).await;
        kill.kill();
    });
    tx
}

/// Whether the session ended normally (not by a stalled or gone client).
async fn write_frames(
    out: ChannelWriteHalf<Msg>,
    mut rx: mpsc::Receiver<Vec<u8>>,
    why: Bye,
) -> bool {
    while let Some(frame) = rx.recv().await {
        match tokio::time::timeout(STALL, out.data_bytes(frame)).await {
            Ok(Ok(())) => {}
            // Gone or stalled: drop the slot, which ends the explorer.
            _ => return false,
        }
    }
    let bye = why.bytes();
    let _ = tokio::time::timeout(STALL, async {
        let _ = out.data_bytes(bye).await;
        let _ = out.exit_status(0).await;
        let _ = out.eof().await;
        let _ = out.close().await;
    })
    .await;
    true
}
