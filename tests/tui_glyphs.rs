//! The glyph sets drawn without a terminal: every view, the help, the
//! prompts and the status line in ASCII at 80×24 (insta snapshots, and
//! every character below 0x80 as the views draw it, before the session's
//! safety net; every byte below 0x80 as the session sends it), the
//! half-block and block sets, the map's colours per palette, `M`, `c` and
//! Ctrl-L.

mod common;

use common::key;

use crossterm::event::{KeyCode, KeyModifiers};
use ratatui::backend::TestBackend;
use ratatui::style::Color;
use ratatui::Terminal;
use roughtui::figure::{View, ANSI16_SCALE, ANSI256_SCALE};
use roughtui::presets;
use roughtui::serve::output::FrameBuf;
use roughtui::tui::app::{update, App, Message, Mode};
use roughtui::tui::glyphs::Glyphs;
use roughtui::tui::keys::message_for_key;
use roughtui::tui::layout::Regions;
use roughtui::tui::session::{ascii_only, Session};
use roughtui::tui::theme::{Palette, Theme};

fn app(name: &str, size: (u16, u16), glyphs: Glyphs, color: bool) -> App {
    let theme = Theme::new(glyphs, Palette::Ansi16, color);
    App::new(presets::load(name).unwrap(), theme, size)
}

fn draw(app: &App) -> Terminal<TestBackend> {
    let (w, h) = app.size;
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
    t
}

fn text(app: &App) -> String {
    common::buffer_text(&draw(app))
}

fn show(a: &mut App, view: View) {
    while a.view != view {
        update(a, Message::NextView);
    }
}

fn press(a: &mut App, code: KeyCode, mods: KeyModifiers) {
    let m = message_for_key(a, &key(code, mods)).expect("a bound key");
    update(a, m);
}

fn type_text(a: &mut App, s: &str) {
    for c in s.chars() {
        press(a, KeyCode::Char(c), KeyModifiers::NONE);
    }
}

/// The characters of `s` that `ok` refuses, with their line.
fn refused(s: &str, ok: impl Fn(char) -> bool) -> Vec<(usize, char)> {
    s.lines()
        .enumerate()
        .flat_map(|(i, l)| {
            l.chars()
                .filter(|c| !ok(*c))
                .map(move |c| (i, c))
                .collect::<Vec<_>>()
        })
        .collect()
}

fn assert_ascii(what: &str, s: &str) {
    let bad = refused(s, |c| c.is_ascii());
    assert!(bad.is_empty(), "{what}: not ASCII {bad:?}\n{s}");
}

const VIEWS: [View; 4] = [View::Slopes, View::Indices, View::Map, View::Load];

/// Every screen the explorer has: the four views of each preset, the help's
/// pages, both prompts, an error in the status line, a ghost, another
/// sweep, the too-small message; `check` sees each.
fn every_screen(glyphs: Glyphs, mut check: impl FnMut(&str, &App)) {
    for color in [true, false] {
        for size in [(80, 24), (100, 30), (160, 48)] {
            for name in ["fig1", "fig2", "fig3", "fig4"] {
                let mut a = app(name, size, glyphs, color);
                for v in VIEWS {
                    show(&mut a, v);
                    check(&format!("{name} {v:?} {size:?} colour {color}"), &a);
                }
            }
            let mut a = app("fig2", size, glyphs, color);
            update(&mut a, Message::ToggleHelp);
            for page in 0..3 {
                check(&format!("help page {page} {size:?}"), &a);
                update(&mut a, Message::HelpPage { next: true });
            }
            let mut a = app("fig2", size, glyphs, color);
            update(&mut a, Message::ToggleGhost);
            update(&mut a, Message::ToggleSizeEffect);
            check("ghost", &a);
            update(&mut a, Message::SelectNext);
            update(&mut a, Message::StartValue);
            type_text(&mut a, "abc");
            press(&mut a, KeyCode::Enter, KeyModifiers::NONE);
            check("value prompt with its error", &a);
            press(&mut a, KeyCode::Esc, KeyModifiers::NONE);
            update(&mut a, Message::StartSave);
            check("save prompt", &a);
            press(&mut a, KeyCode::Esc, KeyModifiers::NONE);
            for _ in 0..4 {
                update(&mut a, Message::CycleSweep);
                check("another sweep", &a);
            }
        }
    }
    let a = app("fig2", (60, 20), glyphs, true);
    check("too small", &a);
}

#[test]
fn in_ascii_every_screen_draws_only_ascii() {
    every_screen(Glyphs::Ascii, |what, a| assert_ascii(what, &text(a)));
}

#[test]
fn half_and_block_draw_ascii_blocks_and_box_lines_only() {
    let ok = |c: char| c.is_ascii() || "▀▄█─│┌┐└┘├┤┬┴┼".contains(c);
    for g in [Glyphs::Half, Glyphs::Block] {
        every_screen(g, |what, a| {
            let s = text(a);
            let bad = refused(&s, ok);
            assert!(bad.is_empty(), "{g:?} {what}: {bad:?}\n{s}");
        });
    }
}

#[test]
fn every_byte_a_session_sends_in_ascii_is_ascii() {
    // Through the session, with its escape sequences, as SSH sends it.
    let buf = FrameBuf::default();
    let theme = Theme::new(Glyphs::Ascii, Palette::TrueColor, true);
    let state = presets::load("fig4").unwrap();
    let mut ex = Session::new(buf.clone(), state, theme, (100, 30)).unwrap();
    let mut sent = 0;
    let mut step = |ex: &mut Session<FrameBuf>, msg: Message| {
        ex.update(msg).unwrap();
        ex.draw().unwrap();
        let bytes = buf.take();
        let bad: Vec<u8> = bytes.iter().copied().filter(|b| *b >= 0x80).collect();
        assert!(bad.is_empty(), "{msg:?}: bytes {bad:x?}");
        sent += bytes.len();
    };
    for msg in [
        Message::Resize(100, 30),
        Message::NextView,
        Message::NextView,
        Message::NextView,
        Message::NextView,
        Message::ToggleHelp,
        Message::HelpPage { next: true },
        Message::HelpPage { next: true },
        Message::CloseHelp,
        Message::StartValue,
        Message::PromptCancel,
        Message::StartSave,
        Message::PromptCancel,
        Message::ToggleColor,
        Message::NextView,
        Message::NextView,
        Message::Redraw,
    ] {
        step(&mut ex, msg);
    }
    assert!(sent > 10_000, "{sent} bytes");
}

#[test]
fn the_safety_net_turns_what_is_left_into_ascii() {
    let mut buf = ratatui::buffer::Buffer::empty(ratatui::layout::Rect::new(0, 0, 4, 1));
    buf[(0, 0)].set_symbol("ζ");
    buf[(1, 0)].set_symbol("—");
    buf[(2, 0)].set_symbol("a");
    assert_eq!(ascii_only(&mut buf), 2);
    let s: String = (0..4).map(|x| buf[(x, 0)].symbol()).collect();
    assert_eq!(s, "?-a ");
}

#[test]
fn snapshots_in_ascii_at_80x24() {
    for v in VIEWS {
        let mut a = app("fig2", (80, 24), Glyphs::Ascii, true);
        show(&mut a, v);
        let name = format!("ascii_fig2_{}_80x24", v.name());
        insta::assert_snapshot!(name, text(&a));
    }
    let mut a = app("fig4", (80, 24), Glyphs::Ascii, false);
    show(&mut a, View::Map);
    insta::assert_snapshot!("ascii_fig4_map_no_color_80x24", text(&a));
    let mut a = app("fig4", (80, 24), Glyphs::Ascii, true);
    update(&mut a, Message::ToggleHelp);
    for page in 1..=3 {
        insta::assert_snapshot!(format!("ascii_help_{page}_80x24"), text(&a));
        update(&mut a, Message::HelpPage { next: true });
    }
    // A value prompt with a length's units, then its refusal.
    let mut a = app("fig3", (80, 24), Glyphs::Ascii, true);
    update(&mut a, Message::SelectPrev);
    update(&mut a, Message::StartValue);
    type_text(&mut a, "2 ");
    insta::assert_snapshot!("ascii_value_prompt_80x24", text(&a));
    type_text(&mut a, "parsec");
    press(&mut a, KeyCode::Enter, KeyModifiers::NONE);
    assert!(matches!(a.mode, Mode::Value(..)));
    insta::assert_snapshot!("ascii_value_refused_80x24", text(&a));
}

#[test]
fn snapshots_in_half_and_block_at_80x24() {
    for g in [Glyphs::Half, Glyphs::Block] {
        for v in [View::Slopes, View::Indices] {
            let mut a = app("fig2", (80, 24), g, true);
            show(&mut a, v);
            let name = format!("{}_fig2_{}_80x24", g.name(), v.name());
            insta::assert_snapshot!(name, text(&a));
        }
    }
}

#[test]
fn m_cycles_the_glyphs_and_c_the_colour() {
    let mut a = app("fig2", (80, 24), Glyphs::Braille, true);
    let mut seen = vec![];
    for _ in 0..4 {
        press(&mut a, KeyCode::Char('M'), KeyModifiers::SHIFT);
        seen.push(a.theme.glyphs);
        let s = text(&a);
        let status = s.lines().nth(22).unwrap();
        assert!(
            status.contains(&format!("drawing in {}", a.theme.glyphs.describe())),
            "{status}"
        );
    }
    use Glyphs::*;
    assert_eq!(seen, [Half, Block, Ascii, Braille]);
    // M works in the help too, but is text in a prompt.
    update(&mut a, Message::ToggleHelp);
    press(&mut a, KeyCode::Char('M'), KeyModifiers::SHIFT);
    assert_eq!(a.theme.glyphs, Half);
    update(&mut a, Message::CloseHelp);
    update(&mut a, Message::StartSave);
    let before = a.theme;
    press(&mut a, KeyCode::Char('M'), KeyModifiers::SHIFT);
    assert_eq!(a.theme, before);
    assert!(matches!(&a.mode, Mode::Prompt(l) if l.text().ends_with('M')));
    press(&mut a, KeyCode::Esc, KeyModifiers::NONE);

    // c: colour off and on, the palette kept; nothing the snapshot holds.
    let mut a = app("fig2", (80, 24), Glyphs::Braille, true);
    a.theme = Theme::new(Braille, Palette::Ansi256, true);
    press(&mut a, KeyCode::Char('c'), KeyModifiers::NONE);
    assert!(!a.theme.color);
    assert_eq!(a.theme, Theme::new(Braille, Palette::Ansi256, false));
    let t = draw(&a);
    let coloured = t
        .backend()
        .buffer()
        .content
        .iter()
        .filter(|c| !matches!(c.fg, Color::Reset) || !matches!(c.bg, Color::Reset))
        .count();
    assert_eq!(coloured, 0, "colour codes with colour off");
    press(&mut a, KeyCode::Char('c'), KeyModifiers::NONE);
    assert_eq!(a.theme, Theme::new(Braille, Palette::Ansi256, true));
    assert!(!a.modified);
}

#[test]
fn the_map_is_drawn_in_the_palettes_colours() {
    let cells = |palette: Palette, glyphs: Glyphs| {
        let theme = Theme::new(glyphs, palette, true);
        let mut a = App::new(presets::load("fig2").unwrap(), theme, (100, 30));
        show(&mut a, View::Map);
        let g = Regions::of_size(a.size).unwrap().graph;
        let t = draw(&a);
        let buf = t.backend().buffer().clone();
        let mut v = vec![];
        for y in g.top()..g.bottom() {
            for x in g.left()..g.right() {
                let c = &buf[(x, y)];
                v.push((c.symbol().to_string(), c.fg, c.bg));
            }
        }
        v
    };
    let named16: Vec<Color> = ANSI16_SCALE
        .iter()
        .map(|(_, n)| roughtui::tui::views::ansi16(*n))
        .collect();
    let contour16 = Color::LightMagenta;
    for (sym, fg, bg) in cells(Palette::Ansi16, Glyphs::Braille) {
        for c in [fg, bg] {
            assert!(
                named16.contains(&c) || c == contour16 || (sym == "◆" && c == Color::Red),
                "{sym} {c:?}"
            );
        }
    }
    for (sym, fg, bg) in cells(Palette::Ansi256, Glyphs::Half) {
        for c in [fg, bg] {
            let ok = matches!(c, Color::Indexed(n) if ANSI256_SCALE.contains(&n) || n == 231);
            assert!(ok || (sym == "X" && c == Color::Red), "{sym} {c:?}");
        }
    }
    // In ASCII a cell is a space on its colour.
    let ascii = cells(Palette::Ansi16, Glyphs::Ascii);
    assert!(ascii.iter().filter(|c| c.0 == " ").count() > ascii.len() * 9 / 10);
    assert!(ascii
        .iter()
        .all(|(s, _, bg)| s == "X" || named16.contains(bg) || *bg == contour16));
}

#[test]
fn ctrl_l_redraws_everywhere_and_repaints_the_whole_screen() {
    let ctrl_l = key(KeyCode::Char('l'), KeyModifiers::CONTROL);
    let mut a = app("fig2", (80, 24), Glyphs::Braille, true);
    assert_eq!(message_for_key(&a, &ctrl_l), Some(Message::Redraw));
    update(&mut a, Message::ToggleHelp);
    assert_eq!(message_for_key(&a, &ctrl_l), Some(Message::Redraw));
    update(&mut a, Message::CloseHelp);
    update(&mut a, Message::StartValue);
    assert_eq!(message_for_key(&a, &ctrl_l), Some(Message::Redraw));
    let small = app("fig2", (40, 10), Glyphs::Braille, true);
    assert_eq!(message_for_key(&small, &ctrl_l), Some(Message::Redraw));

    let buf = FrameBuf::default();
    let state = presets::load("fig2").unwrap();
    let mut ex = Session::new(buf.clone(), state, Theme::colored(), (80, 24)).unwrap();
    ex.draw().unwrap();
    let first = buf.take().len();
    ex.draw().unwrap();
    assert!(
        buf.take().len() < 100,
        "an unchanged frame is (almost) empty"
    );
    ex.update(Message::Redraw).unwrap();
    ex.draw().unwrap();
    let again = buf.take();
    assert!(again.starts_with(b"\x1b[2J"), "{:?}", &again[..8]);
    assert!(
        again.len() * 10 > first * 9,
        "{} of {first} bytes",
        again.len()
    );
    assert_eq!(ex.app.state, presets::load("fig2").unwrap());
}
