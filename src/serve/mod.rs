//! `roughtui serve`: the explorer for a classroom over SSH. Each connection
//! gets its own explorer at its own terminal size; a lecturer (by key) leads
//! and students follow until they explore on their own. Nobody gets a shell
//! or anything else: see [`handler`] for what is refused, [`limits`] for
//! the bounds.

pub mod auth;
pub mod follow;
pub mod handler;
pub mod host_key;
pub mod input;
pub mod limits;
pub mod output;
pub mod session;
pub mod stream;
pub mod term;

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use anyhow::Context;
use russh::{MethodKind, MethodSet};
use tokio::net::TcpListener;
use tokio::sync::{watch, Notify};

use crate::snapshot::State;
use auth::LecturerKeys;
use follow::Shown;
use limits::Limits;

/// How long a connection may take from TCP connect to a running explorer.
/// For tests, `ROUGHTUI_LOGIN_DEADLINE_MS` shortens it.
pub const LOGIN_DEADLINE: Duration = Duration::from_secs(60);

fn login_deadline() -> Duration {
    std::env::var("ROUGHTUI_LOGIN_DEADLINE_MS")
        .ok()
        .and_then(|v| v.parse().ok())
        .map_or(LOGIN_DEADLINE, Duration::from_millis)
        .min(LOGIN_DEADLINE)
}

/// Authentication attempts per connection.
pub const MAX_AUTH_ATTEMPTS: usize = 6;

/// What `roughtui serve` was asked for.
#[derive(Clone, Debug)]
pub struct Options {
    pub listen: SocketAddr,
    pub host_key: Option<PathBuf>,
    pub lecturer_keys: Option<PathBuf>,
    pub state: State,
    pub max_sessions: usize,
    pub max_per_address: usize,
    pub idle_timeout: Duration,
    /// `--marker`: every session's glyphs, instead of each client's own.
    pub marker: Option<crate::tui::glyphs::Glyphs>,
}

/// What every connection shares.
pub struct Shared {
    /// The scene every explorer starts from.
    pub state: State,
    pub lecturer_keys: LecturerKeys,
    pub idle_timeout: Duration,
    /// `--marker`, if given.
    pub marker: Option<crate::tui::glyphs::Glyphs>,
    /// The lecturer's latest state; `None` while no lecturer is connected.
    pub follow: watch::Sender<Option<Shown>>,
    /// What the lecturer showed last, kept after they leave: a lecturer who
    /// connects (again, or a second time) starts from it.
    last: Mutex<Option<Shown>>,
    lecturers: AtomicUsize,
}

impl Shared {
    fn lecturer_joined(&self, app: &mut crate::tui::app::App) {
        self.lecturers.fetch_add(1, Ordering::SeqCst);
        let last = self.last.lock().ok().and_then(|l| l.clone());
        if let Some(shown) = last {
            shown.apply(app);
        }
        self.publish(app);
    }

    fn publish(&self, app: &crate::tui::app::App) {
        let shown = Shown::of(app);
        if let Ok(mut last) = self.last.lock() {
            *last = Some(shown.clone());
        }
        self.follow.send_if_modified(|cur| {
            if cur.as_ref() == Some(&shown) {
                return false;
            }
            *cur = Some(shown);
            true
        });
    }

    fn lecturer_left(&self) {
        if self.lecturers.fetch_sub(1, Ordering::SeqCst) == 1 {
            self.follow.send_replace(None);
        }
    }
}

/// Runs the server until the process is stopped.
pub fn run(opts: Options) -> anyhow::Result<()> {
    let rt = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .context("cannot start the server's runtime")?;
    rt.block_on(serve(opts))
}

async fn serve(opts: Options) -> anyhow::Result<()> {
    let key_path = match &opts.host_key {
        Some(p) => p.clone(),
        None => host_key::default_path()?,
    };
    let (key, generated) = host_key::load_or_create(&key_path)?;
    let lecturer_keys = match &opts.lecturer_keys {
        Some(p) => LecturerKeys::read(p)?,
        None => LecturerKeys::default(),
    };
    let listener = TcpListener::bind(opts.listen)
        .await
        .with_context(|| format!("cannot listen on {}", opts.listen))?;
    let addr = listener.local_addr()?;
    let fingerprint = host_key::fingerprint(&key);
    println!("roughtui serve: listening on {addr}");
    println!(
        "host key {} ({}): {fingerprint}",
        key_path.display(),
        if generated { "new" } else { "reused" }
    );
    if lecturer_keys.any() {
        println!("lecturer: ssh -p {} {}@HOST", addr.port(), auth::LECTURER);
    } else {
        println!("no --lecturer-keys: everyone explores alone");
    }
    // On all interfaces the students need the machine's own name.
    let host = if addr.ip().is_unspecified() {
        "HOST".to_string()
    } else {
        addr.ip().to_string()
    };
    println!("students: ssh -p {} {host}", addr.port());
    use std::io::Write;
    std::io::stdout().flush()?;

    let config = Arc::new(russh::server::Config {
        methods: MethodSet::from(&[MethodKind::None, MethodKind::PublicKey][..]),
        auth_rejection_time: Duration::from_millis(300),
        auth_rejection_time_initial: Some(Duration::ZERO),
        keys: vec![key],
        max_auth_attempts: MAX_AUTH_ATTEMPTS,
        inactivity_timeout: None,
        keepalive_interval: Some(Duration::from_secs(15)),
        keepalive_max: 3,
        nodelay: true,
        ..Default::default()
    });
    let shared = Arc::new(Shared {
        state: opts.state,
        lecturer_keys,
        idle_timeout: opts.idle_timeout,
        marker: opts.marker,
        follow: watch::Sender::new(None),
        last: Mutex::new(None),
        lecturers: AtomicUsize::new(0),
    });
    let limits = Limits::new(opts.max_sessions, opts.max_per_address);
    let login = login_deadline();
    loop {
        let (socket, peer) = match listener.accept().await {
            Ok(x) => x,
            // Out of file descriptors and the like: wait, then go on.
            Err(_) => {
                tokio::time::sleep(Duration::from_millis(100)).await;
                continue;
            }
        };
        // Over a limit: closed at once, before any SSH is spoken.
        let Ok(permit) = limits.enter(peer.ip()) else {
            drop(socket);
            continue;
        };
        let _ = socket.set_nodelay(true);
        let config = Arc::clone(&config);
        let shared = Arc::clone(&shared);
        tokio::spawn(async move {
            let _permit = permit;
            connection(config, shared, socket, login).await;
        });
    }
}

async fn connection(
    config: Arc<russh::server::Config>,
    shared: Arc<Shared>,
    socket: tokio::net::TcpStream,
    login: Duration,
) {
    let started = Arc::new(Notify::new());
    let (socket, kill) = stream::Killable::new(socket);
    let handler = handler::Handler::new(shared, Arc::clone(&started), kill.clone());
    let deadline = tokio::time::Instant::now() + login;
    let setup =
        tokio::time::timeout_at(deadline, russh::server::run_stream(config, socket, handler));
    let Ok(Ok(running)) = setup.await else {
        return;
    };
    let handle = running.handle();
    tokio::pin!(running);
    tokio::select! {
        _ = &mut running => return,
        () = started.notified() => {}
        () = tokio::time::sleep_until(deadline) => {
            let _ = tokio::time::timeout(
                Duration::from_secs(2),
                handle.disconnect(
                    russh::Disconnect::ByApplication,
                    "login took too long".into(),
                    String::new(),
                ),
            )
            .await;
            kill.kill();
        }
    }
    let _ = running.await;
}
