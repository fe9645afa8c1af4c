//! The terminal: raw mode and the alternate screen on the way in, restored on
//! every way out — normal return, error (the [`Guard`] drops), panic (the
//! hook restores before the panic message is printed, so it stays readable)
//! and the signals that end a session (SIGHUP when an SSH connection drops,
//! SIGTERM, SIGINT, SIGQUIT: restored, then exit status 128 + the signal).

use std::io::{self, BufWriter, IsTerminal, Stdout, Write};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, MutexGuard};

use signal_hook::consts::{SIGHUP, SIGINT, SIGQUIT, SIGTERM};
use signal_hook::iterator::Signals;

use crossterm::cursor::{Hide, Show};
use crossterm::execute;
use crossterm::terminal::{
    disable_raw_mode, enable_raw_mode, EnterAlternateScreen, LeaveAlternateScreen,
};

/// Whether the terminal is set up, so restoring twice does nothing.
static ACTIVE: AtomicBool = AtomicBool::new(false);

/// Held while a frame is written, so that a signal restores the terminal
/// between frames, never in the middle of one.
static DRAWING: Mutex<()> = Mutex::new(());

/// The lock to hold while writing a frame.
pub fn drawing() -> MutexGuard<'static, ()> {
    DRAWING.lock().unwrap_or_else(|e| e.into_inner())
}

/// What the explorer says when it has no terminal to draw in.
pub const NO_TERMINAL: &str = "the explorer needs a terminal (standard input and output are not \
                               one); for data use `roughtui export`";

/// Raw mode, alternate screen, hidden cursor; a panic hook and a signal
/// handler that restore. Returns the buffered stdout to draw into. Without
/// a terminal on standard input and output, an error saying so.
pub fn setup() -> anyhow::Result<BufWriter<Stdout>> {
    if !(io::stdin().is_terminal() && io::stdout().is_terminal()) {
        anyhow::bail!(NO_TERMINAL);
    }
    install_panic_hook();
    restore_on_signals()?;
    enable_raw_mode()?;
    ACTIVE.store(true, Ordering::SeqCst);
    let mut out = io::stdout();
    if let Err(e) = execute!(out, EnterAlternateScreen, Hide) {
        restore();
        return Err(e.into());
    }
    // One write per frame instead of one per line.
    Ok(BufWriter::with_capacity(1 << 16, io::stdout()))
}

/// A thread that waits for SIGHUP, SIGTERM, SIGINT or SIGQUIT, restores the
/// terminal once no frame is being written, and exits with 128 + the signal.
fn restore_on_signals() -> io::Result<()> {
    static ONCE: std::sync::Once = std::sync::Once::new();
    let mut result = Ok(());
    ONCE.call_once(|| {
        result = Signals::new([SIGHUP, SIGTERM, SIGINT, SIGQUIT]).and_then(|mut signals| {
            std::thread::Builder::new()
                .name("signals".into())
                .spawn(move || {
                    if let Some(sig) = signals.forever().next() {
                        let _frame = drawing();
                        restore();
                        std::process::exit(128 + sig);
                    }
                })
                .map(drop)
        });
    });
    result
}

/// Leaves the alternate screen, shows the cursor, ends raw mode. Idempotent.
pub fn restore() {
    if ACTIVE.swap(false, Ordering::SeqCst) {
        let mut out = io::stdout();
        let _ = execute!(out, LeaveAlternateScreen, Show);
        let _ = out.flush();
        let _ = disable_raw_mode();
    }
}

fn install_panic_hook() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            restore();
            previous(info);
        }));
    });
}

/// Restores the terminal when dropped (error returns, unwinding).
pub struct Guard;

impl Drop for Guard {
    fn drop(&mut self) {
        restore();
    }
}
