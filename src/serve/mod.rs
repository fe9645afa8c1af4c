//! `roughtui serve`: the explorer for a classroom over SSH and the web
//! ([`web`]: a page and a WebSocket carrying the same session). Each
//! connection gets its own explorer at its own terminal size; a lecturer (by key) leads
//! and students follow until they explore on their own. Nobody gets a shell
//! or anything else: see [`handler`] for what is refused, [`limits`] for
//! the bounds.

pub mod auth;
pub mod banner;
pub mod code;
pub mod follow;
pub mod frames;
pub mod gate;
pub mod handler;
pub mod host_key;
pub mod input;
pub mod limits;
pub mod log;
pub mod output;
pub mod panel;
pub mod poll;
pub mod seat;
pub mod session;
pub mod stream;
pub mod term;
pub mod web;
pub mod wire;

use std::io::Write;
use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::Duration;

use anyhow::Context;
use russh::{MethodKind, MethodSet};
use tokio::net::TcpListener;
use tokio::sync::{watch, Notify};

use crate::class::{Class, Shown};
use crate::scene::State;
use auth::LecturerKeys;
use code::{ClassCode, WrongCodes};
use limits::{Full, Limits};
use log::Log;

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
    /// `--listen`: the SSH server's address; `None` with `--web` alone.
    pub listen: Option<SocketAddr>,
    /// `--web`: the web page's address.
    pub web: Option<SocketAddr>,
    pub host_key: Option<PathBuf>,
    pub lecturer_keys: Option<PathBuf>,
    pub state: State,
    pub max_sessions: usize,
    pub max_per_address: usize,
    pub idle_timeout: Duration,
    /// Students log in with this code (keyboard-interactive).
    pub class_code: Option<ClassCode>,
    /// No join, leave or summary lines on the console.
    pub quiet: bool,
    /// `--marker`: every session's glyphs, instead of each client's own.
    pub marker: Option<crate::tui::glyphs::Glyphs>,
    /// `--lesson`: the lesson the lecturer leads.
    pub lesson: Option<crate::class::Lesson>,
    /// `--cell`, `--contact-grid`, `--per-wavelength`, `--hardness`: every
    /// session's contact simulation.
    pub simulate: crate::cli::Simulate,
}

/// What every connection shares.
pub struct Shared {
    /// The contact solver every explorer of the class shares.
    pub contact: Arc<crate::contact::engine::Engine>,
    /// The scene every explorer starts from.
    pub state: State,
    pub lecturer_keys: LecturerKeys,
    pub idle_timeout: Duration,
    pub class_code: Option<ClassCode>,
    pub wrong_codes: WrongCodes,
    /// The roster and the poll.
    pub class: Class,
    pub log: Log,
    /// `--marker`, if given.
    pub marker: Option<crate::tui::glyphs::Glyphs>,
    /// How every session's contact view samples the scene.
    pub sampling: crate::contact::Sampling,
    /// The lecturer's latest state; `None` while no lecturer is connected.
    pub follow: watch::Sender<Option<Arc<Shown>>>,
    /// What the lecturer showed last, kept after they leave: a lecturer who
    /// connects (again, or a second time) starts from it.
    last: Mutex<Option<Shown>>,
    lecturers: AtomicUsize,
    /// The poll CSVs written.
    saved: Mutex<Vec<PathBuf>>,
    /// The lesson the lecturer leads, and its polls' CSV.
    pub lesson: Option<Arc<crate::class::Lesson>>,
    pub lesson_csv: Mutex<poll::LessonCsv>,
    /// Moves on each lecturer's `F`: every student follows again.
    pub all_follow: watch::Sender<u64>,
    /// Set when the server stops: every session says goodbye.
    pub ending: watch::Sender<bool>,
    /// Students' places (`--max-sessions`, `--max-per-address`), taken at
    /// login (SSH) or join (the web); the lecturer's key needs none.
    pub seats: Limits,
    /// The web page's join address with the class code (`--web`), for
    /// the lecturer's `Q`.
    pub join_url: Option<String>,
    /// The frames students at one screen share.
    pub frames: frames::Frames,
    /// The pages phones that show one scene share.
    pub pictures: web::phone::Pictures,
    /// What was refused, for the console's line each second.
    pub refusals: Arc<gate::Refusals>,
}

impl Shared {
    fn lecturer_joined(&self, app: &mut crate::tui::app::App) {
        self.lecturers.fetch_add(1, Ordering::SeqCst);
        if let Some(lesson) = &self.lesson {
            crate::tui::class::start_lesson(app, Arc::clone(lesson));
        }
        let last = self.last.lock().ok().and_then(|l| l.clone());
        if let Some(shown) = last {
            app.follow(&shown);
            // Back where the lesson was.
            if let (Some(l), Some(step)) = (app.class.lesson.as_mut(), &shown.step) {
                l.at = step.at - 1;
            }
        }
        self.publish(app);
    }

    fn publish(&self, app: &crate::tui::app::App) {
        let shown = app.shown();
        if let Ok(mut last) = self.last.lock() {
            *last = Some(shown.clone());
        }
        self.follow.send_if_modified(|cur| {
            if cur.as_deref() == Some(&shown) {
                return false;
            }
            *cur = Some(Arc::new(shown));
            true
        });
    }

    fn lecturer_left(&self) {
        if self.lecturers.fetch_sub(1, Ordering::SeqCst) == 1 {
            // A poll holds: the lecturer may come back to reveal it.
            self.follow.send_replace(None);
        }
    }

    /// A poll's CSV was written (the console's goodbye names it).
    pub fn saved(&self, path: std::path::PathBuf) {
        self.log.line(&format!("saved {}", path.display()));
        if let Ok(mut s) = self.saved.lock() {
            s.push(path);
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

/// The SSH side, when `--listen` asks for it: its listener, its
/// configuration and the banner's host-key line.
struct Ssh {
    listener: TcpListener,
    config: Arc<russh::server::Config>,
    key_line: String,
}

/// The kernel's send buffer each connection gets (Linux doubles it for
/// its own bookkeeping): what waits for a client that stops reading is
/// bounded by it (with the client's own receive buffer) instead of the
/// megabytes the kernel would otherwise grow it to, and such a client
/// stalls a frame, and is let go ([`output::STALL`]), that much sooner.
/// 64 KiB carries a terminal's frames at 12 MB/s over a 10 ms path.
pub const SEND_BUFFER: u32 = 64 * 1024;

/// A listener whose connections get [`SEND_BUFFER`] (they inherit it).
fn bind(addr: SocketAddr) -> std::io::Result<TcpListener> {
    let s = if addr.is_ipv4() {
        tokio::net::TcpSocket::new_v4()?
    } else {
        tokio::net::TcpSocket::new_v6()?
    };
    s.set_reuseaddr(true)?;
    s.set_send_buffer_size(SEND_BUFFER)?;
    s.bind(addr)?;
    s.listen(1024)
}

async fn ssh(opts: &Options, listen: SocketAddr) -> anyhow::Result<Ssh> {
    let key_path = match &opts.host_key {
        Some(p) => p.clone(),
        None => host_key::default_path()?,
    };
    let (key, generated) = host_key::load_or_create(&key_path)?;
    let listener = bind(listen).with_context(|| format!("cannot listen on {listen}"))?;
    let key_line = format!(
        "host key {} ({}): {}",
        key_path.display(),
        if generated { "new" } else { "reused" },
        host_key::fingerprint(&key)
    );
    let mut methods = vec![MethodKind::None, MethodKind::PublicKey];
    if opts.class_code.is_some() {
        methods.push(MethodKind::KeyboardInteractive);
    }
    let config = Arc::new(russh::server::Config {
        methods: MethodSet::from(&methods[..]),
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
    Ok(Ssh {
        listener,
        config,
        key_line,
    })
}

async fn serve(opts: Options) -> anyhow::Result<()> {
    let lecturer_keys = match &opts.lecturer_keys {
        Some(p) => LecturerKeys::read(p)?,
        None => LecturerKeys::default(),
    };
    let ssh = match opts.listen {
        Some(listen) => Some(ssh(&opts, listen).await?),
        None => None,
    };
    let web = match opts.web {
        Some(a) => Some(bind(a).with_context(|| format!("cannot listen on {a} for the web"))?),
        None => None,
    };
    let web_addr = web.as_ref().map(TcpListener::local_addr).transpose()?;
    let join_url = web_addr.map(|a| banner::join_url(a, opts.class_code.as_ref()));
    // The console log's writer exists before the banner, so that a server
    // that has printed its banner has all its threads.
    let log = Log::new(opts.quiet);
    // One contact engine for the class: a scene is solved once for all
    // who show it, each job's end on the console.
    let contact = crate::contact::engine::Engine::new(
        std::thread::available_parallelism().map_or(1, |n| n.get()),
    );
    {
        let log = log.clone();
        contact.on_end(move |line| log.line(line));
    }
    let shared = Arc::new(Shared {
        contact,
        state: opts.state,
        lecturer_keys,
        idle_timeout: opts.idle_timeout,
        class_code: opts.class_code,
        wrong_codes: WrongCodes::default(),
        class: Class::default(),
        log,
        marker: opts.marker,
        sampling: opts
            .simulate
            .sampling(crate::tui::contact::ContactPane::default().sampling),
        follow: watch::Sender::new(None),
        last: Mutex::new(None),
        lecturers: AtomicUsize::new(0),
        saved: Mutex::new(Vec::new()),
        ending: watch::Sender::new(false),
        all_follow: watch::Sender::new(0),
        lesson: opts.lesson.map(Arc::new),
        lesson_csv: Mutex::default(),
        seats: Limits::new(opts.max_sessions, opts.max_per_address),
        join_url: join_url.as_ref().map(|u| u.url.clone()),
        frames: frames::Frames::default(),
        pictures: web::phone::Pictures::default(),
        refusals: Arc::default(),
    });
    if shared.log.on() {
        tokio::spawn(summaries(Arc::clone(&shared)));
    }
    // Connections that have not logged in (SSH) or sent a request (the
    // web) wait at a gate, each transport's own; a student's place is
    // taken at login (SSH) or join (the web), see `seats`. Open
    // connections are counted for the goodbye.
    let ssh_gate = gate::Gate::new(gate::WAITING, Arc::clone(&shared.refusals));
    let web_gate = gate::Gate::new(gate::WAITING, Arc::clone(&shared.refusals));
    let live = Limits::new(usize::MAX, usize::MAX);
    if shared.log.on() {
        tokio::spawn(refusals(
            Arc::clone(&shared),
            [ssh_gate.clone(), web_gate.clone()],
        ));
    }
    let login = login_deadline();
    let mut stop = Stop::new()?;
    // The banner, once everything is set up (signals caught, the contact
    // engine's threads started, no file open for set-up): a server that has
    // printed it holds only what it keeps. A console that is gone (a closed
    // pipe) does not stop the server.
    let mut extra = vec![format!(
        "at most {} students at once, {} from one address (--max-sessions, --max-per-address)",
        shared.seats.max_sessions(),
        shared.seats.max_per_address()
    )];
    if shared.class_code.is_some() {
        extra.push("class code: on (students type it at \"class code:\")".to_string());
    }
    if shared.log.on() {
        extra.push("log: a line per join and leave (times UTC), a summary each minute".into());
    }
    let lecturer = shared.lecturer_keys.any().then_some(auth::LECTURER);
    let mut lines = Vec::new();
    if let Some(ssh) = &ssh {
        lines.push(format!(
            "roughtui serve: listening on {}",
            ssh.listener.local_addr()?
        ));
        lines.push(ssh.key_line.clone());
        lines.extend(banner::lines(ssh.listener.local_addr()?, lecturer, &extra));
    } else {
        lines.push("no SSH (no --listen): the lecturer leads only over SSH".into());
        lines.extend(extra);
    }
    if let (Some(addr), Some(join)) = (web_addr, &join_url) {
        lines.extend(banner::web_lines(addr, join));
    }
    let mut out = std::io::stdout().lock();
    for line in lines {
        let _ = writeln!(out, "{line}");
    }
    if let Some(join) = &join_url {
        use std::io::IsTerminal;
        if out.is_terminal() {
            for line in crate::tui::qr::terminal_lines(&join.url) {
                let _ = writeln!(out, "  {line}");
            }
        }
    }
    let _ = out.flush();
    drop(out);
    if let Some(listener) = web {
        tokio::spawn(web::serve(
            listener,
            Arc::clone(&shared),
            web_gate.clone(),
            live.clone(),
        ));
    }
    let ssh_listener = ssh.as_ref().map(|s| &s.listener);
    loop {
        let accept = async {
            match ssh_listener {
                Some(l) => l.accept().await,
                None => std::future::pending().await,
            }
        };
        let (socket, peer) = tokio::select! {
            accepted = accept => match accepted {
                Ok(x) => x,
                // Out of file descriptors and the like: wait, then go on.
                Err(_) => {
                    tokio::time::sleep(Duration::from_millis(100)).await;
                    continue;
                }
            },
            () = stop.wait() => break,
        };
        let Some(ssh) = &ssh else { continue };
        let _ = socket.set_nodelay(true);
        let config = Arc::clone(&ssh.config);
        let shared = Arc::clone(&shared);
        let place = ssh_gate.enter(peer.ip());
        let Ok(permit) = live.enter(peer.ip()) else {
            continue;
        };
        tokio::spawn(async move {
            let _permit = permit;
            connection(config, shared, socket, peer, login, place).await;
        });
    }
    drop(ssh);
    goodbye(&shared, &live, &[&ssh_gate, &web_gate]).await;
    Ok(())
}

/// How long the server waits for its sessions to say goodbye when it stops.
pub const GOODBYE_TIME: Duration = Duration::from_secs(6);

/// What a student over a limit is told.
pub fn full_text(full: Full, seats: &Limits, ip: std::net::IpAddr) -> String {
    match full {
        Full::Server => format!(
            "the class is full ({} students): try again later",
            seats.max_sessions()
        ),
        Full::Address => format!(
            "too many sessions from {ip} ({}): try again later",
            seats.max_per_address()
        ),
    }
}

/// Ctrl-C (SIGINT) or SIGTERM.
struct Stop {
    int: tokio::signal::unix::Signal,
    term: tokio::signal::unix::Signal,
}

impl Stop {
    fn new() -> anyhow::Result<Stop> {
        use tokio::signal::unix::{signal, SignalKind};
        Ok(Stop {
            int: signal(SignalKind::interrupt()).context("cannot catch SIGINT")?,
            term: signal(SignalKind::terminate()).context("cannot catch SIGTERM")?,
        })
    }

    async fn wait(&mut self) {
        tokio::select! {
            _ = self.int.recv() => {}
            _ = self.term.recv() => {}
        }
    }
}

/// The end of the class: every session says goodbye to its client (out of
/// the alternate screen, cursor shown, colours reset, "the class has
/// ended") and closes; after at most [`GOODBYE_TIME`] the console's
/// summary.
async fn goodbye(shared: &Shared, live: &Limits, gates: &[&gate::Gate]) {
    // An open poll's answers are not lost with the class.
    let open = poll::save_open(shared);
    shared.ending.send_replace(true);
    for g in gates {
        g.close_all();
    }
    let until = tokio::time::Instant::now() + GOODBYE_TIME;
    while live.open() > 0 && tokio::time::Instant::now() < until {
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    let saved = shared.saved.lock().map(|s| s.clone()).unwrap_or_default();
    let mut out = std::io::stdout().lock();
    if let Some(line) = open {
        let _ = writeln!(out, "{line}");
    }
    for line in banner::summary(shared.class.seen(), shared.class.polls(), &saved) {
        let _ = writeln!(out, "{line}");
    }
    let _ = out.flush();
}

/// The console's line on what was refused, each second something was.
async fn refusals(shared: Arc<Shared>, gates: [gate::Gate; 2]) {
    let mut tick = tokio::time::interval(Duration::from_secs(1));
    tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    loop {
        tick.tick().await;
        let waiting = gates.iter().map(gate::Gate::waiting).sum();
        if let Some(line) = shared.refusals.line(waiting) {
            shared.log.line(&line);
        }
    }
}

/// The console's summary, each minute while students are connected.
async fn summaries(shared: Arc<Shared>) {
    let every = log::summary_every();
    let mut tick = tokio::time::interval_at(tokio::time::Instant::now() + every, every);
    tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    loop {
        tick.tick().await;
        if let Some(line) = shared.class.summary() {
            shared.log.line(&line);
            let (drawn, taken) = shared.pictures.counts();
            let mut frames = shared.frames.summary();
            if drawn > 0 {
                frames.push_str(&format!(
                    "; phones: {drawn} pages drawn, taken {taken} times by others"
                ));
            }
            shared.log.line(&frames);
        }
    }
}

async fn connection(
    config: Arc<russh::server::Config>,
    shared: Arc<Shared>,
    socket: tokio::net::TcpStream,
    peer: SocketAddr,
    login: Duration,
    place: gate::Place,
) {
    let started = Arc::new(Notify::new());
    let (socket, kill) = stream::Killable::new(socket);
    // The gate cuts a connection it closes to make room.
    place.knock.cuts(kill.clone());
    let conn = Arc::new(OnceLock::new());
    let handler = handler::Handler::new(
        shared,
        Arc::clone(&started),
        kill.clone(),
        peer,
        Arc::clone(&conn),
    );
    let deadline = tokio::time::Instant::now() + login;
    let setup =
        tokio::time::timeout_at(deadline, russh::server::run_stream(config, socket, handler));
    let Ok(Ok(running)) = setup.await else {
        return;
    };
    let handle = running.handle();
    let _ = conn.set(handle.clone());
    tokio::pin!(running);
    tokio::select! {
        _ = &mut running => return,
        () = started.notified() => drop(place),
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
