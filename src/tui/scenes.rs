//! The lecturer's scene list (`o`): the presets, the snapshots (.ron) in
//! the save folder that load, and the lessons there (a lesson is listed as
//! one, and picking it leads the class through it from its first step);
//! one to pick with ↑↓ and Enter; in a served class every follower gets
//! the scene picked. A `.ron` file that is neither is not listed.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Widget};

use super::app::{App, Message};
use crate::presets;

/// The most snapshots listed (the first by name).
pub const MAX_FILES: usize = 200;

#[derive(Clone, Debug, PartialEq)]
pub enum Source {
    Preset(usize),
    File(PathBuf),
    Lesson(Arc<crate::lesson::Lesson>),
}

#[derive(Clone, Debug, PartialEq)]
pub struct SceneList {
    pub entries: Vec<(String, Source)>,
    pub selected: usize,
}

/// The presets, then the `.ron` files in `dir` by name that load: as
/// snapshots, or as lessons.
pub fn list(dir: &Path) -> SceneList {
    let mut entries: Vec<(String, Source)> = presets::PRESETS
        .iter()
        .enumerate()
        .map(|(i, (name, _))| (format!("preset {name}"), Source::Preset(i)))
        .collect();
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(Result::ok)
                .map(|e| e.path())
                .filter(|p| p.is_file() && p.extension().is_some_and(|e| e == "ron"))
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    files.truncate(MAX_FILES);
    entries.extend(files.into_iter().filter_map(|p| {
        let name = p
            .file_name()
            .map_or(String::new(), |n| n.to_string_lossy().into_owned());
        if crate::snapshot::read_file(&p).is_ok() {
            return Some((name, Source::File(p)));
        }
        let lesson = crate::lesson::read(&p).ok()?;
        let title = format!("lesson {name}: {}", lesson.title);
        Some((title, Source::Lesson(Arc::new(lesson))))
    }));
    SceneList {
        entries,
        selected: 0,
    }
}

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
                    app.class.lesson = Some(crate::lesson::LessonAt::new(Arc::clone(lesson), 0));
                    crate::lesson::show(app);
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
                    crate::lesson::leave(app, scene);
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
