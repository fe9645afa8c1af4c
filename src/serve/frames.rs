//! Followers share frames. Students who show one scene (the same
//! lecturer's state, or the same poll's: [`Scene`]) with the same
//! [`Look`] (terminal size, glyphs and colours, status line, help page,
//! poll line, …) and the same first-screen line show the same screen: the
//! first of them to draw renders it, the others take that frame. Each
//! still sends its own client only what differs from what that client
//! shows, and where that client showed a shared frame too, the bytes are
//! those the first session to make the same change wrote. A follower does
//! not even bring its explorer up to the scene until it needs to (a key,
//! a miss): taking a frame costs a copy.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, OnceLock};

use ratatui::buffer::Buffer;

use super::follow::Scene;
use super::seat::Seat;
use super::term;
use crate::figure::View;
use crate::tui::app::Look;

/// What a shared frame shows.
#[derive(Clone, Debug, PartialEq)]
struct Key {
    scene: Scene,
    look: Look,
    hint: Option<String>,
}

/// Frames kept: a few shapes of the latest scenes (a 160×48 frame is
/// about 300 kB; older scenes' frames are never asked for again).
const KEEP: usize = 24;

/// A shared frame, once rendered, and the bytes that turn a screen
/// showing another shared frame into it.
#[derive(Default)]
struct Slot {
    frame: OnceLock<Arc<Buffer>>,
    /// From a frame (by identity, which the `Arc` kept here holds) to
    /// this one: the bytes the first session to make that change wrote.
    from: Mutex<Vec<Change>>,
}

/// A frame shown before, and the bytes that change it into another, once
/// the first session to make that change wrote them (`None`: its write
/// failed, each works them out).
type Change = (Arc<Buffer>, Arc<OnceLock<Option<Arc<[u8]>>>>);

/// Changes into one frame kept (each from another frame shown before).
const FROM: usize = 8;

impl Slot {
    /// The change from `shown` into this frame: the one kept, or a new
    /// one (the oldest goes).
    fn change_from(&self, shown: &Arc<Buffer>) -> Arc<OnceLock<Option<Arc<[u8]>>>> {
        let mut from = self.from.lock().unwrap_or_else(|p| p.into_inner());
        if let Some((_, c)) = from.iter().find(|(f, _)| Arc::ptr_eq(f, shown)) {
            return Arc::clone(c);
        }
        if from.len() >= FROM {
            from.remove(0);
        }
        let c = Arc::default();
        from.push((Arc::clone(shown), Arc::clone(&c)));
        c
    }
}

/// The class's shared frames, and how many frames its sessions rendered
/// and took rendered.
pub struct Frames {
    /// Whether followers share frames (`ROUGHTUI_SHARED_FRAMES=off`: each
    /// renders its own, as before they did, to measure what sharing saves).
    share: bool,
    kept: Mutex<Vec<(Key, Arc<Slot>)>>,
    rendered: AtomicU64,
    as_bytes: AtomicU64,
    alone: AtomicU64,
    taken: AtomicU64,
    /// (Tests) the frames taken that differ from the taker's own render.
    #[cfg(test)]
    mismatches: Mutex<Vec<String>>,
}

impl Default for Frames {
    fn default() -> Frames {
        let off = std::env::var("ROUGHTUI_SHARED_FRAMES").is_ok_and(|v| v == "off" || v == "0");
        Frames {
            share: !off,
            kept: Mutex::default(),
            rendered: AtomicU64::default(),
            as_bytes: AtomicU64::default(),
            alone: AtomicU64::default(),
            taken: AtomicU64::default(),
            #[cfg(test)]
            mismatches: Mutex::default(),
        }
    }
}

impl Frames {
    /// The console's line on the frames drawn so far.
    pub fn summary(&self) -> String {
        format!(
            "frames: {} rendered for followers of one shape, taken {} times by others; {} drawn by a session alone; {} sent as the bytes another session wrote{}",
            self.rendered(),
            self.taken(),
            self.alone(),
            self.as_bytes(),
            if self.share { "" } else { " (ROUGHTUI_SHARED_FRAMES=off)" }
        )
    }

    /// Frames rendered for the students who show them (once for all).
    pub fn rendered(&self) -> u64 {
        self.rendered.load(Ordering::Relaxed)
    }

    /// Frames rendered for one session alone (the lecturer's, a student's
    /// own scene, a screen of their own).
    pub fn alone(&self) -> u64 {
        self.alone.load(Ordering::Relaxed)
    }

    /// Shared frames a session sent as the bytes another session wrote
    /// for the same change of screen.
    pub fn as_bytes(&self) -> u64 {
        self.as_bytes.load(Ordering::Relaxed)
    }

    /// Frames a session took from another's render.
    pub fn taken(&self) -> u64 {
        self.taken.load(Ordering::Relaxed)
    }

    /// The slot for `key`: the one kept, or a new one (the oldest goes).
    fn slot(&self, key: &Key) -> Arc<Slot> {
        let mut kept = self.kept.lock().unwrap_or_else(|p| p.into_inner());
        if let Some((_, slot)) = kept.iter().find(|(k, _)| k == key) {
            return Arc::clone(slot);
        }
        if kept.len() >= KEEP {
            kept.remove(0);
        }
        let slot = Arc::<Slot>::default();
        kept.push((key.clone(), Arc::clone(&slot)));
        slot
    }
}

/// Draws a session's screen (with the first screen's `hint` over its
/// status row): taken from the class's frames where another session
/// rendered it, else rendered (and kept when others may show it too).
pub(super) fn draw(s: &mut Seat, hint: Option<&String>) -> std::io::Result<()> {
    let shared = Arc::clone(&s.shared);
    let frames = &shared.frames;
    let overlay = |app: &crate::tui::app::App, buf: &mut Buffer| {
        // Not over a screen too small for the explorer.
        if let Some(h) = hint.filter(|_| !app.too_small()) {
            term::draw_hint(buf, h, app.theme.glyphs);
        }
    };
    let Some(key) = key(s, hint) else {
        s.sync();
        frames.alone.fetch_add(1, Ordering::Relaxed);
        return s.ex.draw_with(overlay);
    };
    let slot = frames.slot(&key);
    let mut rendered = false;
    // Another session rendering this frame now is waited for (a render
    // blocks its thread anyway).
    let frame = Arc::clone(slot.frame.get_or_init(|| {
        s.sync();
        rendered = true;
        Arc::new(s.ex.render(overlay))
    }));
    let counter = if rendered {
        &frames.rendered
    } else {
        &frames.taken
    };
    counter.fetch_add(1, Ordering::Relaxed);
    #[cfg(test)]
    if !rendered {
        // The frame taken is the one this session would have drawn.
        s.sync();
        if let Some(diff) = tests::differ(&s.ex.render(overlay), &frame) {
            let mut m = frames.mismatches.lock().unwrap();
            m.push(diff);
        }
    }
    // A screen that showed a shared frame goes on as every other screen
    // that showed it and goes on to this one: the first of them works out
    // the bytes (the others wait for them, as for a render), the others
    // send them.
    let Some(shown) = s.ex.shown().cloned() else {
        return s.ex.draw_frame(&frame);
    };
    let change = slot.change_from(&shown);
    let mut drawn = None;
    let bytes = change.get_or_init(|| {
        let start = s.out.len();
        let r = s.ex.draw_frame(&frame);
        let ok = r.is_ok();
        drawn = Some(r);
        ok.then(|| s.out.since(start).into())
    });
    if let Some(r) = drawn {
        return r;
    }
    let Some(bytes) = bytes else {
        return s.ex.draw_frame(&frame);
    };
    #[cfg(test)]
    if **bytes != *tests::encode(&shown, &frame) {
        let mut m = frames.mismatches.lock().unwrap();
        m.push("the bytes sent are not the change of screen".into());
    }
    frames.as_bytes.fetch_add(1, Ordering::Relaxed);
    s.ex.draw_frame_as(&frame, bytes)
}

/// What the session's next frame shows, if others may show it too: a
/// student's, on a scene from the lecturer or the poll, with nothing of
/// their own beyond their [`Look`]. Taken before the scene is applied:
/// applying a scene to explorers of one look gives one screen.
fn key(s: &Seat, hint: Option<&String>) -> Option<Key> {
    if s.is_lecturer() || !s.shared.frames.share {
        return None;
    }
    let scene = s.scene.clone()?;
    // The contact view draws a simulation as it runs.
    if scene.view() == View::Contact {
        return None;
    }
    Some(Key {
        scene,
        look: s.ex.app.look()?,
        hint: hint.cloned(),
    })
}

#[cfg(test)]
#[path = "frames_tests.rs"]
mod tests;
