//! The explorer's screen without a terminal: a command line, the
//! terminal's environment, a size and the keys pressed in; the cells the
//! explorer would show out. It starts as `roughtui` starts
//! ([`super::start_state`], [`super::caps_for`], [`super::prepare`]) and
//! draws through the same [`Session`] a terminal gets, so the screens the
//! documentation shows are the program's own (`tests/docs_blocks.rs`
//! makes and checks them).

use crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};
use ratatui::buffer::Buffer;

use super::layout::Regions;
use super::session::Session;
use crate::cli::Cli;

/// A drawn screen and where its regions lie.
pub struct Screen {
    pub buffer: Buffer,
    /// `None` on a terminal smaller than the explorer draws in.
    pub regions: Option<Regions>,
}

impl Screen {
    /// The rows of `area` (the whole screen when `None`) as text, each row's
    /// trailing blanks dropped.
    pub fn text(&self, area: Option<ratatui::layout::Rect>) -> Vec<String> {
        let area = area.unwrap_or(self.buffer.area);
        (area.y..area.bottom())
            .map(|y| {
                let row: String = (area.x..area.right())
                    .map(|x| self.buffer[(x, y)].symbol())
                    .collect();
                row.trim_end().to_string()
            })
            .collect()
    }

    /// The region named `name` (`header`, `caption`, `sliders`, `readout`,
    /// `chart`, `graph`, `status`, `footer`).
    pub fn region(&self, name: &str) -> Option<ratatui::layout::Rect> {
        let r = self.regions.as_ref()?;
        Some(match name {
            "header" => r.header,
            "caption" => r.caption,
            "sliders" => r.sliders,
            "readout" => r.readout,
            "chart" => r.chart,
            "graph" => r.graph,
            "status" => r.status,
            "footer" => r.footer,
            _ => return None,
        })
    }
}

/// The screen of `roughtui ARGS` (`args` without the program's name) in a
/// terminal of `size` whose environment `var` answers (LANG, TERM,
/// NO_COLOR …), after `keys`. The contact view's solver is not waited for:
/// a screen it still works on is refused (its progress is not the same
/// twice).
pub fn draw(
    args: &[String],
    var: impl Fn(&str) -> Option<String>,
    size: (u16, u16),
    keys: &[KeyEvent],
) -> anyhow::Result<Screen> {
    let cli = Cli::try_parse_from(std::iter::once("roughtui".to_string()).chain(args.to_vec()))
        .map_err(|e| anyhow::anyhow!("{}", e.to_string().trim()))?;
    if cli.command.is_some() {
        anyhow::bail!("a screen is the explorer's: no export, bench or serve");
    }
    let (state, lesson) = super::start_state(&cli)?;
    let (caps, why) = super::caps_for(cli.marker.map(Into::into), &var);
    let mut session = Session::new(std::io::sink(), state, caps.theme(), size)?;
    super::prepare(
        &mut session.app,
        caps,
        why,
        cli.source.load.as_deref(),
        lesson,
        &cli.simulate,
    );
    for k in keys {
        if let Some(m) = session.message_for(&Event::Key(*k)) {
            session.update(m)?;
        }
    }
    if session.app.contact.busy() {
        anyhow::bail!("the contact view is still solving: its screen changes as it works");
    }
    Ok(Screen {
        buffer: session.render(|_, _| {}),
        regions: Regions::of_app(&session.app),
    })
}

use clap::Parser as _;

/// Keys written as words: `Tab`, `S-Tab`, `Enter`, `Esc`, `Up`, `Down`,
/// `Left`, `Right`, `S-Left`, `S-Right`, `Home`, `End`, `PgUp`, `PgDn`,
/// `Backspace`, `Del`, `Space`, `C-x` (Ctrl and a letter); any other word
/// is typed a character at a time (`e`, `25nm`).
pub fn parse_keys(text: &str) -> Result<Vec<KeyEvent>, String> {
    let mut out = Vec::new();
    let press = |code, mods| KeyEvent::new(code, mods);
    for word in text.split_whitespace() {
        let none = KeyModifiers::NONE;
        let named = match word {
            "Tab" => Some((KeyCode::Tab, none)),
            "S-Tab" => Some((KeyCode::BackTab, KeyModifiers::SHIFT)),
            "Enter" => Some((KeyCode::Enter, none)),
            "Esc" => Some((KeyCode::Esc, none)),
            "Up" => Some((KeyCode::Up, none)),
            "Down" => Some((KeyCode::Down, none)),
            "Left" => Some((KeyCode::Left, none)),
            "Right" => Some((KeyCode::Right, none)),
            "S-Left" => Some((KeyCode::Left, KeyModifiers::SHIFT)),
            "S-Right" => Some((KeyCode::Right, KeyModifiers::SHIFT)),
            "Home" => Some((KeyCode::Home, none)),
            "End" => Some((KeyCode::End, none)),
            "PgUp" => Some((KeyCode::PageUp, none)),
            "PgDn" => Some((KeyCode::PageDown, none)),
            "Backspace" => Some((KeyCode::Backspace, none)),
            "Del" => Some((KeyCode::Delete, none)),
            "Space" => Some((KeyCode::Char(' '), none)),
            _ => None,
        };
        if let Some((code, mods)) = named {
            out.push(press(code, mods));
            continue;
        }
        if let Some(c) = word.strip_prefix("C-") {
            let mut cs = c.chars();
            match (cs.next(), cs.next()) {
                (Some(c), None) if c.is_ascii_alphabetic() => {
                    out.push(press(KeyCode::Char(c), KeyModifiers::CONTROL));
                    continue;
                }
                _ => return Err(format!("{word}: Ctrl and one letter (C-l)")),
            }
        }
        for c in word.chars() {
            let mods = if c.is_uppercase() {
                KeyModifiers::SHIFT
            } else {
                none
            };
            out.push(press(KeyCode::Char(c), mods));
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn var(k: &str) -> Option<String> {
        match k {
            "LANG" => Some("C.UTF-8".into()),
            "TERM" => Some("xterm-256color".into()),
            _ => None,
        }
    }

    #[test]
    fn a_screen_is_the_explorer_at_that_size_after_those_keys() {
        let s = draw(&[], var, (80, 24), &[]).unwrap();
        let text = s.text(None);
        assert_eq!(text.len(), 24);
        assert!(text[0].starts_with(" roughtui [fig2]"), "{}", text[0]);
        let chart = s.text(s.region("chart"));
        assert!(
            chart[0].starts_with("slope H0·dA/dp̄/A0 vs ζ"),
            "{}",
            chart[0]
        );
        let keys = parse_keys("Tab").unwrap();
        let s = draw(&["--preset".into(), "fig3".into()], var, (80, 24), &keys).unwrap();
        assert!(s.text(s.region("chart"))[0].starts_with("plasticity indices"));
    }

    #[test]
    fn the_environment_chooses_the_drawing_as_it_does_in_a_terminal() {
        let s = draw(&[], |_| None, (80, 24), &[]).unwrap();
        let status = s.text(s.region("status")).join("");
        assert!(
            status.starts_with("drawing in ASCII (no locale set (LANG))"),
            "{status}"
        );
        assert!(draw(&["export".into()], var, (80, 24), &[]).is_err());
    }

    #[test]
    fn keys_as_words() {
        let k = parse_keys("Tab S-Tab e 25nm C-l Enter").unwrap();
        let codes: Vec<KeyCode> = k.iter().map(|k| k.code).collect();
        assert_eq!(
            codes,
            [
                KeyCode::Tab,
                KeyCode::BackTab,
                KeyCode::Char('e'),
                KeyCode::Char('2'),
                KeyCode::Char('5'),
                KeyCode::Char('n'),
                KeyCode::Char('m'),
                KeyCode::Char('l'),
                KeyCode::Enter
            ]
        );
        assert_eq!(k[7].modifiers, KeyModifiers::CONTROL);
        assert!(parse_keys("C-ab").is_err());
    }
}
