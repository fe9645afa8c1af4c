//! The full-screen explorer: an Elm loop over [`app::update`]. It blocks on
//! the next terminal event and draws only after an event that changed
//! something, so an idle session writes nothing to the terminal. While the
//! contact solver works for the view on screen it waits at most [`TICK`]
//! for an event, then reads the solver's progress ([`app::Message::Tick`]).

pub mod app;
pub mod big;
pub mod caps;
pub mod caption;
pub mod class;
pub mod contact;
pub mod ghost;
pub mod glyphs;
pub mod help;
pub mod keys;
pub mod layout;
pub mod line_edit;
pub mod measured;
pub mod message;
pub mod plots;
pub mod prompt;
pub mod qr;
pub mod readout;
pub mod scenes;
pub mod screen;
pub mod session;
pub mod status;
pub mod steps;
pub mod term;
pub mod theme;
pub mod views;
pub mod wrap;

use std::io::Write;
use std::time::Instant;

use crossterm::event::{self, Event, KeyCode};

use crate::scene::State;
use caps::Caps;
use session::Session;

/// How often the explorer looks at the contact solver's progress while it
/// works.
pub const TICK: std::time::Duration = std::time::Duration::from_millis(100);

/// Runs the explorer on `state` until `q`. The terminal is restored on every
/// way out.
///
/// Two environment variables exist for tests: `ROUGHTUI_FRAME_LOG=FILE`
/// appends, per handled event, the microseconds from the event's arrival to
/// the flushed frame; `ROUGHTUI_PANIC_KEY=C` makes key C panic, to test the
/// restore on panic.
///
/// The glyphs are `marker` if given, else chosen from the locale and TERM
/// ([`caps`]); a choice other than braille says why in the status line.
pub fn run(
    state: State,
    file: Option<&std::path::Path>,
    marker: Option<glyphs::Glyphs>,
    lesson: Option<crate::class::Lesson>,
    simulate: &crate::cli::Simulate,
) -> anyhow::Result<()> {
    let mut frame_log = match std::env::var_os("ROUGHTUI_FRAME_LOG") {
        Some(p) => Some(
            std::fs::OpenOptions::new()
                .create(true)
                .append(true)
                .open(p)?,
        ),
        None => None,
    };
    let panic_key = std::env::var("ROUGHTUI_PANIC_KEY")
        .ok()
        .and_then(|s| s.chars().next());

    let var = |k: &str| std::env::var(k).ok();
    let (caps, why) = caps_for(marker, var);
    let out = term::setup()?;
    let _guard = term::Guard;
    let (w, h) = crossterm::terminal::size()?;
    let mut session = Session::new(out, state, caps.theme(), (w, h))?;
    prepare(&mut session.app, caps, why, file, lesson, simulate);
    draw(&mut session)?;
    loop {
        let (msg, arrived) = loop {
            if session.app.contact.busy() && !event::poll(TICK)? {
                break (app::Message::Tick, Instant::now());
            }
            let ev = event::read()?;
            let arrived = Instant::now();
            if let (Some(c), Event::Key(k)) = (panic_key, &ev) {
                if k.code == KeyCode::Char(c) {
                    panic!("ROUGHTUI_PANIC_KEY pressed");
                }
            }
            if let Some(m) = session.message_for(&ev) {
                break (m, arrived);
            }
        };
        if msg == app::Message::Redraw {
            // The size the terminal has now, in case a resize went unseen.
            let (w, h) = crossterm::terminal::size()?;
            if (w, h) != session.app.size {
                session.update(app::Message::Resize(w, h))?;
            }
        }
        session.update(msg)?;
        if session.app.quit {
            break;
        }
        draw(&mut session)?;
        if let Some(log) = frame_log.as_mut() {
            writeln!(log, "{}", arrived.elapsed().as_micros())?;
        }
    }
    Ok(())
}

/// The scene and the lesson the explorer's command line names, checked
/// as `main` checks them (the documentation's screens start the same way).
pub fn start_state(cli: &crate::cli::Cli) -> anyhow::Result<(State, Option<crate::class::Lesson>)> {
    let lesson = cli
        .lesson
        .as_deref()
        .map(crate::class::lesson::read)
        .transpose()?;
    let state = match &lesson {
        Some(l) => l.steps[0].state.clone(),
        None => crate::cli::setup::load_source(&cli.source, &cli.setup)?,
    };
    cli.simulate.check(&state)?;
    Ok((state, lesson))
}

/// The terminal's capabilities from the variables `var` gives (the locale,
/// TERM, COLORTERM, NO_COLOR), the glyphs `marker` if given; and why the
/// drawing is not braille, if it is not and nobody asked for it.
pub fn caps_for(
    marker: Option<glyphs::Glyphs>,
    var: impl Fn(&str) -> Option<String>,
) -> (Caps, Option<String>) {
    let mut caps = Caps::local(&var);
    let why = match marker {
        Some(m) => {
            caps.glyphs = m;
            None
        }
        None => caps.reason(&var, &var("TERM").unwrap_or_default()),
    };
    (caps, why)
}

/// What the explorer sets on a new session's app before its first frame:
/// the contact view's simulation from `--cell` and the like, the file's
/// name in the header, a lesson's first step, and why it draws in what it
/// draws in.
pub fn prepare(
    app: &mut app::App,
    caps: Caps,
    why: Option<String>,
    file: Option<&std::path::Path>,
    lesson: Option<crate::class::Lesson>,
    simulate: &crate::cli::Simulate,
) {
    // --cell, --contact-grid, --per-wavelength, --hardness: the contact
    // view's simulation (one longest wavelength unless --cell says).
    app.contact.sampling = simulate.sampling(app.contact.sampling);
    app.file = file
        .and_then(|f| f.file_name())
        .map(|f| f.to_string_lossy().into_owned());
    if let Some(lesson) = lesson {
        // Rehearsing a lesson alone: its first step, n / N to go on.
        class::start_lesson(app, std::sync::Arc::new(lesson));
    }
    if let Some(why) = why {
        let g = caps.glyphs;
        app.set_status(
            format!("drawing in {} ({why}) · M switches", g.describe()),
            false,
        );
    }
}

/// One frame, written whole before a signal may restore the terminal.
fn draw(session: &mut Session<std::io::BufWriter<std::io::Stdout>>) -> std::io::Result<()> {
    let _frame = term::drawing();
    session.draw()
}
