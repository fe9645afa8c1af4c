//! One SSH connection's protocol side: who it is (auth: see [`super::auth`]
//! and, with a class code, [`super::code`]), and the one thing
//! it may do — a shell request on one session channel with a pty, which
//! starts an explorer, after telling its terminal (the pty's TERM and size,
//! LANG and LC_* as env requests). Everything else is refused: exec,
//! subsystems (sftp), any other env variable, X11 and agent forwarding,
//! port forwarding either way, streamlocal, a second channel, a shell
//! without a pty.

use std::net::SocketAddr;
use std::sync::{Arc, OnceLock};

use russh::keys::PublicKey;
use russh::server::{Auth, ChannelOpenHandle, Msg, Response, Session};
use russh::{Channel, ChannelId, MethodKind, MethodSet};
use tokio::sync::Notify;

use super::auth::Role;
use super::code::Turn;
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
    peer: SocketAddr,
    /// The connection, to disconnect it with a reason the client prints.
    conn: Arc<OnceLock<russh::server::Handle>>,
    /// The user name the connection logged in with.
    user: String,
    /// Wrong class codes on this connection.
    wrong: usize,
    role: Option<Role>,
    channel: Option<Channel<Msg>>,
    channel_opened: bool,
    pty: Option<(u16, u16)>,
    /// The client's TERM and locale.
    client: ClientTerm,
    running: bool,
    requests: usize,
    /// A student's place in the class, held while the connection lasts.
    seat: Option<super::limits::Permit>,
    /// A student who found the class full: why, said on their terminal.
    full: Option<String>,
}

#[derive(Debug)]
pub struct Error(pub String);

impl From<russh::Error> for Error {
    fn from(e: russh::Error) -> Error {
        Error(e.to_string())
    }
}

impl Handler {
    pub fn new(
        shared: Arc<Shared>,
        started: Arc<Notify>,
        kill: Kill,
        peer: SocketAddr,
        conn: Arc<OnceLock<russh::server::Handle>>,
    ) -> Handler {
        Handler {
            shared,
            started,
            kill,
            peer,
            conn,
            user: String::new(),
            wrong: 0,
            role: None,
            channel: None,
            channel_opened: false,
            pty: None,
            client: ClientTerm::default(),
            running: false,
            requests: 0,
            seat: None,
            full: None,
        }
    }

    /// Ends the connection with `why`, which OpenSSH prints ("Received
    /// disconnect from …: why"), once the current reply is sent.
    fn disconnect(&self, why: String) {
        if let Some(h) = self.conn.get().cloned() {
            tokio::spawn(async move {
                let _ = h
                    .disconnect(russh::Disconnect::ByApplication, why, String::new())
                    .await;
            });
        }
    }

    /// A student logs in: with a place in the class, or to be told on
    /// their terminal that the class is full (the lecturer's key needs no
    /// place).
    fn student(&mut self, user: &str) -> Auth {
        let ip = self.peer.ip();
        match self.shared.seats.enter(ip) {
            Ok(p) => self.seat = Some(p),
            Err(full) => {
                let why = super::full_text(full, &self.shared.seats, ip);
                self.shared.log.line(&format!("turned away {ip}: {why}"));
                self.full = Some(why);
            }
        }
        self.role = Some(Role::Student);
        self.user = user.to_string();
        Auth::Accept
    }

    /// The methods left to a user: the lecturer's key, or the class code.
    fn methods_for(&self, user: &str) -> MethodSet {
        if self.shared.lecturer_keys.admits_student(user) {
            MethodSet::from(&[MethodKind::KeyboardInteractive][..])
        } else {
            MethodSet::from(&[MethodKind::PublicKey][..])
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
        let code = self.shared.class_code.is_some();
        if !code && self.shared.lecturer_keys.admits_student(user) {
            return Ok(self.student(user));
        }
        Ok(Auth::Reject {
            proceed_with_methods: Some(if code {
                self.methods_for(user)
            } else {
                MethodSet::from(&[MethodKind::PublicKey][..])
            }),
            partial_success: false,
        })
    }

    async fn auth_keyboard_interactive<'a>(
        &'a mut self,
        user: &str,
        _: &str,
        response: Option<Response<'a>>,
    ) -> Result<Auth, Error> {
        let Some(code) = self.shared.class_code.clone() else {
            return Ok(Auth::reject());
        };
        if !self.shared.lecturer_keys.admits_student(user) {
            return Ok(Auth::Reject {
                proceed_with_methods: Some(self.methods_for(user)),
                partial_success: false,
            });
        }
        let Some(mut response) = response else {
            let prompt = if self.wrong == 0 {
                "class code: "
            } else {
                "wrong code, try again. class code: "
            };
            return Ok(Auth::Partial {
                name: "".into(),
                instructions: "".into(),
                prompts: vec![(prompt.into(), false)].into(),
            });
        };
        let typed = response.next().unwrap_or_default();
        let ip = self.peer.ip();
        let wrongs = &self.shared.wrong_codes;
        match wrongs.turn(ip, std::time::Instant::now()) {
            Turn::Now => {}
            Turn::At(t) => tokio::time::sleep_until(t.into()).await,
            Turn::Refused(first) => {
                if first {
                    self.shared.log.line(&super::code::too_fast(ip));
                }
                self.shared.refusals.count(super::code::UNCHECKED);
                self.disconnect(super::code::wait_line(ip));
                return Ok(Auth::reject());
            }
        }
        if code.matches(&typed) {
            wrongs.right(ip, std::time::Instant::now());
            return Ok(self.student(user));
        }
        self.wrong += 1;
        self.shared.refusals.count(super::code::WRONG);
        Ok(Auth::Reject {
            proceed_with_methods: Some(self.methods_for(user)),
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
            self.user = user.to_string();
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
        if let Some(why) = self.full.take() {
            session::refuse(ch, why);
            return Ok(());
        }
        session::spawn(Start {
            shared: Arc::clone(&self.shared),
            wire: session::Wire::ssh(ch, session.handle(), self.kill.clone()),
            role,
            size,
            name: std::mem::take(&mut self.user),
            addr: self.peer.ip(),
            client: std::mem::take(&mut self.client),
            transport: crate::class::Transport::Ssh,
            token: None,
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
