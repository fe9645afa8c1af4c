//! A session's wire: the bytes and sizes that come in from a client and
//! the one-frame slot its frames go out through, whatever carries them —
//! an SSH channel or a browser's WebSocket. The session (`session.rs`)
//! does not know which.

use russh::server::Msg;
use russh::{Channel, ChannelMsg};

use super::limits::clamp_size;
use super::output;
use super::stream::Kill;

/// The bytes and sizes that come in from a client, whatever carries them.
pub enum WireIn {
    /// Keys (and terminal answers), as a terminal sends them.
    Data(Vec<u8>),
    /// A new terminal size, clamped.
    Resize(u16, u16),
    /// A web page's command (its text message): a phone's view or
    /// slider chosen (`view map`, `slider zeta`), its picture's shape
    /// (`shape wide`).
    Command(String),
}

/// How a session's screen goes to its client.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Render {
    /// A terminal's cells (SSH, the web page's xterm.js).
    Terminal,
    /// A phone's page: the picture and the texts around it
    /// (`web::phone`).
    Phone,
}

/// Where a session's input comes from: an SSH channel, or a WebSocket's
/// reader task.
pub enum Input {
    Ssh(russh::ChannelReadHalf),
    Web(tokio::sync::mpsc::Receiver<WireIn>),
}

impl Input {
    /// The next input; `None` when the client is gone.
    pub(super) async fn next(&mut self) -> Option<WireIn> {
        match self {
            Input::Web(rx) => rx.recv().await,
            Input::Ssh(read) => loop {
                match read.wait().await? {
                    ChannelMsg::Data { data } => return Some(WireIn::Data(data.to_vec())),
                    ChannelMsg::WindowChange {
                        col_width,
                        row_height,
                        ..
                    } => {
                        let (w, h) = clamp_size(col_width, row_height);
                        return Some(WireIn::Resize(w, h));
                    }
                    ChannelMsg::Eof | ChannelMsg::Close => return None,
                    _ => {}
                }
            },
        }
    }
}

/// A session's transport: its input, the one-frame slot its writer takes
/// frames from, the goodbye that writer sends, and how the console names
/// it (`""` for SSH, `" over the web"`).
pub struct Wire {
    pub input: Input,
    pub slot: output::Slot,
    pub bye: output::Bye,
    pub via: &'static str,
    /// How the screen is drawn.
    pub render: Render,
    /// The web page's side channel: the seat's token and the student's
    /// name in the class (`seat TOKEN NAME`), which the page keeps.
    pub notes: Option<tokio::sync::mpsc::UnboundedSender<String>>,
}

impl Wire {
    /// An SSH channel's wire: its writer started.
    pub fn ssh(channel: Channel<Msg>, conn: russh::server::Handle, kill: Kill) -> Wire {
        let (read, write) = channel.split();
        let bye = output::Bye::default();
        let slot = output::spawn(write, conn, kill, bye.clone());
        Wire {
            input: Input::Ssh(read),
            slot,
            bye,
            via: "",
            render: Render::Terminal,
            notes: None,
        }
    }
}
