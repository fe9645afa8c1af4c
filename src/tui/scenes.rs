//! The lecturer's scene list (`o`, [`crate::class::scenes`]) on screen:
//! one to pick with ↑↓ and Enter; in a served class every follower gets
//! the scene picked; a lesson picked leads the class through it from its
//! first step.

use std::sync::Arc;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Widget};

use super::app::{App, Message};
use crate::class::scenes::{list, Source};
use crate::presets;

/// The list's messages.
pub fn update(app: &mut App, msg: Message) {
    match msg {
        Message::OpenScenes => app.class.scenes = Some(list(&app.save_dir)),
        Message::SceneClose => app.class.scenes = None,
        Message::SceneMove { down } => {
            if let Some(l) = app.class.scenes.as_mut() {
                let n = l.entries.len();
                l.selected = if down {
                    (l.selected + 1) % n
                } else {
                    (l.selected + n - 1) % n
                };
            }
        }
        Message::ScenePick => {
            let Some(l) = app.class.scenes.take() else {
                return;
            };
            let Some((name, src)) = l.entries.get(l.selected).cloned() else {
                return;
            };
            let loaded = match &src {
                Source::Preset(i) => presets::load(presets::PRESETS[*i].0),
                Source::File(p) => crate::snapshot::load_file(p),
                Source::Lesson(lesson) => {
                    super::class::start_lesson(app, Arc::clone(lesson));
                    return;
                }
            };
            match loaded {
                Ok(state) => {
                    app.load_state(state);
                    if let Source::File(_) = src {
                        app.file = Some(name.clone());
                    }
                    // Away from the lesson's step, which says so.
                    let scene = name.strip_prefix("preset ").unwrap_or(&name);
                    app.class.leave_lesson(scene);
                    app.set_status(format!("loaded {name}"), false);
                }
                Err(e) => app.set_status(format!("{e:#}"), true),
            }
        }
        _ => {}
    }
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let Some(l) = &app.class.scenes else {
        return;
    };
    let g = app.theme.glyphs;
    let w = 60.min(area.width);
    let h = (l.entries.len() as u16 + 2).clamp(3, area.height);
    let per_page = usize::from(h - 2).max(1);
    let first = l.selected / per_page * per_page;
    let lines: Vec<Line> = l
        .entries
        .iter()
        .enumerate()
        .skip(first)
        .take(per_page)
        .map(|(i, (name, _))| {
            let text = format!(" {name}");
            let text = g.text(&text).into_owned();
            if i == l.selected {
                Line::styled(text, app.theme.selected)
            } else {
                Line::raw(text)
            }
        })
        .collect();
    let r = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    let title = g
        .text(" load a scene · ↑↓ choose · Enter loads · Esc closes ")
        .into_owned();
    Clear.render(r, buf);
    Paragraph::new(lines)
        .block(
            Block::default()
                .borders(Borders::ALL)
                .border_set(g.border())
                .title(title),
        )
        .render(r, buf);
}
