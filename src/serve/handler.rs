//! One SSH connection's protocol side: who it is (auth), and the one thing
//! it may do — a shell request on one session channel with a pty, which
//! starts an explorer, after telling its terminal (the pty's TERM and size,
//! LANG and LC_* as env requests). Everything else is refused: exec,
//! subsystems (sftp), any other env variable, X11 and agent forwarding,
//! port forwarding either way, streamlocal, a second channel, a shell
//! without a pty.

use std::sync::Arc;

use russh::keys::PublicKey;
use russh::server::{Auth, ChannelOpenHandle, Msg, Session};
use russh::{Channel, ChannelId, MethodKind, MethodSet};
use tokio::sync::Notify;

use super::auth::Role;
use super::limits::clamp_size;
use super::session::{self, Start};
use super::stream::Kill;
use super::term::ClientTerm;
use super::Shared;

/// Channel requests a connection may make before its shell starts; past
/// this it is dropped (a client flooding requests gets nothing queued).
const MAX_REQUESTS: usize = 32;

pub struct Handler {
    pub shared: Arc<Shared>,
    /// Told when the explorer starts (the login deadline stops).
    pub started: Arc<Notify>,
    kill: Kill,
    role: Option<Role>,
    channel: Option<Channel<Msg>>,
    channel_opened: bool,
    pty: Option<(u16, u16)>,
    /// The client's TERM and locale.
    client: ClientTerm,
    running: bool,
    requests: usize,
}

#[derive(Debug)]
pub struct Error(pub String);

impl From<russh::Error> for Error {
    fn from(e: russh::Error) -> Error {
        Error(e.to_string())
    }
}

impl Handler {
    pub fn new(shared: Arc<Shared>, started: Arc<Notify>, kill: Kill) -> Handler {
        Handler {
            shared,
            started,
            kill,
            role: None,
            channel: None,
            channel_opened: false,
            pty: None,
            client: ClientTerm::default(),
            running: false,
            requests: 0,
        }
    }

    /// Counts a channel request; too many before the shell end the connection.
    fn count(&mut self) -> Result<(), Error> {
        self.requests += 1;
        if !self.running && self.requests > MAX_REQUESTS {
            return Err(Error("too many channel requests".into()));
        }
        Ok(())
    }

    fn refuse(&mut self, channel: ChannelId, session: &mut Session) -> Result<(), Error> {
        self.count()?;
        session.channel_failure(channel)?;
        Ok(())
    }
}

impl russh::server::Handler for Handler {
    type Error = Error;

    async fn auth_none(&mut self, user: &str) -> Result<Auth, Error> {
        if self.shared.lecturer_keys.admits_student(user) {
            self.role = Some(Role::Student);
            return Ok(Auth::Accept);
        }
        Ok(Auth::Reject {
            proceed_with_methods: Some(MethodSet::from(&[MethodKind::PublicKey][..])),
            partial_success: false,
        })
    }

    async fn auth_publickey_offered(&mut self, user: &str, key: &PublicKey) -> Result<Auth, Error> {
        Ok(if self.shared.lecturer_keys.admits(user, key) {
            Auth::Accept
        } else {
            Auth::reject()
        })
    }

    async fn auth_publickey(&mut self, user: &str, key: &PublicKey) -> Result<Auth, Error> {
        if self.shared.lecturer_keys.admits(user, key) {
            self.role = Some(Role::Lecturer);
            return Ok(Auth::Accept);
        }
        Ok(Auth::reject())
    }

    async fn channel_open_session(
        &mut self,
        channel: Channel<Msg>,
        reply: ChannelOpenHandle,
        _: &mut Session,
    ) -> Result<(), Error> {
        // One session channel per connection; a second is refused (dropping
        // the reply refuses it).
        if !self.channel_opened {
            self.channel_opened = true;
            self.channel = Some(channel);
            reply.accept().await;
        }
        Ok(())
    }

    async fn pty_request(
        &mut self,
        channel: ChannelId,
        term: &str,
        cols: u32,
        rows: u32,
        _: u32,
        _: u32,
        _: &[(russh::Pty, u32)],
        session: &mut Session,
    ) -> Result<(), Error> {
        self.count()?;
        if self.running || self.channel.as_ref().map(|c| c.id()) != Some(channel) {
            session.channel_failure(channel)?;
            return Ok(());
        }
        self.pty = Some(clamp_size(cols, rows));
        self.client.set_term(term);
        session.channel_success(channel)?;
        Ok(())
    }

    async fn shell_request(
        &mut self,
        channel: ChannelId,
        session: &mut Session,
    ) -> Result<(), Error> {
        self.count()?;
        let (Some(size), Some(role)) = (self.pty, self.role) else {
            // No pty: there is nothing to draw on.
            session.channel_failure(channel)?;
            return Ok(());
        };
        let Some(ch) = self.channel.take().filter(|c| c.id() == channel) else {
            session.channel_failure(channel)?;
            return Ok(());
        };
        session.channel_success(channel)?;
        self.running = true;
        self.started.notify_one();
        session::spawn(Start {
            shared: Arc::clone(&self.shared),
            channel: ch,
            conn: session.handle(),
            kill: self.kill.clone(),
            role,
            size,
            client: std::mem::take(&mut self.client),
        });
        Ok(())
    }

    async fn exec_request(&mut self, c: ChannelId, _: &[u8], s: &mut Session) -> Result<(), Error> {
        self.refuse(c, s)
    }

    async fn subsystem_request(
        &mut self,
        c: ChannelId,
        _: &str,
        s: &mut Session,
    ) -> Result<(), Error> {
        self.refuse(c, s)
    }

    /// LANG and LC_* before the shell (they choose the session's glyphs);
    /// any other variable, or any after the shell, is refused.
    async fn env_request(
        &mut self,
        c: ChannelId,
        name: &str,
        value: &str,
        s: &mut Session,
    ) -> Result<(), Error> {
        let ours = self.channel.as_ref().map(|ch| ch.id()) == Some(c);
        if self.running || !ours || !self.client.env(name, value) {
            return self.refuse(c, s);
        }
        self.count()?;
        s.channel_success(c)?;
        Ok(())
    }

    async fn x11_request(
        &mut self,
        c: ChannelId,
        _: bool,
        _: &str,
        _: &str,
        _: u32,
        s: &mut Session,
    ) -> Result<(), Error> {
        self.refuse(c, s)
    }

    async fn agent_request(&mut self, _: ChannelId, _: &mut Session) -> Result<bool, Error> {
        self.count()?;
        Ok(false)
    }

    async fn window_change_request(
        &mut self,
        _: ChannelId,
        _: u32,
        _: u32,
        _: u32,
        _: u32,
        _: &mut Session,
    ) -> Result<(), Error> {
        // The explorer reads the new size from its channel.
        Ok(())
    }

    async fn tcpip_forward(
        &mut self,
        _: &str,
        _: &mut u32,
        _: &mut Session,
    ) -> Result<bool, Error> {
        self.count()?;
        Ok(false)
    }

    async fn streamlocal_forward(&mut self, _: &str, _: &mut Session) -> Result<bool, Error> {
        self.count()?;
        Ok(false)
    }
}
