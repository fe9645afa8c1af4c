//! The lecturer's scene list (`o`): the presets, the snapshots (.ron) in
//! the save folder that load, and the lessons there (a lesson is listed as
//! one). A `.ron` file that is neither is not listed.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::lesson::{self, Lesson};
use crate::presets;

/// The most snapshots listed (the first by name).
pub const MAX_FILES: usize = 200;

#[derive(Clone, Debug, PartialEq)]
pub enum Source {
    Preset(usize),
    File(PathBuf),
    Lesson(Arc<Lesson>),
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
        let lesson = lesson::read(&p).ok()?;
        let title = format!("lesson {name}: {}", lesson.title);
        Some((title, Source::Lesson(Arc::new(lesson))))
    }));
    SceneList {
        entries,
        selected: 0,
    }
}
