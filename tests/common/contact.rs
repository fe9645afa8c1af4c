//! The contact view's tests: fig2 at a ζ on an engine of the test's own,
//! Tab to the view, tick until the job for the scene on screen ends.

use std::sync::Arc;
use std::time::{Duration, Instant};

use crossterm::event::{KeyCode, KeyModifiers};
use rough_model::Axis;
use roughtui::contact::engine::Engine;
use roughtui::figure::View;
use roughtui::presets;
use roughtui::tui::app::{update, App, Message};
use roughtui::tui::theme::Theme;

use super::app::press;

/// fig2 at ζ = `zeta` on `engine`.
pub fn app_at(zeta: f64, size: (u16, u16), theme: Theme, engine: &Arc<Engine>) -> App {
    let mut s = presets::load("fig2").unwrap();
    s.params = s.params.with(Axis::Zeta, zeta).unwrap();
    let mut a = App::new(s, theme, size);
    a.contact.engine = Arc::clone(engine);
    a
}

pub fn to_contact(a: &mut App) {
    while a.view != View::Contact {
        press(a, KeyCode::Tab, KeyModifiers::NONE);
    }
}

/// Ticks until the job for the scene on screen has ended.
pub fn settle(a: &mut App) {
    let start = Instant::now();
    while a.contact.busy() {
        assert!(start.elapsed() < Duration::from_secs(300), "solver hung");
        std::thread::sleep(Duration::from_millis(5));
        update(a, Message::Tick);
    }
}
