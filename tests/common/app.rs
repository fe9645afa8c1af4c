//! Driving the explorer without a terminal: key presses through the key
//! table, and the drawn screen as text.

use crossterm::event::{KeyCode, KeyModifiers};
use ratatui::backend::TestBackend;
use ratatui::Terminal;
use roughtui::presets;
use roughtui::tui::app::{update, App};
use roughtui::tui::keys::message_for_key;
use roughtui::tui::theme::Theme;

/// The explorer on a preset at 80×24, coloured.
pub fn fig(name: &str) -> App {
    App::new(presets::load(name).unwrap(), Theme::colored(), (80, 24))
}

/// Presses a key: the message the key table gives, if any, goes to update.
pub fn press(app: &mut App, code: KeyCode, mods: KeyModifiers) {
    if let Some(m) = message_for_key(app, &super::key(code, mods)) {
        update(app, m);
    }
}

pub fn ch(app: &mut App, c: char) {
    press(app, KeyCode::Char(c), KeyModifiers::NONE);
}

/// Types each character of `s`.
pub fn type_text(app: &mut App, s: &str) {
    for c in s.chars() {
        ch(app, c);
    }
}

pub fn ctrl(app: &mut App, c: char) {
    press(app, KeyCode::Char(c), KeyModifiers::CONTROL);
}

/// The app drawn at its size, as text.
pub fn screen(app: &App) -> String {
    let (w, h) = app.size;
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
    super::buffer_text(&t)
}
