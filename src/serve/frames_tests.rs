//! Followers sharing frames, in a class run in-process: sessions fed as
//! the WebSocket feeds them, their frames read back into screens by a
//! small terminal.

use std::net::{IpAddr, Ipv4Addr};
use std::sync::atomic::AtomicUsize;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use tokio::sync::{mpsc, watch};

use super::*;
use crate::class::Class;
use crate::serve::auth::{LecturerKeys, Role};
use crate::serve::code::WrongCodes;
use crate::serve::limits::Limits;
use crate::serve::log::Log;
use crate::serve::output::Bye;
use crate::serve::session::{self, Start};
use crate::serve::term::ClientTerm;
use crate::serve::wire::{Input, Wire, WireIn};
use crate::serve::Shared;

fn shared() -> Arc<Shared> {
    shared_with(crate::presets::load("fig2").unwrap())
}

fn shared_with(state: crate::scene::State) -> Arc<Shared> {
    Arc::new(Shared {
        contact: crate::contact::engine::Engine::new(1),
        state,
        lecturer_keys: LecturerKeys::default(),
        idle_timeout: Duration::from_secs(600),
        class_code: None,
        wrong_codes: WrongCodes::default(),
        class: Class::default(),
        log: Log::new(true),
        marker: None,
        sampling: crate::tui::contact::ContactPane::default().sampling,
        follow: watch::Sender::new(None),
        last: Mutex::new(None),
        lecturers: AtomicUsize::new(0),
        saved: Mutex::new(Vec::new()),
        ending: watch::Sender::new(false),
        all_follow: watch::Sender::new(0),
        lesson: None,
        lesson_csv: Mutex::default(),
        seats: Limits::new(100, 100),
        join_url: None,
        frames: Frames::default(),
        pictures: Default::default(),
        refusals: Default::default(),
    })
}

/// A screen as a terminal shows the bytes ratatui's crossterm backend
/// writes: cursor moves, clears and text (colours and modes ignored).
#[derive(Clone)]
struct Screen {
    cells: Vec<Vec<String>>,
    at: (usize, usize),
    /// Whether a colour was ever set (SGR 30–49, 90–107).
    coloured: bool,
}

impl Screen {
    fn new((w, h): (u16, u16)) -> Screen {
        Screen {
            cells: vec![vec![" ".to_string(); usize::from(w)]; usize::from(h)],
            at: (0, 0),
            coloured: false,
        }
    }

    fn feed(&mut self, bytes: &[u8]) {
        let text = String::from_utf8_lossy(bytes);
        let mut chars = text.chars().peekable();
        while let Some(c) = chars.next() {
            if c != '\x1b' {
                // A combining mark (the bar of p̄) joins the cell before.
                let combining = ('\u{300}'..='\u{36f}').contains(&c);
                let (x, y) = self.at;
                let x = if combining { x.saturating_sub(1) } else { x };
                if let Some(cell) = self.cells.get_mut(y).and_then(|r| r.get_mut(x)) {
                    if !combining {
                        cell.clear();
                    }
                    cell.push(c);
                }
                if !combining {
                    self.at.0 += 1;
                }
                continue;
            }
            if chars.peek() != Some(&'[') {
                chars.next();
                continue;
            }
            chars.next();
            let mut params = String::new();
            let end = loop {
                match chars.next() {
                    Some(c) if c.is_ascii_digit() || c == ';' || c == '?' => params.push(c),
                    Some(c) => break c,
                    None => return,
                }
            };
            let n: Vec<usize> = params.split(';').map(|p| p.parse().unwrap_or(1)).collect();
            match end {
                'H' => self.at = (n.get(1).copied().unwrap_or(1) - 1, n[0] - 1),
                'm' => {
                    let colour = |p: &str| {
                        p.parse::<u32>()
                            .is_ok_and(|n| matches!(n, 30..=38 | 40..=48 | 90..=97 | 100..=107))
                    };
                    self.coloured |= params.split(';').next().is_some_and(colour);
                }
                'J' if params == "2" => {
                    for row in &mut self.cells {
                        row.fill(" ".to_string());
                    }
                }
                _ => {}
            }
        }
    }

    fn text(&self) -> String {
        let rows: Vec<String> = self.cells.iter().map(|r| r.concat()).collect();
        rows.join("\n")
    }
}

/// A session of the class: its keys in, its screen out.
struct Client {
    keys: mpsc::Sender<WireIn>,
    screen: Arc<Mutex<Screen>>,
}

impl Client {
    fn start(shared: &Arc<Shared>, role: Role, size: (u16, u16), term: (&str, &str)) -> Client {
        let (keys, input) = mpsc::channel(16);
        let (slot, mut frames) = mpsc::channel::<Vec<u8>>(1);
        let mut client = ClientTerm::default();
        client.set_term(term.0);
        client.env("LANG", term.1);
        session::spawn(Start {
            shared: Arc::clone(shared),
            wire: Wire {
                input: Input::Web(input),
                slot,
                bye: Bye::default(),
                via: " over the web",
                render: crate::serve::session::Render::Terminal,
                notes: None,
            },
            role,
            size,
            name: "s".into(),
            addr: IpAddr::V4(Ipv4Addr::LOCALHOST),
            client,
            transport: crate::class::Transport::Web,
            token: None,
        });
        let screen = Arc::new(Mutex::new(Screen::new(size)));
        let s = Arc::clone(&screen);
        tokio::spawn(async move {
            while let Some(f) = frames.recv().await {
                s.lock().unwrap().feed(&f);
            }
        });
        Client { keys, screen }
    }

    async fn key(&self, k: &str) {
        self.keys
            .send(WireIn::Data(k.as_bytes().to_vec()))
            .await
            .unwrap();
    }

    fn text(&self) -> String {
        self.screen.lock().unwrap().text()
    }

    /// Whether a colour was set since the last call.
    fn coloured(&self) -> bool {
        std::mem::take(&mut self.screen.lock().unwrap().coloured)
    }
}

/// Where two frames differ (their first differing rows), if they do.
pub(super) fn differ(own: &Buffer, taken: &Buffer) -> Option<String> {
    if own == taken {
        return None;
    }
    if own.area != taken.area {
        return Some(format!("{:?} taken for {:?}", taken.area, own.area));
    }
    let row = |b: &Buffer, y: u16| {
        (0..b.area.width)
            .map(|x| b[(x, y)].symbol().to_string())
            .collect::<String>()
    };
    let rows: Vec<String> = (0..own.area.height)
        .filter(|&y| {
            let w = usize::from(own.area.width);
            let at = usize::from(y) * w;
            own.content[at..at + w] != taken.content[at..at + w]
        })
        .take(3)
        .map(|y| format!("row {y}:\n own   {}\n taken {}", row(own, y), row(taken, y)))
        .collect();
    Some(rows.join("\n"))
}

/// The bytes a terminal backend writes to change `from` into `to` (as
/// a frame drawn over `from` does, the cursor hidden).
pub(super) fn encode(from: &Buffer, to: &Buffer) -> Vec<u8> {
    use ratatui::backend::{Backend, CrosstermBackend};
    let mut out = Vec::new();
    let mut b = CrosstermBackend::new(&mut out);
    b.draw(from.diff(to).into_iter()).unwrap();
    b.hide_cursor().unwrap();
    out
}

/// Waits until the students have drawn what they had to: no shared frame
/// rendered or taken for 300 ms. The counts then (rendered, taken, alone).
async fn settled(frames: &Frames) -> (u64, u64, u64) {
    let counts = || (frames.rendered(), frames.taken());
    let mut last = counts();
    for _ in 0..50 {
        tokio::time::sleep(Duration::from_millis(300)).await;
        let now = counts();
        if now == last {
            return (now.0, now.1, frames.alone());
        }
        last = now;
    }
    panic!("the class never stopped drawing: {last:?}");
}

/// No session was given a frame other than its own.
fn no_mismatch(frames: &Frames) {
    let m = frames.mismatches.lock().unwrap();
    assert!(m.is_empty(), "frames taken that differ:\n{}", m.join("\n"));
}

/// Waits until every client's screen passes `pred`.
async fn until(clients: &[&Client], what: &str, pred: impl Fn(&str) -> bool) {
    for _ in 0..400 {
        if clients.iter().all(|c| pred(&c.text())) {
            // The frames in flight land.
            tokio::time::sleep(Duration::from_millis(100)).await;
            return;
        }
        tokio::time::sleep(Duration::from_millis(25)).await;
    }
    let screens: Vec<String> = clients.iter().map(|c| c.text()).collect();
    panic!("{what}:\n{}", screens.join("\n----\n"));
}

const UTF8: (&str, &str) = ("xterm-256color", "C.UTF-8");
const ASCII: (&str, &str) = ("vt100", "C");

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn followers_of_one_shape_share_one_render() {
    let shared = shared();
    let frames = &shared.frames;
    let lecturer = Client::start(&shared, Role::Lecturer, (100, 30), UTF8);
    until(&[&lecturer], "the lecturer", |s| s.contains("Readout")).await;
    // Eight students at 100×30 in braille, one at 80×24, one in ASCII.
    const N: usize = 8;
    let same: Vec<Client> = (0..N)
        .map(|_| Client::start(&shared, Role::Student, (100, 30), UTF8))
        .collect();
    let small = Client::start(&shared, Role::Student, (80, 24), UTF8);
    let ascii = Client::start(&shared, Role::Student, (100, 30), ASCII);
    let students: Vec<&Client> = same.iter().chain([&small, &ascii]).collect();
    until(&students, "following", |s| {
        s.contains("following the lecturer")
    })
    .await;

    // The lecturer's Tab: one render for the lecturer, one for each of
    // the three shapes; the other seven of the eight take theirs.
    let counts = || (frames.rendered(), frames.taken(), frames.alone());
    let (r0, t0, a0) = counts();
    let b0 = frames.as_bytes();
    lecturer.key("\t").await;
    until(&students, "the index view", |s| {
        s.contains("plasticity indices vs")
    })
    .await;
    assert_eq!(frames.rendered() - r0, 3, "renders for the students");
    assert_eq!(frames.taken() - t0, N as u64 - 1, "frames taken");
    assert_eq!(frames.alone() - a0, 1, "the lecturer's");
    // The eight showed one frame before: one of them works out the
    // change, the others send its bytes.
    assert_eq!(frames.as_bytes() - b0, N as u64 - 1, "frames sent as bytes");
    // Each has the right screen: the eight one and the same, the small
    // one its own 24 rows, the ASCII one ASCII only.
    let first = same[0].text();
    for c in &same {
        assert_eq!(c.text(), first);
    }
    assert_eq!(small.text().lines().count(), 24);
    assert!(small.text().contains("plasticity indices vs ζ"));
    assert!(ascii.text().is_ascii(), "{}", ascii.text());
    assert!(ascii.text().contains("plasticity indices vs zeta"));
    assert!(first.contains("plasticity indices vs ζ") && first.contains("⠉"));

    // A poll: one render a shape for the question; one who answered gets
    // their own screen, the others still theirs.
    // Back to the slopes (⇧Tab).
    lecturer.key("\x1b[Z").await;
    until(&students, "slopes", |s| s.contains("slope H0")).await;
    let (r0, t0, _) = counts();
    lecturer.key("v").await;
    until(&students, "the question", |s| s.contains("Predict: ")).await;
    assert_eq!(frames.rendered() - r0, 3, "the question's renders");
    assert_eq!(frames.taken() - t0, N as u64 - 1);
    let (r0, t0, _) = counts();
    same[0].key("\r").await;
    until(&[&same[0]], "the answer", |s| {
        s.contains("you answered ζ = 128")
    })
    .await;
    // (The lecturer's count of answers moves too: a frame of their own.)
    assert_eq!(
        (frames.rendered(), frames.taken()),
        (r0 + 1, t0),
        "the answer's screen"
    );
    for c in &same[1..] {
        assert!(c.text().contains("Predict: where does"), "{}", c.text());
    }
    // The reveal: the seven who did not answer share theirs, the one who
    // did has their own.
    let (r0, t0, _) = counts();
    lecturer.key("v").await;
    until(&students, "the reveal", |s| s.contains("the model: ")).await;
    assert!(first.contains("ζ") && same[2].text().contains("the model: ζ = 321.5"));
    assert!(same[0].text().contains("you: 128"), "{}", same[0].text());
    for c in &same[1..] {
        assert!(c.text().contains("you did not answer"), "{}", c.text());
    }
    assert_eq!(frames.rendered() - r0, 4, "the reveal's renders");
    assert_eq!(frames.taken() - t0, N as u64 - 2);
    // A student's own move: their own frames from then on.
    let (r0, t0, a0) = counts();
    same[1].key("l").await;
    until(&[&same[1]], "on their own", |s| {
        s.contains("exploring on your own")
    })
    .await;
    assert_eq!(
        (frames.rendered(), frames.taken()),
        (r0, t0),
        "an own move's frame"
    );
    assert!(frames.alone() > a0);
    no_mismatch(frames);
}

/// Students who show something of their own beside the scene — the help
/// (one page or another), their own scene, another size, ASCII, no
/// colour or fewer colours — are never given another's frame; while a
/// poll is open no one is given the lecturer's.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_follower_with_a_screen_of_their_own_renders_it() {
    let shared = shared();
    let frames = &shared.frames;
    let lecturer = Client::start(&shared, Role::Lecturer, (100, 30), UTF8);
    until(&[&lecturer], "the lecturer", |s| s.contains("Readout")).await;
    let start = |size, term| Client::start(&shared, Role::Student, size, term);
    let a = start((100, 30), UTF8);
    let b = start((100, 30), UTF8);
    let help = start((100, 30), UTF8);
    let help2 = start((100, 30), UTF8);
    let own = start((100, 30), UTF8);
    let small = start((80, 24), UTF8);
    let ascii = start((100, 30), ASCII);
    // A vt220 in UTF-8 draws as the vt100 in C does (ASCII, no colour);
    // an xterm in 16 colours; one who turned colour off (c).
    let vt220 = start((100, 30), ("vt220", "C.UTF-8"));
    let ansi16 = start((100, 30), ("xterm", "C.UTF-8"));
    let mono = start((100, 30), UTF8);
    let all = [
        &a, &b, &help, &help2, &own, &small, &ascii, &vt220, &ansi16, &mono,
    ];
    until(&all, "following", |s| s.contains("following the lecturer")).await;
    help.key("?").await;
    help2.key("? ").await;
    own.key("l").await;
    mono.key("c").await;
    until(&[&mono], "colour off", |s| s.contains("colour off")).await;
    until(&[&help], "the help", |s| s.contains(" help 1/")).await;
    until(&[&help2], "its next page", |s| s.contains(" help 2/")).await;
    until(&[&own], "on their own", |s| {
        s.contains("exploring on your own")
    })
    .await;
    let own_before = own.text();
    let help_before = (help.text(), help2.text());
    assert_ne!(help_before.0, help_before.1, "two pages of the help");
    for c in all {
        c.coloured();
    }

    // The lecturer's Tab: a and b share one render, as do the two ASCII
    // terminals; each of the others renders its own (and the lecturer's
    // and the one exploring alone draw theirs).
    let (r0, t0, a0) = settled(frames).await;
    lecturer.key("\t").await;
    let following = [&a, &b, &small, &ascii, &vt220, &ansi16, &mono];
    until(&following, "the index view", |s| {
        s.contains("plasticity indices vs")
    })
    .await;
    let (r1, t1, a1) = settled(frames).await;
    assert_eq!((r1 - r0, t1 - t0), (7, 2), "renders and frames taken");
    assert_eq!(a1 - a0, 2, "frames of their own");
    assert_eq!(a.text(), b.text());
    assert_eq!(ascii.text(), vt220.text());
    assert_eq!(
        own.text(),
        own_before,
        "the lecturer's move on an own scene"
    );
    assert!(!own.text().contains("plasticity indices vs"));
    // The help stays, on its page, over the lecturer's new scene.
    for (c, page) in [(&help, " help 1/"), (&help2, " help 2/")] {
        let t = c.text();
        assert!(t.contains(page), "{t}");
        assert!(!t.contains("plasticity indices vs"), "{t}");
    }
    assert!(ascii.text().is_ascii());
    assert_eq!(small.text().lines().count(), 24);
    assert!(a.coloured() && ansi16.coloured(), "colour drawn");
    assert!(!mono.coloured(), "colour off, and a frame in colour");
    assert!(!vt220.coloured(), "a vt220's frame has no colour");
    no_mismatch(frames);

    // A poll: everyone at 100×30 in braille and colour, whatever they
    // showed (the help, their own scene), answers on one question frame.
    // Back to the slopes (⇧Tab).
    lecturer.key("\x1b[Z").await;
    until(&[&a], "slopes", |s| s.contains("slope H0")).await;
    let (r0, t0, _) = settled(frames).await;
    lecturer.key("v").await;
    until(&all, "the question", |s| s.contains("Predict: ")).await;
    let (r1, t1, _) = settled(frames).await;
    assert_eq!(
        (r1 - r0, t1 - t0),
        (5, 5),
        "the question's renders and takes"
    );
    for c in [&b, &help, &help2, &own] {
        assert_eq!(c.text(), a.text());
    }
    // The lecturer moves on while it is open: no student shows it.
    lecturer.key("\t").await;
    until(&[&lecturer], "the lecturer's index view", |s| {
        s.contains("plasticity indices vs")
    })
    .await;
    let (r2, _, _) = settled(frames).await;
    assert_eq!(r2, r1, "no student renders the lecturer's move");
    for c in all {
        let t = c.text();
        assert!(
            t.contains("Predict: ") && !t.contains("plasticity indices vs"),
            "{t}"
        );
    }
    no_mismatch(frames);
}

/// Students following the lecturer into the contact view take the
/// lecturer's seed count (`R`) and convergence table (`t`), not only the
/// load and the plot: they see what the lecturer sees.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn followers_take_the_lecturers_seeds_and_convergence_table() {
    // ζ = 4: grids of 32² to 256², quick in a debug build.
    let mut state = crate::presets::load("fig2").unwrap();
    state.params = state.params.with(rough_model::Axis::Zeta, 4.0).unwrap();
    let shared = shared_with(state);
    let lecturer = Client::start(&shared, Role::Lecturer, (120, 36), UTF8);
    until(&[&lecturer], "the lecturer", |s| s.contains("Readout")).await;
    let a = Client::start(&shared, Role::Student, (120, 36), UTF8);
    let small = Client::start(&shared, Role::Student, (80, 24), UTF8);
    until(&[&a, &small], "following", |s| {
        s.contains("following the lecturer")
    })
    .await;
    lecturer.key("\t\t\t\t").await;
    let all = [&lecturer, &a, &small];
    until(&all, "the contact view", |s| {
        s.contains("simulation 32² · seeds 1–4")
    })
    .await;
    lecturer.key("R").await;
    until(&all, "sixteen seeds", |s| {
        s.contains("simulation 32² · seeds 1–16")
    })
    .await;
    lecturer.key("t").await;
    until(&all, "the convergence table", |s| {
        s.contains("convergence at p̄ = 0.01 H0 · seeds 1–16") && s.contains("n/λ")
    })
    .await;
    // Back to the plot on one surface.
    lecturer.key("tR").await;
    until(&all, "one seed", |s| {
        s.contains("simulation 32² · seed 1") && !s.contains("convergence at")
    })
    .await;
}
